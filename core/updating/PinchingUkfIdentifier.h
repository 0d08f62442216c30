#pragma once
// PinchingUkfIdentifier: the online identifier of a Bouc-Wen-Baber-Noori specimen with
// pinching (`"method": "ukf"` with a boucWenPinching model; docs/method.md, "The pinching
// UKF"): the joint state-parameter UKF of PinchingUkf.h anchored by the pinching calibration
// (CalibrationDefaults.h) of the history measured so far, on the same plan as the robust UKF
// of the plain law (RobustUkfIdentifier.h):
//  1. Warm-up: until the deformation has gone through warmUpReversals turning points (dead
//     band 2 % of its range so far, counted every max(1, N / 50) samples) the estimate stays
//     at the initial model, not reportable.
//  2. Anchor (PinchingUkfJobs.h): the pinching calibration of the history so far with a
//     budget: the first anchor a global search; later ones a local refit warm-started from the
//     anchor and the UKF's estimate, global when the history has grown globalGrowth times
//     since the last global one or the local fit is poor. Scales: the model's uRef / fRef when
//     the configuration gives them, else derived from the data at the first anchor and
//     re-derived at each later one, taken when either moved by more than rescaleFactor (the
//     anchor and estimate re-expressed exactly in the new scales), published as the
//     estimate's uRef / fRef. The better, by NRMSE over the history, of the fit, the previous
//     anchor and the UKF's current estimate is the anchor. The UKF restarts there: (z, e)
//     replayed over the history, P0 from the calibration's standard deviations (1 % to 10 %
//     of each parameter's typical scale), R from the anchor's RMS error, the box the
//     calibration's default box (the user's bounds replacing it by name).
//  3. Track: a UKF step per sample (PinchingUkf: sigma points and means admissible); the
//     anchor's model is stepped along beside it with its running squared error.
//  4. Re-anchor when the history has grown anchorGrowth times since the last anchor, or when
//     the guard finds the anchor stale (its NRMSE over the whole history, from its running
//     error, above staleRatio times its value at its fit).
//  5. Divergence: the a-priori force error / fRef, RMS over divergenceWindow steps, above
//     divergenceRatio times the larger of the anchor model's own error over those steps, the
//     anchor's RMS error and divergenceFloor (or a non-finite estimate): the step is
//     rejected, the UKF restarts from the anchor, a refit is started, and its estimates are
//     not reportable for the next divergenceWindow steps.
//  5b. Law failures: three UKF steps rejected in a row (a sigma point the law cannot
//     integrate) restart the filter at the anchor and start a refit (global if the law cannot
//     replay the history from the anchor or the estimate); the anchor's own model failing on
//     the new deformation starts a global one.
//  6. Guard: every max(50, N / 20) steps the UKF's estimate is replayed over the history (a
//     job); it is published if its NRMSE is within driftRatio of the anchor's, else the filter
//     goes back to the anchor, which is published.
//  7. Verdict: as the robust UKF (an anchor over >= verdictReversals turning points with
//     NRMSE above verdictNrmse).
// The warm-up, anchoring, tracking, divergence recovery, guard and jobs are AnchoredUkf.h's
// (one machinery with the robust and MR damper UKFs); this class gives the pinching parts:
// the filter (PinchingUkf), the anchor job (PinchingUkfJobs.h) and the plan of point 4.
// Jobs (ScheduledJob.h): the anchors (2, 4, 5, 5b) and the guard's replays (6) run on a worker
// thread, one at a time, on a copy of the history at step N_k; the result is applied at the
// step where the history reaches N_k + max(50, N_k / 20), observe() waiting there only if the
// worker is late, and caught up over the samples since N_k on the stepping thread. So the
// estimates depend on the samples only: an online run and an offline replay agree bit for
// bit. The destructor cancels a running job.
// Cost: a UKF step is 31 integrations of the pinching law (docs/benchmarks.md: the stepping
// thread's cost per step, the worker's per anchor). Values in the law's normalized units.
// Thread rules: observe() and the rest from one thread; the worker only reads its own copy of
// the inputs.

#include "core/hysteresis/BoucWenPinching.h"
#include "core/identification/PinchingUkf.h"
#include "core/updating/AnchoredUkf.h"
#include "core/updating/PinchingUkfJobs.h"

#include <optional>
#include <vector>

namespace hsmu {

struct PinchingUkfIdentifierSettings : AnchoredUkfSettings {
    PinchingUkfIdentifierSettings() { fullWindowOnly = true; }
    PinchingAnchorBudget budget;
};

class PinchingUkfIdentifier final
    : public AnchoredUkf<BoucWenPinchingParameters, BoucWenPinching, PinchingAnchorJobResult> {
public:
    /// initial: the model (normalized). uRef / fRef: given, or std::nullopt (from the data).
    /// bounds: user bounds by name (the rest: CalibrationDefaults' box). Throws
    /// std::invalid_argument for a bound that is not one of the 13 identified parameters.
    PinchingUkfIdentifier(const BoucWenPinchingParameters& initial, std::optional<double> uRef,
                          std::optional<double> fRef, const ParameterBoundsMap& bounds,
                          const PinchingUkfIdentifierSettings& settings = {});

    std::string methodName() const override { return "UKF (pinching)"; }
    /// pinchingUkfParameterNames() (its 13), then uRef and fRef (not filtered, no bounds).
    const ParameterLayout& layout() const override { return m_layout; }
    std::span<const double> estimate() const override { return m_estimate; }
    std::span<const double> standardDeviation() const override { return m_stddev; }
    std::span<const ParameterBounds> bounds() const override { return m_bounds; }
    bool setBounds(std::size_t index, const ParameterBounds& b) override;

    /// The UKF itself (after the first anchor), e.g. for benchmarks.
    PinchingUkf* filter() { return m_ukf ? &*m_ukf : nullptr; }

private:
    const char* filterName() const override { return "pinching UKF"; }
    bool filtering() const override { return m_ukf.has_value(); }
    FilterStep stepFilter(double u, double f) override;
    std::string startFilter(const PinchingAnchorJobResult& r, const BoucWenState& state,
                            double u) override;
    void restartFilter(const BoucWenState& state, double u) override;
    AnchorWork anchorWork(bool global, bool diverged) override;
    VerifyWork verifyWork(const BoucWenPinchingParameters& candidate) const override;
    BoucWenPinching anchorLaw(const PinchingAnchorJobResult& r, double uPrevious) const override;
    double fRef(const BoucWenPinchingParameters& p) const override { return p.boucWen.fRef; }
    double uRef(const BoucWenPinchingParameters& p) const override { return p.boucWen.uRef; }
    bool finite(const BoucWenPinchingParameters& p) const override;
    void publish(const BoucWenPinchingParameters& p) override;
    AnchorPlan plan(std::size_t n) override;
    std::string anchorNote(const PinchingAnchorJobResult& r) const override;

    BoucWenPinchingParameters m_initial;
    std::optional<double> m_uRef, m_fRef;
    ParameterBoundsMap m_userBounds; ///< as configured, by name (for the calibrations)
    ParameterLayout m_layout;
    /// Published in layout order; NaN bounds: none.
    std::array<double, kPinchingUkfParameters + 2> m_estimate{}, m_stddev{};
    std::array<ParameterBounds, kPinchingUkfParameters + 2> m_bounds{};
    PinchingUkfIdentifierSettings m_settings;
    std::optional<PinchingUkf> m_ukf;
};

} // namespace hsmu
