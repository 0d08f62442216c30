#include "core/offline/OfflineIdentificationReport.h"

#include "core/record/CsvFile.h"
#include "core/record/CsvText.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace hsmu {

namespace {

void writeCsv(const std::string& path, const SpecimenHistory& h, const std::string& law,
              const OfflineIdentificationResult& r, std::vector<std::string>& written) {
    using csvtext::number;
    CsvFile f(path, written);
    f.column("time", "s");
    f.column("deformation", h.deformationUnits);
    f.column("force", h.forceUnits);
    f.column("auxiliary_force", h.forceUnits);
    f.column("fit_error", "-");
    for (const auto& p : r.parameterNames)
        f.column(p, parameterUnit(law, p, h.deformationUnits, h.forceUnits));
    for (const auto& p : r.parameterNames)
        f.column("stddev " + p, parameterUnit(law, p, h.deformationUnits, h.forceUnits));
    f.endHeader();
    for (Eigen::Index k = 0; k < r.parameters.rows(); ++k) {
        const auto i = std::size_t(k);
        std::vector<std::string> row{number(h.time[i]), number(h.deformation[i]),
                                     number(h.force[i]), number(r.auxiliaryForce[k]),
                                     number(r.fitError[k])};
        for (const Eigen::MatrixXd* m : {&r.parameters, &r.stddev})
            for (Eigen::Index j = 0; j < m->cols(); ++j)
                row.push_back(number((*m)(k, j)));
        f.line(row);
    }
    f.close();
}

} // namespace

void writeJsonFile(const std::string& path, const nlohmann::json& j,
                   std::vector<std::string>& written) {
    std::ofstream out(path);
    out << j.dump(2) << '\n';
    out.close();
    if (!out)
        throw std::runtime_error(path + ": cannot be written");
    written.push_back(path);
}

std::string parameterUnit(const std::string& law, const std::string& name,
                          const std::string& deformationUnits, const std::string& forceUnits) {
    if (name == "uRef")
        return deformationUnits;
    if (name == "fRef" || name == "forceOffset")
        return forceUnits;
    if (name == "deformationOffset")
        return deformationUnits;
    const std::string stiffness = forceUnits + "/" + deformationUnits;
    if (law == "bilinear")
        return name == "k0" ? stiffness : (name == "fy" ? forceUnits : "-");
    if (law == "elastic" && name == "k")
        return stiffness;
    return "-";
}

nlohmann::json calibrationJson(const CalibrationResult& c) {
    nlohmann::json cal = {{"nrmse", c.nrmse},
                          {"rmsError", c.rmsError},
                          {"starts", c.startsTried},
                          {"replays", c.residualEvaluations},
                          {"seconds", c.computeSeconds}};
    nlohmann::json all = nlohmann::json::object();
    for (const auto& [name, v] : c.parameters)
        all[name] = v;
    cal["model"] = all;
    nlohmann::json fitted = nlohmann::json::object();
    for (std::size_t i = 0; i < c.names.size(); ++i) {
        const auto k = Eigen::Index(i);
        const double sd = c.standardDeviation[k];
        nlohmann::json p = {{"value", c.estimate[k]}, {"onBound", bool(c.onBound[i])}};
        if (std::isfinite(sd)) {
            p["stddev"] = sd;
            p["ci95"] = {c.estimate[k] - 1.96 * sd, c.estimate[k] + 1.96 * sd};
            nlohmann::json corr = nlohmann::json::object();
            for (std::size_t m = 0; m < c.names.size(); ++m)
                if (std::isfinite(c.correlation(k, Eigen::Index(m))))
                    corr[c.names[m]] = c.correlation(k, Eigen::Index(m));
            p["correlation"] = corr;
        }
        fitted[c.names[i]] = p;
    }
    cal["parameters"] = fitted;
    if (c.offsetTest.ran) {
        const auto finite = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
        cal["offsets"] = {{"used", c.offsetTest.used},
                          {"nrmseWithout", finite(c.offsetTest.nrmseWithout)},
                          {"nrmseWith", finite(c.offsetTest.nrmseWith)},
                          {"branches", c.offsetTest.branches},
                          {"criterion", finite(c.offsetTest.criterion)}};
    }
    return cal;
}

