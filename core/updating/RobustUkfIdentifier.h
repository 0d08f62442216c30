#pragma once
// RobustUkfIdentifier: the default online identifier of a Bouc-Wen specimen (docs/method.md,
// "The robust UKF"): the joint state-parameter UKF (BoucWenUkf) anchored by least-squares
// calibrations (Calibration.h) of the history measured so far.
//
//  1. Warm-up. Until the specimen has gone through warmUpReversals turning points (dead band
//     2 % of its deformation range so far, counted every max(1, N / 50) samples) the estimate
//     stays at the initial model and nothing is reported: there is nothing yet to identify.
//  2. Anchor. The law is calibrated on the history so far (multi-start Levenberg-Marquardt;
//     with the current estimate as one more start once tracking) and the better of that fit
//     and the current estimate, by NRMSE over the history, becomes the anchor
//     (RobustUkfJobs.h). Scales: the model's uRef / fRef when the configuration gives them,
//     else derived from the data (HistoryScales.h) at the first anchor and re-derived at each
//     later one, taken when either moved by more than rescaleFactor (the anchor and estimate
//     are re-expressed exactly in the new scales); published as the estimate's uRef / fRef
//     so that the auxiliary model and the twins take them with the other parameters. The UKF
//     restarts at the anchor: parameters, the law's (z, e) replayed over the history, P0 from
//     the calibration's standard deviations (1 % to 10 % of each parameter's typical scale),
//     R from the anchor's RMS error (noise levels scaled from the data: the model error, not
//     the sensor's noise, bounds what the filter can explain).
//  3. Track. The UKF runs every step (unscented transform a = 1, kappa = 0, b = 2: positive
//     weights), sigma points and means kept admissible (BoucWenUkf.h). The anchor's model is
//     stepped along beside it, with its running squared error over the whole history.
//  4. Re-anchor when the history has grown by anchorGrowth since the last anchor (with the
//     calibration's multi-start), or the deformation amplitude by amplitudeGrowth (new
//     cycles the anchor has not seen; a local refit from the anchor and the estimate).
//  5. Divergence. The a-priori force error (UKF prediction - measured) / fRef, RMS over the
//     last divergenceWindow steps, above divergenceRatio times the larger of: the anchor
//     model's own error over the same steps (what the model family can do there, so a
//     specimen the law cannot follow is not a divergence), the anchor's RMS error over its
//     history, and divergenceFloor; or a non-finite estimate: the step is rejected (ok false,
//     a message saying why), the UKF restarts at once from the anchor (its stepped model's
//     state), a local refit is started, and for the next divergenceWindow steps its estimates
//     are not reportable (the Reporter passes nothing to the twins until it has recovered).
//     Three UKF steps rejected in a row (a sigma point the law cannot integrate) restart the
//     UKF at the anchor the same way; the anchor's model failing on a new deformation starts
//     a global refit (AnchoredUkf.h).
//  5b. Guard, every max(50, N / 20) steps: the anchor's NRMSE over the whole history comes
//     from its running error (no replay); one that grew past staleRatio times its value at
//     its fit is refitted (step 2). Else the UKF's estimate is replayed over the history
//     (a job, below): within driftRatio of the anchor's NRMSE it becomes the published
//     estimate; a worse one sends the filter back to the anchor, which is published (the
//     one-step prediction can stay good while the parameters drift: the filter follows the
//     force through z). So the estimate the auxiliary model and the Reporter receive has
//     always been verified on the history measured so far.
//  6. Verdict. When an anchor over at least verdictReversals turning points fits no better
//     than verdictNrmse, the status carries the best NRMSE: the Inspector says that the model
//     family cannot represent the specimen.
// The warm-up, anchoring, tracking, divergence recovery, guard and jobs are AnchoredUkf.h's
// (written once for the robust, pinching and MR damper filters); this class gives the
// Bouc-Wen parts: the filter (BoucWenUkf, a = 1, kappa = 0, b = 2), the anchor job
// (RobustUkfJobs.h anchorJob) and the plan of point 4 (history doubled: a global anchor; the
// amplitude grown: a local refit), and the seed.
// Jobs (ScheduledJob.h, AnchoredUkf.h): calibrations (2, 4, 5) and the guard's replay (5b) run
// on a worker thread, one at a time, on a copy of the history at the step k they are started;
// the result is applied at the step where the history reaches N_k + max(50, N_k / 20)
// (jobDelay()), and observe() waits for the worker there if it has not finished. So the
// estimates depend on the samples only, not on the machine's speed: a replay of a record gives
// the same estimates bit for bit, online or offline. The destructor cancels a running job.
// Values are in the law's normalized units. Thread rules: observe() and the rest from one
// thread; the worker only reads its own copy of the inputs.

