#include "core/output/RunSummary.h"

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

nlohmann::json makeRunSummary(const HybridTest& test, const RunStatistics& stats,
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
    nlohmann::json finalU = nlohmann::json::object(), finalF = nlohmann::json::object();
    for (std::size_t i = 0; i < layout.dofNames.size(); ++i)
        finalU[layout.dofNames[i]] =
            Eigen::Index(i) < last.u.size() ? number(last.u[Eigen::Index(i)]) : nullptr;
    for (std::size_t i = 0; i < layout.elements.size(); ++i) {
        const double f = i < last.elements.size() ? last.elements[i].force : std::nan("");
        finalF[layout.elements[i].name] = withUnit(f, layout.elements[i].units.force);
    }
    j["final"] = {{"step", last.step},
                  {"time_s", number(last.time)},
                  {"displacement_m", finalU},
                  {"force", finalF}};

    j["peak_ground_acceleration_m_s2"] = number(stats.peakGroundAcceleration());
    nlohmann::json peakU = nlohmann::json::object(), peakF = nlohmann::json::object(),
                   peakD = nlohmann::json::object();
    for (std::size_t i = 0; i < layout.dofNames.size(); ++i)
        peakU[layout.dofNames[i]] = number(stats.peakDisplacement()[i]);
    for (std::size_t i = 0; i < layout.elements.size(); ++i) {
        const ElementInfo& e = layout.elements[i];
        peakF[e.name] = withUnit(stats.peakForce()[i], e.units.force);
        peakD[e.name] = withUnit(stats.peakDeformation()[i], e.units.deformation);
    }
    j["peak_displacement_m"] = peakU;
    j["peak_force"] = peakF;
    j["peak_deformation"] = peakD;
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
    nlohmann::json tracking = nlohmann::json::object();
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        if (const rths::TrackingReport* t = stats.tracking(i, test.dt()))
            tracking[layout.elements[i].name] = trackingJson(*t, layout.elements[i].units.deformation);
    j["tracking"] = tracking;
    if (const ModelUpdater* updater = test.updater())
        j["updating"] = updatingBlock(*updater, last);
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
    out << makeRunSummary(test, stats, info).dump(2) << '\n';
    out.flush();
    if (!out)
        throw std::runtime_error(path + ": write failed");
}

} // namespace hsmu
