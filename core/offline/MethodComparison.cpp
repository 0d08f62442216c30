#include "core/offline/MethodComparison.h"

#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryScales.h"
#include "core/offline/OfflineIdentificationReport.h"
#include "core/record/CsvFile.h"
#include "core/record/CsvText.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace hsmu {

namespace {

constexpr const char* kMethods[] = {"calibration", "ukf", "nelder-mead"};
constexpr double kOnBoundFraction = 2e-3;  // of the box's width (the UKF keeps 1e-3 inside)
constexpr double kNearBest = 1.05;         // "within 5 % of the best" ...
constexpr double kNearBestAbsolute = 5e-3; // ... or 0.005 of it (0.5 % of the RMS force)

bool nearBest(double nrmse, double best) {
    return nrmse <= std::max(kNearBest * best, best + kNearBestAbsolute);
}

double processCpuSeconds() {
    return double(std::clock()) / CLOCKS_PER_SEC;
}

IdentificationSettings settingsFor(const IdentificationSettings& base, const std::string& method) {
    if (method == "calibration") {
        IdentificationSettings s = base;
        s.online = false;
        s.calibrate = true;
        return s;
    }
    IdentificationSettings s = withMethod(base, method);
    s.online = true;
    s.calibrate = false; // once, as the calibration row
    return s;
}

/// The fitted parameters of an online method's final model on a bound of the calibration's
/// box in that model's scales (the header).
std::vector<std::string> onBoundsOf(const SpecimenHistory& h, const IdentificationSettings& s,
                                    const OfflineIdentificationResult& r) {
    CalibrationRequest request;
    request.law = s.model.law;
    request.bounds = s.updating.bounds;
    request.time = h.time;
    if (const auto it = r.finalEstimate.find("uRef"); it != r.finalEstimate.end())
        request.uRef = it->second;
    else if (s.updating.modelURef)
        request.uRef = s.updating.modelURef;
    if (const auto it = r.finalEstimate.find("fRef"); it != r.finalEstimate.end())
        request.fRef = it->second;
    else if (s.updating.modelFRef)
        request.fRef = s.updating.modelFRef;
    std::vector<std::string> names;
    CalibrationSpec spec;
    try {
        spec = defaultCalibrationSpec(request, deriveHistoryScales(h.deformation, h.force));
    } catch (const std::exception&) {
        return names; // a law without a default box: nothing to judge against
    }
    for (const auto& b : spec.fitted) {
        const auto it = r.finalEstimate.find(b.name);
        if (it == r.finalEstimate.end())
            continue;
        const double tol = kOnBoundFraction * (b.upper - b.lower);
        if (it->second <= b.lower + tol || it->second >= b.upper - tol)
            names.push_back(b.name);
    }
    return names;
}

std::string ratioText(double x) {
    std::ostringstream m;
    m.setf(std::ios::fixed);
    m.precision(3);
    m << x;
    return m.str();
}

void judge(MethodComparison& c) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& row : c.rows)
        if (row.ok)
            best = std::min(best, row.nrmse);
    const MethodComparisonRow* recommended = nullptr;
    for (const auto& row : c.rows)
        if (row.ok && nearBest(row.nrmse, best) &&
            (!recommended || row.cpuSeconds < recommended->cpuSeconds))
            recommended = &row;
    c.recommended = recommended ? recommended->method : "";
    for (std::size_t i = 0; i < c.rows.size(); ++i) {
        MethodComparisonRow& row = c.rows[i];
        if (!row.ok)
            continue;
        if (&row == recommended)
            row.verdict = "recommended";
        else if (row.nrmse == best)
            row.verdict = "best fit";
        else if (nearBest(row.nrmse, best))
            row.verdict = "within 5 % of the best";
        else
            row.verdict = ratioText(best > 0.0 ? row.nrmse / best : 0.0) + " x the best";
        if (c.results[i] && !c.results[i]->worseThanInitial.empty())
            row.verdict += "; worse than its initial model";
        if (row.rejected > 0)
            row.verdict += "; " + std::to_string(row.rejected) + " rejected samples";
    }
}

} // namespace

