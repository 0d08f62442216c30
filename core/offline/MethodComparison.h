#pragma once
// MethodComparison: `hsmu replay --method all` (docs/cli.md): the calibration, the UKF and
// Nelder-Mead run on the same history with the same settings otherwise, one after the other,
// and one table to choose a method from:
//
//   method        what --method names: "calibration", "ukf", "nelder-mead"
//   NRMSE [-]     the method's final model replayed from the virgin state over the whole
//                 history over RMS(F) (OfflineIdentificationResult::finalNrmse: the same
//                 figure as that method's own run)
//   CPU [s]       process CPU over all threads (the robust UKF's jobs run on a worker) while
//                 the method ran, excluding the calibration the single-method runs of the UKF
//                 and Nelder-Mead append (run once, as the calibration row)
//   on bounds     the fitted parameters whose final value sits on a bound: the calibration's
//                 own flags; for the UKF and Nelder-Mead, within 0.2 % of the width of the
//                 calibration's box (CalibrationDefaults.h, with the user's bounds, in the
//                 final model's scales, the scales and energy of the whole history; the UKF
//                 keeps its means 0.1 % of the width inside its box)
//   rejected      rejected identification steps (estimatorWarnings)
//   verdict       "recommended" for the cheapest method (CPU) whose NRMSE is within 5 % of
//                 the best (or within 0.005 of it: 0.5 % of the RMS force, where ratios of
//                 near-zero NRMSEs mean nothing); else "best fit", "within 5 % of the best"
//                 (the same test) or "X.XXX x the best";
//                 "; worse than its initial model" and "; N rejected samples" appended when
//                 so; "failed: why" for a method that cannot run (e.g. the UKF on a bilinear
//                 model) or threw
// The law's own verdict ("the model family cannot represent this specimen") is the
// calibration's and stands beside the table (lawVerdict).
// Thread rules: none. Cancellation (settings.cancel) throws OfflineCancelled as
// identifyOffline does.

#include "core/offline/OfflineIdentification.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hsmu {

struct MethodComparisonRow {
    std::string method;      ///< "calibration", "ukf" or "nelder-mead"
    bool ok = false;         ///< false: the method failed (verdict says why)
    double nrmse = 0.0;      ///< [-]
    double cpuSeconds = 0.0; ///< [s]
    std::vector<std::string> onBounds;
    int rejected = 0;
    std::string verdict;
};

struct MethodComparison {
    std::vector<MethodComparisonRow> rows; ///< calibration, ukf, nelder-mead
    /// Each method's full result and settings (rows[i]'s), for its own report; empty
    /// optionals where it failed.
    std::vector<std::optional<OfflineIdentificationResult>> results;
    std::vector<IdentificationSettings> settings;
    std::string recommended; ///< the recommended row's method ("": none ran)
    std::string lawVerdict;  ///< the calibration's verdict ("" if none)
};

/// The three methods on `history` from `base` (its model, bounds, inspector; its method and
/// online / calibrate flags are replaced per row). progress as identifyOffline's, per method.
/// Throws std::invalid_argument for an unusable history, OfflineCancelled when cancelled.
MethodComparison compareMethods(const SpecimenHistory& history, const IdentificationSettings& base,
                                const OfflineProgressCallback& progress = {});

/// The comparison as summary.json's "comparison" array and the top-level keys written by
/// writeMethodComparison.
nlohmann::json methodComparisonJson(const MethodComparison& c);

/// DIR/comparison.csv (one row per method: method, nrmse [-], cpu [s], on_bounds (names
/// separated by spaces), rejected [-], verdict) and DIR/summary.json ({"source", "samples",
/// "units", "method": "all", "comparison": [...], "recommended", "verdict"}), and each
/// method's own report (OfflineIdentificationReport.h) in DIR/<method>/. Returns the paths
/// written. Throws std::runtime_error naming a file that cannot be written.
std::vector<std::string> writeMethodComparison(const std::string& dir,
                                               const SpecimenHistory& history,
                                               const MethodComparison& c);

} // namespace hsmu