#include "core/identification/BoucWenUkf.h"
#include "core/updating/AnchoredUkf.h"
#include "core/updating/RobustUkfJobs.h"

#include <array>
#include <optional>
#include <vector>

namespace hsmu {

struct RobustUkfSettings : AnchoredUkfSettings {
    double amplitudeGrowth = 1.25; ///< re-anchor (locally) when the amplitude grew by this
};

class RobustUkfIdentifier final : public AnchoredUkf<BoucWenParameters, BoucWen, AnchorJobResult> {
public:
    /// initial: the model (normalized). uRef / fRef given (std::nullopt: derive from the
    /// data). bounds: user bounds by name (the rest: CalibrationDefaults' box). Throws
    /// std::invalid_argument for a bound that is not a UKF parameter or leaves no admissible
    /// law.
    RobustUkfIdentifier(const BoucWenParameters& initial, std::optional<double> uRef,
                        std::optional<double> fRef, const ParameterBoundsMap& bounds,
                        const RobustUkfSettings& settings = {});

    std::string methodName() const override { return "UKF (robust)"; }
    /// k0, alpha, beta, gamma, n, deltaNu, deltaEta, uRef, fRef (the scales are not
    /// identified by the filter and have no bounds; their standard deviation is 0).
    const ParameterLayout& layout() const override { return m_layout; }
    std::span<const double> estimate() const override { return m_estimate; }
    std::span<const double> standardDeviation() const override { return m_stddev; }
    std::span<const ParameterBounds> bounds() const override { return m_bounds; }
    bool setBounds(std::size_t index, const ParameterBounds& b) override;

    /// Seeding (before the first observe()): the anchor is the calibration of a previous
    /// test's record of the same kind of specimen (deformation and force in this test's
    /// units), the filter starts there in the virgin state at zero deformation and tracks from
    /// the first sample instead of waiting for the warm-up; the record's scales are kept for
    /// the test (as if configured, unless the configuration gives them), and the first anchor
    /// on this test's own history comes, as without a seed, after the warm-up's reversals.
    /// False, with the reason in `message`, if the record cannot be calibrated or the test has
    /// started; nothing changes then.
    bool seed(const std::vector<double>& deformation, const std::vector<double>& force,
              std::string& message);
    bool seeded() const { return m_seeded; }

private:
    const char* filterName() const override { return "UKF"; }
    bool filtering() const override { return m_ukf.has_value(); }
    FilterStep stepFilter(double u, double f) override;
    std::string startFilter(const AnchorJobResult& r, const BoucWenState& state,
                            double u) override;
    void restartFilter(const BoucWenState& state, double u) override;
    AnchorWork anchorWork(bool global, bool diverged) override;
    VerifyWork verifyWork(const BoucWenParameters& candidate) const override;
    BoucWen anchorLaw(const AnchorJobResult& r, double uPrevious) const override;
    double fRef(const BoucWenParameters& p) const override { return p.fRef; }
    double uRef(const BoucWenParameters& p) const override { return p.uRef; }
    bool finite(const BoucWenParameters& p) const override;
    void publish(const BoucWenParameters& p) override;
    AnchorPlan plan(std::size_t n) override;
    AnchorJobInput anchorInput(bool global) const;

    BoucWenParameters m_initial;
    std::optional<double> m_uRef, m_fRef;
    ParameterBoundsMap m_userBounds; ///< as configured, by name (for the calibrations)
    RobustUkfSettings m_settings;
    std::optional<BoucWenUkf> m_ukf;
    bool m_seeded = false;      ///< started from a previous record's calibration
    ParameterLayout m_layout;
    // Published in layout order (kRobustUkfParameters, uRef, fRef); NaN bounds: none yet.
    std::array<double, 9> m_estimate{}, m_stddev{};
    std::array<ParameterBounds, 9> m_bounds{};
};

} // namespace hsmu