MethodComparison compareMethods(const SpecimenHistory& history, const IdentificationSettings& base,
                                const OfflineProgressCallback& progress) {
    if (const std::string why = history.problem(); !why.empty())
        throw std::invalid_argument(history.source + ": " + why);
    MethodComparison c;
    for (const char* method : kMethods) {
        MethodComparisonRow row;
        row.method = method;
        std::optional<OfflineIdentificationResult> result;
        IdentificationSettings s = base;
        const double cpu0 = processCpuSeconds();
        try {
            s = settingsFor(base, method);
            result = identifyOffline(history, s, progress);
            row.ok = std::isfinite(result->finalNrmse);
            if (!row.ok)
                row.verdict = "failed: its final model does not replay the history";
        } catch (const OfflineCancelled&) {
            throw;
        } catch (const std::exception& e) {
            row.verdict = std::string("failed: ") + e.what();
        }
        row.cpuSeconds = processCpuSeconds() - cpu0;
        if (result) {
            row.nrmse = result->finalNrmse;
            row.rejected = result->estimatorWarnings;
            if (row.method == "calibration") {
                if (result->calibration)
                    for (std::size_t j = 0; j < result->calibration->names.size(); ++j)
                        if (result->calibration->onBound[j])
                            row.onBounds.push_back(result->calibration->names[j]);
                c.lawVerdict = result->verdict;
            } else {
                row.onBounds = onBoundsOf(history, s, *result);
            }
        }
        c.rows.push_back(std::move(row));
        c.results.push_back(std::move(result));
        c.settings.push_back(std::move(s));
    }
    judge(c);
    return c;
}

nlohmann::json methodComparisonJson(const MethodComparison& c) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : c.rows) {
        nlohmann::json j = {{"method", row.method},
                            {"ok", row.ok},
                            {"cpuSeconds", row.cpuSeconds},
                            {"parametersOnBounds", row.onBounds},
                            {"rejectedSamples", row.rejected},
                            {"verdict", row.verdict}};
        if (row.ok)
            j["nrmse"] = row.nrmse;
        rows.push_back(j);
    }
    return rows;
}

std::vector<std::string> writeMethodComparison(const std::string& dir,
                                               const SpecimenHistory& history,
                                               const MethodComparison& c) {
    using csvtext::number;
    std::vector<std::string> written;
    const std::filesystem::path d(dir);
    {
        CsvFile f((d / "comparison.csv").string(), written);
        f.column("method", "");
        f.column("nrmse", "-");
        f.column("cpu", "s");
        f.column("on_bounds", "");
        f.column("rejected", "-");
        f.column("verdict", "");
        f.endHeader();
        for (const auto& row : c.rows) {
            std::string bounds;
            for (const auto& name : row.onBounds)
                bounds += (bounds.empty() ? "" : " ") + name;
            const std::vector<std::string> fields{row.method,
                                                  row.ok ? number(row.nrmse) : std::string(),
                                                  number(row.cpuSeconds),
                                                  csvtext::quoted(bounds),
                                                  std::to_string(row.rejected),
                                                  csvtext::quoted(row.verdict)};
            f.line(fields);
        }
        f.close();
    }
    nlohmann::json j;
    j["source"] = history.source;
    j["samples"] = history.size();
    j["units"] = {{"deformation", history.deformationUnits}, {"force", history.forceUnits}};
    j["method"] = "all";
    j["comparison"] = methodComparisonJson(c);
    j["recommended"] = c.recommended;
    j["verdict"] = c.lawVerdict;
    writeJsonFile((d / "summary.json").string(), j, written);
    for (std::size_t i = 0; i < c.rows.size(); ++i) {
        if (!c.results[i])
            continue;
        const std::filesystem::path sub = d / c.rows[i].method;
        std::filesystem::create_directories(sub);
        for (std::string& p :
             writeIdentificationReport(sub.string(), history, c.settings[i], *c.results[i]))
            written.push_back(std::move(p));
    }
    return written;
}

} // namespace hsmu
