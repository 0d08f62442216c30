#include "core/output/RunSummary.h"

#include "core/output/PrettyJson.h"
#include "core/rths/TrackingMetrics.h"

#include "core/integration/Integrator.h"
#include "core/output/RunStatistics.h"
#include "core/experiment/HybridTest.h"
#include "core/updating/ModelUpdater.h"
#include "core/rths/TrackingMetrics.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace hsmu {

namespace {

nlohmann::json number(double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

nlohmann::json withUnit(double value, const std::string& unit) {
    return {{"value", number(value)}, {"unit", unit}};
}

nlohmann::json updatingBlock(const ModelUpdater& updater, const StepRecord& last) {
    const std::vector<std::string> names = updater.parameterNames();
    const UpdatingSample& u = last.updating;
    nlohmann::json values = nlohmann::json::object(), stddev = nlohmann::json::object();
    for (std::size_t i = 0; i < names.size(); ++i) {
        const bool has = last.hasUpdating;
        values[names[i]] = has && i < u.parameters.size() ? number(u.parameters[i]) : nullptr;
        stddev[names[i]] = has && i < u.stddev.size() ? number(u.stddev[i]) : nullptr;
    }
    return {{"specimen", updater.specimenElement()},
            {"method", updater.identifier().methodName()},
            {"parameters", values},
            {"standard_deviations", stddev},
            {"applied_updates", updater.reporter().appliedCount()},
            {"pending_proposals", updater.reporter().pending().size()},
            {"final_fit_error", last.hasUpdating ? number(u.fitError) : nullptr}};
}

} // namespace

std::optional<std::string> holdReason(const HybridTest& test) {
    if (test.state() != HybridTest::State::Holding)
        return std::nullopt;
    const auto& alarms = test.alarms();
    for (auto it = alarms.rbegin(); it != alarms.rend(); ++it) {
        if (it->severity != AlarmSeverity::Critical)
            continue;
        static const std::string prefix = "test held: "; // HybridTest's wording of a hold
        return it->message.rfind(prefix, 0) == 0 ? it->message.substr(prefix.size()) : it->message;
    }
    return std::string("held");
}

namespace {

/// The summary without its per-DOF and per-element objects (namedSummaryBlocks).
nlohmann::json summaryWithoutNamedBlocks(const HybridTest& test, const RunStatistics& stats,
                                         const RunInfo& info) {
    const RunLayout& layout = stats.layout();
    const StabilityReport& st = test.stability();
    nlohmann::json j;
    j["config"] = {{"name", info.configName}, {"file", info.configFile}};
    j["state"] = testStateName(test.state());
    j["steps"] = test.currentStep();
    j["total_steps"] = test.totalSteps();
    j["test_time_s"] = number(test.time());
    j["wall_time_s"] = number(info.wallTimeS);
    j["dt_s"] = number(test.dt());
    j["integrator"] = test.integrator().name();
    j["stability"] = {{"omega_max_rad_s", number(st.omegaMax)},
                      {"omega_dt", number(st.omegaDt)},
                      {"limit", number(st.limit)},
                      {"stable", st.stable},
                      {"message", st.message}};

    const StepRecord& last = stats.last();
    j["final"] = {{"step", last.step}, {"time_s", number(last.time)}};
    j["peak_ground_acceleration_m_s2"] = number(stats.peakGroundAcceleration());
    if (!layout.channels.empty()) { // multi-DOF elements: every basic DOF and actuator
        nlohmann::json peakC = nlohmann::json::object();
        for (std::size_t i = 0; i < layout.channels.size(); ++i) {
            const ElementChannel& c = layout.channels[i];
            peakC[c.element][c.name] = withUnit(stats.peakChannel()[i], c.unit);
        }
        j["peak_channels"] = peakC;
    }

    nlohmann::json alarms = nlohmann::json::array();
    for (const Alarm& a : test.alarms())
        alarms.push_back({{"time_s", number(a.time)},
                          {"step", a.step},
                          {"severity", alarmSeverityName(a.severity)},
                          {"kind", alarmKindName(a.kind)},
                          {"message", a.message}});
    j["alarms"] = alarms;
    const auto reason = holdReason(test);
    j["hold_reason"] = reason ? nlohmann::json(*reason) : nlohmann::json(nullptr);
    j["link_security"] = linkSecurityJson(layout.sites, info.siteSecurity);
    if (const DofRecording& r = info.dofRecording; !r.full())
        j["record_dofs"] = {{"dofs", describeDofList(r.dofs)},
                            {"recorded", r.dofs.empty() ? layout.dofNames.size() : r.dofs.size()},
                            {"of", layout.dofNames.size()},
                            {"every", r.every}};
    nlohmann::json tracking = nlohmann::json::object();
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        if (const rths::TrackingReport* t = stats.tracking(i, test.dt()))
            tracking[layout.elements[i].name] = trackingJson(*t, layout.elements[i].units.deformation);
    j["tracking"] = tracking;
    if (const ModelUpdater* updater = test.updater())
        j["updating"] = updatingBlock(*updater, last);
    return j;
}

/// The summary's {name: value} objects by their JSON pointers: final displacement and force,
/// peak displacement, force and deformation.
std::map<std::string, NamedValues> namedSummaryBlocks(const RunStatistics& stats) {
    const RunLayout& layout = stats.layout();
    const StepRecord& last = stats.last();
    std::vector<std::string> elements, forceUnits, deformationUnits;
    for (const ElementInfo& e : layout.elements) {
        elements.push_back(e.name);
        forceUnits.push_back(e.units.force);
        deformationUnits.push_back(e.units.deformation);
    }
    std::vector<double> finalU(layout.dofNames.size()), finalF(elements.size());
    for (std::size_t i = 0; i < finalU.size(); ++i)
        finalU[i] = Eigen::Index(i) < last.u.size() ? last.u[Eigen::Index(i)] : std::nan("");
    for (std::size_t i = 0; i < finalF.size(); ++i)
        finalF[i] = i < last.elements.size() ? last.elements[i].force : std::nan("");
    std::map<std::string, NamedValues> blocks;
    blocks["/final/displacement_m"] = {layout.dofNames, std::move(finalU), {}};
    blocks["/final/force"] = {elements, std::move(finalF), forceUnits};
    blocks["/peak_displacement_m"] = {layout.dofNames, stats.peakDisplacement(), {}};
    blocks["/peak_force"] = {elements, stats.peakForce(), std::move(forceUnits)};
    blocks["/peak_deformation"] = {std::move(elements), stats.peakDeformation(),
                                   std::move(deformationUnits)};
    return blocks;
}

} // namespace

nlohmann::json makeRunSummary(const HybridTest& test, const RunStatistics& stats,
                              const RunInfo& info) {
    nlohmann::json j = summaryWithoutNamedBlocks(test, stats, info);
    for (const auto& [pointer, block] : namedSummaryBlocks(stats)) {
        nlohmann::json values = nlohmann::json::object();
        for (std::size_t i = 0; i < block.names.size(); ++i)
            values[block.names[i]] = block.units.empty()
                                            ? number(block.values[i])
                                            : withUnit(block.values[i], block.units[i]);
        j[nlohmann::json::json_pointer(pointer)] = std::move(values);
    }
    return j;
}

nlohmann::json linkSecurityJson(const std::vector<std::string>& sites, const SiteSecurity& given) {
    const std::vector<std::string> security = securityOfSites(sites, given);
    nlohmann::json out = nlohmann::json::object();
    for (std::size_t i = 0; i < sites.size(); ++i)
        out[sites[i]] =
            security[i].empty() ? nlohmann::json(nullptr) : nlohmann::json(security[i]);
    return out;
}

nlohmann::json trackingJson(const rths::TrackingReport& r, const std::string& unit) {
    return {{"J1_ms", number(r.j1)},
            {"J2_percent", number(r.j2)},
            {"J3_percent", number(r.j3)},
            {"frequency_evaluation", {{"amplitude", number(r.frequency.amplitude)},
                                      {"delay_ms", number(r.frequency.delay)},
                                      {"frequency_Hz", number(r.frequency.frequency)}}},
            {"tracking_indicator", withUnit(r.indicator, unit + "^2")}};
}

void writeSummaryJson(const std::string& path, const HybridTest& test, const RunStatistics& stats,
                      const RunInfo& info) {
    std::ofstream out(path, std::ios::out | std::ios::trunc);
    if (!out)
        throw std::runtime_error(path + ": cannot be opened for writing");
    // Streamed: the same bytes as makeRunSummary(...).dump(2) (test_output_run_summary).
    writePrettyJson(out, summaryWithoutNamedBlocks(test, stats, info), namedSummaryBlocks(stats));
    out << '\n';
    out.flush();
    if (!out)
        throw std::runtime_error(path + ": write failed");
}

} // namespace hsmu
