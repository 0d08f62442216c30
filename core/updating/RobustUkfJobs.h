#pragma once
// RobustUkfJobs: the robust UKF's heavy work (docs/method.md, "The robust UKF"), as pure
// functions of a snapshot of the history so that RobustUkfIdentifier can run them on a worker
// thread and apply their results at a step fixed in advance (the same estimates whatever the
// machine's speed):
//
//  - anchorJob: the calibration of the history (multi-start, or a local refit from the
//    anchor and the estimate), the better of it and the estimate by NRMSE over the history,
//    the law's (z, e) replayed to the snapshot's end, the UKF's box, P0 and R from it.
//    Scales (uRef, fRef): the configuration's when given; else derived from the history
//    (HistoryScales.h) at the first anchor and re-derived at every later anchor, taken when
//    either moved by more than rescaleFactor (the anchor and the estimate are then expressed
//    exactly in the new scales: rescaled()).
//  - verifyJob: the replay of one estimate over the snapshot (its NRMSE), for either law (the
//    pinching UKF's jobs are in PinchingUkfJobs.h).
// Values are in the law's normalized units. Thread rules: none (pure functions of their input).

#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/BoucWenPinching.h"
#include "core/identification/BoucWenUkf.h"
#include "core/identification/ParameterSet.h"

#include <array>
#include <atomic>
#include <optional>
#include <string>
#include <vector>

namespace hsmu {

struct CalibrationSpec;
struct CalibrationRequest;
struct CalibrationResult;
struct HistoryScales;

/// The seven parameters the robust UKF identifies, in the filter's state order.
inline constexpr BoucWenUkfIndex kRobustUkfParameters[] = {
    BoucWenUkfIndex::K0, BoucWenUkfIndex::Alpha,   BoucWenUkfIndex::Beta,    BoucWenUkfIndex::Gamma,
    BoucWenUkfIndex::N,  BoucWenUkfIndex::DeltaNu, BoucWenUkfIndex::DeltaEta};
/// The field of p that i names (i one of kRobustUkfParameters).
double& robustUkfField(BoucWenParameters& p, BoucWenUkfIndex i);


struct AnchorJobInput {
    std::vector<double> u, f;              ///< the history so far (physical units)
    std::optional<double> uRef, fRef;      ///< the configuration's scales, if given
    std::optional<BoucWenParameters> anchor;   ///< the current anchor (none: the first)
    std::optional<BoucWenParameters> estimate; ///< the UKF's estimate (none: diverged)
    BoucWenParameters initial;             ///< the configured model (A0, deltaA ...)
    ParameterBoundsMap userBounds;
    bool global = true;         ///< the calibration's multi-start, else a local refit
    double rescaleFactor = 1.5; ///< derived scales taken when they moved by more than this
    int verdictReversals = 4;
    double verdictNrmse = 0.25;
};

struct AnchorJobResult {
    bool ok = false;
    bool cancelled = false;     ///< stopped by the cancel flag (then not ok)
    std::string reason;         ///< why not, when !ok
    bool global = false;        ///< the calibration's multi-start ran (else a local refit)
    BoucWenParameters best;     ///< the anchor (scales included)
    BoucWenState state;         ///< the law's state at the snapshot's last sample
    double nrmse = 0.0;         ///< over the snapshot
    double squaredErrors = 0.0; ///< sum of (F_law - F)^2 over the snapshot [force^2]
    double rmsForce = 0.0;      ///< RMS(F) over the snapshot
    std::array<double, kBoucWenUkfSize> sd{}; ///< P0 (normalized)
    BoucWenUkf::BoundsArray box{};
    bool rescaled = false;      ///< the scales moved at this anchor
    std::optional<double> modelInadequate;
    double cpuSeconds = 0.0;    ///< of the worker thread
};

/// cancel: checked between the calibration's iterations (may be null).
AnchorJobResult anchorJob(const AnchorJobInput& in, const std::atomic<bool>* cancel = nullptr);

struct VerifyJobResult {
    bool ok = false;     ///< false: the law failed along the history
    double nrmse = 0.0;  ///< of the estimate replayed over the snapshot
    double cpuSeconds = 0.0;
};

VerifyJobResult verifyJob(const std::vector<double>& u, const std::vector<double>& f,
                          const BoucWenParameters& p);
/// ... of the pinching law (PinchingUkfIdentifier's guard).
VerifyJobResult verifyJob(const std::vector<double>& u, const std::vector<double>& f,
                          const BoucWenPinchingParameters& p);

/// p replayed over the history (u, f) from the virgin state: the law's final state and the sum
/// of squared force errors [force^2]; false if the law fails or p is not admissible.
bool replayHistory(const std::vector<double>& u, const std::vector<double>& f,
                   const BoucWenParameters& p, BoucWenState& state, double& squaredErrors);
bool replayHistory(const std::vector<double>& u, const std::vector<double>& f,
                   const BoucWenPinchingParameters& p, BoucWenState& state,
                   double& squaredErrors);

/// Whether the values of p for the parameters `spec` fits lie in its box [lower, upper] (one
/// check for the robust and the pinching UKF's anchor jobs). An anchor or estimate carried
/// into new scales (rescaled(): beta, gamma scale with (uRef ratio)^-n ...) can leave the box;
/// the UKF must not start outside the box its sigma points are clamped to (it diverges at
/// once). Fitted names p has no UKF parameter for are not checked.
bool insideBox(const CalibrationSpec& spec, const BoucWenParameters& p);
bool insideBox(const CalibrationSpec& spec, const BoucWenPinchingParameters& p);


// The anchor jobs' shared steps (the robust, pinching and MR damper UKFs' anchorJob()s).

/// A later anchor's scales into `request` (those the configuration gives are kept): the
/// previous anchor's (uRef, fRef), or the data's when either moved by more than `factor`
/// (the first anchor may have seen little of the specimen: a few cycles, or sensor noise).
/// True if the scales moved (and the configuration did not give both).
bool laterAnchorScales(CalibrationRequest& request, const HistoryScales& scales, double uRef,
                       double fRef, double factor);
/// P0's standard deviation of the fitted parameter `name` (typical scale `typical`): the
/// calibration's (cal null, or NaN there: none), clamped to [1 %, 10 %] of typical (1 % when
/// none).
double initialStandardDeviation(const std::string& name, double typical,
                                const CalibrationResult* cal);

/// CPU time of the calling thread [s] (wall time where the platform has no thread clock).
double threadCpuSeconds();

} // namespace hsmu
