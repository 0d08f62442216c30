#pragma once
// RunSummary: the summary of a run as JSON (DIR/summary.json of `hsmu run`), built from the
// test and the RunStatistics that observed it. Keys (units in the names or beside values):
//   config {name, file}, state, steps, total_steps, test_time_s, wall_time_s, dt_s,
//   integrator, stability {omega_max_rad_s, omega_dt, limit, stable, message},
//   final {step, time_s, displacement_m {dof: m}, force {element: {value, unit}}},
//   peak_ground_acceleration_m_s2,
//   peak_displacement_m {dof: m}, peak_force {element: {value, unit}},
//   peak_deformation {element: {value, unit}}, peak_channels {element: {channel: {value,
//   unit}}} (only with multi-DOF elements: every basic DOF and actuator, ElementChannels.h),
//   alarms [{time_s, step, severity, kind, message}] (the updating alarms included),
//   hold_reason (string or null),
//   link_security {site: "tls", "plaintext-loopback", "insecure-plaintext", "builtin", or null
//     where the run did not say}: how the console reached each site of the experimental
//     elements (the record's /sites `security`, docs/security.md),
//   record_dofs {dofs ("0-99,200" or "all"), recorded, of, every} (only when the record chose
//     or decimated its numerical DOFs: docs/recording.md "Chosen and decimated DOFs"),
//   tracking {specimen: {J1_ms, J2_percent, J3_percent, frequency_evaluation {amplitude,
//     delay_ms, frequency_Hz}, tracking_indicator {value, unit}}}: each specimen's commanded
//     against measured deformation over the committed steps (docs/rths.md, "Tracking
//     metrics"; sampled at dt, so J1 resolves a step's fraction by its parabola only),
//   updating (only when the test runs online model updating):
//     {specimen, method, parameters {name: final value}, standard_deviations {name: value},
//      applied_updates, pending_proposals, final_fit_error}
//     values in the law's own units (normalized by uRef / fRef for a Bouc-Wen law), taken
//     from the last committed step.
// Non-finite numbers (e.g. an unconditional stability limit) are written as null.
// Thread rules: call once the test stopped stepping.

#include <nlohmann/json.hpp>

#include "core/output/DofRecording.h"
#include "core/output/RunLayout.h"

#include <optional>
#include <string>
#include <vector>

namespace hsmu {

class HybridTest;
class RunStatistics;
namespace rths {
struct TrackingReport;
}

struct RunInfo {
    std::string configName; ///< TestConfig::name
    std::string configFile; ///< path or "preset <name>"
    double wallTimeS = 0.0; ///< wall-clock time spent stepping [s]
    SiteSecurity siteSecurity;  ///< how each site was reached (summary.json "link_security")
    /// The numerical DOFs the record kept and how often (summary.json "record_dofs", only
    /// when not full(): docs/recording.md "Chosen and decimated DOFs").
    DofRecording dofRecording;
};

/// {site: security} of the sites (securityOfSites; a site `given` does not name: null).
nlohmann::json linkSecurityJson(const std::vector<std::string>& sites, const SiteSecurity& given);

/// The reason the test is holding (the last critical alarm's message without a leading
/// "test held: "), if it is holding.
std::optional<std::string> holdReason(const HybridTest& test);

/// One specimen's tracking block (summary.json "tracking", compare.json); unit: its deformation's.
nlohmann::json trackingJson(const rths::TrackingReport& report, const std::string& unit);

nlohmann::json makeRunSummary(const HybridTest& test, const RunStatistics& stats,
                              const RunInfo& info);

/// makeRunSummary written with 2-space indentation (the bytes of its dump(2)), its per-DOF and
/// per-element objects streamed rather than built as a DOM (core/output/PrettyJson.h: a
/// 10,000-DOF run's five 10,000-entry objects). Throws std::runtime_error naming the file if it
/// cannot be written.
void writeSummaryJson(const std::string& path, const HybridTest& test, const RunStatistics& stats,
                      const RunInfo& info);

} // namespace hsmu
