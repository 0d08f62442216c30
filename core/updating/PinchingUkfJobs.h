#pragma once
// PinchingUkfJobs: the pinching UKF's anchor (docs/method.md, "The pinching UKF"), as a pure
// function of a snapshot of the history so that PinchingUkfIdentifier runs it on the worker of
// ScheduledJob.h and applies its result at a step fixed in advance (the guard's replay is
// RobustUkfJobs.h's verifyJob).
//
// pinchingAnchorJob: the pinching calibration of the history (CalibrationDefaults.h), with a
// budget (PinchingAnchorBudget) so that an anchor costs seconds, not minutes, on a long record:
//  - local (a later anchor): Levenberg-Marquardt from the previous anchor and the UKF's
//    estimate (a warm start), its polish on at most polishSamples samples of the history
//    (reducedHistory: the turning points and samples spread along the path) for at most
//    localIterations iterations;
//  - global (the first anchor; when asked, e.g. the history grew a lot since the last global
//    one; or when the local fit is poor: its NRMSE above poorFitRatio times the previous
//    anchor's): the plain law's multi-start, then reducedSamples samples and pinchingStarts
//    scattered starts for the pinching law, the same polish budget; the local candidates
//    compete with it.
// The anchor is the best, by NRMSE over the whole snapshot, of the calibration(s), the previous
// anchor and the estimate. Scales (uRef, fRef): the configuration's when given; else derived
// from the history (HistoryScales.h) at the first anchor and re-derived at every later one,
// taken when either moved by more than rescaleFactor (the previous anchor and the estimate are
// then expressed exactly in the new scales: rescaled()). The UKF's box is the calibration's
// default box (the user's bounds replacing it by name), P0 from the calibration's standard
// deviations (1 % to 10 % of each parameter's typical scale).
// Values in the law's normalized units. Thread rules: none (a pure function of its input).

#include "core/hysteresis/BoucWenPinching.h"
#include "core/identification/ParameterSet.h"
#include "core/identification/PinchingUkf.h"

#include <array>
#include <atomic>
#include <optional>
#include <string>
#include <vector>

namespace hsmu {

struct PinchingAnchorBudget {
    std::size_t reducedSamples = 300; ///< the global phase's history (offline: 800)
    int pinchingStarts = 12;          ///< scattered pinching starts (offline: 40)
    std::size_t polishSamples = 2000; ///< the polish's history (offline: all of it)
    int localIterations = 12;         ///< the polish's iterations (offline: 20)
    double poorFitRatio = 1.25;       ///< a local fit worse than this x the previous: global
};

struct PinchingAnchorJobInput {
    std::vector<double> u, f;             ///< the history so far (physical units)
    std::optional<double> uRef, fRef;     ///< the configuration's scales, if given
    std::optional<BoucWenPinchingParameters> anchor;   ///< the current anchor (none: the first)
    double anchorNrmse = 0.0;                          ///< ... its NRMSE at its fit
    std::optional<BoucWenPinchingParameters> estimate; ///< the UKF's estimate (none: diverged)
    BoucWenPinchingParameters initial;    ///< the configured model (A0, deltaA ...)
    ParameterBoundsMap userBounds;
    bool global = true;                   ///< search globally (else locally, global if poor)
    PinchingAnchorBudget budget;
    double rescaleFactor = 1.5;
    int verdictReversals = 4;
    double verdictNrmse = 0.25;
};

struct PinchingAnchorJobResult {
    bool ok = false;
    bool cancelled = false;       ///< stopped by the cancel flag (then not ok)
    std::string reason;           ///< why not, when !ok
    bool global = false;          ///< a global search ran
    BoucWenPinchingParameters best; ///< the anchor (scales included)
    BoucWenState state;           ///< the law's state at the snapshot's last sample
    double nrmse = 0.0;           ///< over the snapshot
    double squaredErrors = 0.0;   ///< sum of (F_law - F)^2 over the snapshot [force^2]
    double rmsForce = 0.0;        ///< RMS(F) over the snapshot
    std::array<double, kPinchingUkfParameters> sd{}; ///< P0 (normalized)
    PinchingUkf::Box box{};
    bool rescaled = false;        ///< the scales moved at this anchor
    std::optional<double> modelInadequate;
    int residualEvaluations = 0;  ///< replays of the calibration(s)
    double cpuSeconds = 0.0;      ///< of the worker thread
};

/// cancel: checked between the calibration's iterations (may be null).
PinchingAnchorJobResult pinchingAnchorJob(const PinchingAnchorJobInput& in,
                                          const std::atomic<bool>* cancel = nullptr);

} // namespace hsmu