std::vector<std::string> writeIdentificationReport(const std::string& dir,
                                                   const SpecimenHistory& history,
                                                   const IdentificationSettings& settings,
                                                   const OfflineIdentificationResult& result,
                                                   const ParameterValues& online) {
    std::vector<std::string> written;
    const std::filesystem::path d(dir);
    writeCsv((d / "parameters.csv").string(), history, settings.model.law, result, written);

    nlohmann::json j;
    j["source"] = history.source;
    j["specimen"] = settings.specimen;
    j["method"] = result.method;
    j["samples"] = history.size();
    j["dt"] = settings.dt;
    j["units"] = {{"deformation", history.deformationUnits}, {"force", history.forceUnits}};
    nlohmann::json model = {{"law", settings.model.law}};
    for (const auto& [name, v] : settings.model.params)
        model[name] = v;
    j["model"] = model;
    if (settings.online)
        j["updating"] = settings.updatingDocument;
    nlohmann::json units = nlohmann::json::object();
    for (const auto& name : result.parameterNames)
        units[name] =
            parameterUnit(settings.model.law, name, history.deformationUnits, history.forceUnits);
    j["parameterUnits"] = units;
    nlohmann::json params = nlohmann::json::object();
    for (const auto& name : result.parameterNames) {
        nlohmann::json p = {{"initial", result.initial.at(name)},
                            {"final", result.finalEstimate.at(name)},
                            {"stddev", result.finalStddev.at(name)}};
        if (const auto it = online.find(name); it != online.end())
            p["online"] = it->second;
        params[name] = p;
    }
    j["parameters"] = params;
    j["finalRmsError"] = result.finalRmsError;
    j["finalNrmse"] = result.finalNrmse;
    j["initialNrmse"] = result.initialNrmse;
    if (!result.worseThanInitial.empty())
        j["worseThanInitial"] = result.worseThanInitial;
    if (result.fitError.size()) {
        j["auxiliaryNrmse"] = result.auxiliaryNrmse;
        j["finalFitError"] = result.fitError[result.fitError.size() - 1];
    }
    j["refits"] = result.refits;
    j["estimatorWarnings"] = result.estimatorWarnings;
    j["messages"] = result.messages;
    if (result.calibration && result.calibration->ok)
        j["calibration"] = calibrationJson(*result.calibration);
    j["verdict"] = result.verdict;
    writeJsonFile((d / "summary.json").string(), j, written);
    return written;
}

std::vector<std::string> writeInterruptedReport(const std::string& dir,
                                                const SpecimenHistory& history,
                                                const IdentificationSettings& settings,
                                                const OfflinePartial& partial,
                                                const std::string& reason) {
    std::vector<std::string> written;
    nlohmann::json j;
    j["source"] = history.source;
    j["specimen"] = settings.specimen;
    j["method"] = partial.method;
    j["samples"] = history.size();
    j["units"] = {{"deformation", history.deformationUnits}, {"force", history.forceUnits}};
    j["interrupted"] = reason;
    j["phase"] = partial.phase;
    j["samplesDone"] = partial.samplesDone;
    j["refits"] = partial.refits;
    j["estimatorWarnings"] = partial.rejected;
    nlohmann::json units = nlohmann::json::object(), params = nlohmann::json::object();
    for (const auto& [name, v] : partial.estimate) {
        units[name] =
            parameterUnit(settings.model.law, name, history.deformationUnits, history.forceUnits);
        params[name] = {{"current", v}};
    }
    j["parameterUnits"] = units;
    j["parameters"] = params;
    writeJsonFile((std::filesystem::path(dir) / "summary.json").string(), j, written);
    return written;
}

} // namespace hsmu
