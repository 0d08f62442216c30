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
// Jobs (ScheduledJob.h). Calibrations (2, 4, 5) and the guard's replay (5b) run on a worker
// thread (std::async), one at a time, on a copy of the history at the step k they are started;
// the result is applied at the step where the history reaches N_k + max(50, N_k / 20)
// (jobDelay(); the next step when that one is a divergence's), and observe() waits for the
// worker there if it has not finished. So the estimates depend on the samples only, not on the
// machine's speed: a replay of a record gives the same estimates bit for bit, online or
// offline. A job's result is caught up over the samples since N_k on the stepping thread (the
// anchor's model stepped over them). The destructor cancels a running job (the calibration
// stops at its next iteration) and waits only for that.
// Values are in the law's normalized units. Thread rules: observe() and the rest from one
// thread; the worker only reads its own copy of the inputs.

#include "core/identification/BoucWenUkf.h"
#include "core/updating/Identifier.h"
#include "core/updating/RobustUkfJobs.h"
#include "core/updating/ScheduledJob.h"

#include <array>
#include <optional>
#include <vector>

namespace hsmu {

struct RobustUkfSettings {
    int warmUpReversals = 2;       ///< turning points before the first anchor
    double anchorGrowth = 2.0;     ///< re-anchor when the history grew by this factor
    double amplitudeGrowth = 1.25; ///< ... or the deformation amplitude by this factor
    int divergenceWindow = 50;     ///< [steps]
    double divergenceRatio = 4.0;  ///< window RMS error / the anchor's that diverges
    double divergenceFloor = 0.02; ///< errors below this fraction of fRef never diverge
    double parameterNoise = 1e-5;  ///< random walk per step, fraction of the box width
    double driftRatio = 1.05;      ///< UKF estimate's history NRMSE / the anchor's: pull back
    double staleRatio = 1.1;       ///< anchor's history NRMSE / at its fit: refit
    double verdictNrmse = 0.25;    ///< an anchor worse than this: the model family is poor
    int verdictReversals = 4;      ///< ... judged once the history has this many reversals
    double rescaleFactor = 1.5;    ///< derived scales re-taken when they moved by more
};

class RobustUkfIdentifier final : public Identifier {
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
    IdentificationStatus observe(double deformation, double force, bool updateRequested) override;
    std::span<const double> estimate() const override { return m_estimate; }
    std::span<const double> standardDeviation() const override { return m_stddev; }
    double predictedForce() const override { return m_predicted; }
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

    int anchors() const { return m_anchors; }
    int divergences() const { return m_divergences; }
    /// NRMSE of the last anchor over the history it saw (NaN before the first).
    double anchorNrmse() const { return m_anchorNrmse; }

    /// The step distance, in samples, between starting a job on a history of n samples and
    /// applying its result.
    static std::size_t jobDelay(std::size_t n) { return scheduledJobDelay(n); }
    /// Worker CPU spent in jobs so far [s], and their number (anchors and guard replays).
    double workerCpuSeconds() const { return m_workerCpu; }
    int jobs() const { return m_job.started(); }
    /// ... of which in anchor jobs (calibrations) [s].
    double anchorCpuSeconds() const { return m_anchorCpu; }
    /// Applications that had to wait for the worker (informative: depends on the machine).
    int waits() const { return m_job.waits(); }
    ~RobustUkfIdentifier() override = default; // cancels a running job (ScheduledJob)

private:
    struct JobOutcome {
        AnchorJobResult anchor;
        VerifyJobResult verify;
    };
    struct JobMeta {
        bool anchor = false; ///< else a guard replay of `candidate`
        bool diverged = false;
        bool discarded = false; ///< a divergence came after a guard replay was started
        double startAmplitude = 0.0;
        double anchorNrmseAtStart = 0.0;
        BoucWenParameters candidate;
    };
    using Job = ScheduledJob<JobMeta, JobOutcome>;
    void startAnchor(bool global, bool diverged, const std::optional<BoucWenParameters>& estimate);
    void startVerify(const BoucWenParameters& candidate);
    /// Applies the job's result (at its step); the status to return.
    IdentificationStatus applyJob();
    IdentificationStatus applyAnchor(const JobMeta& job, std::size_t startSize,
                                     const AnchorJobResult& r);
    /// The filter, its bounds and settings, and the anchor's model at r.best in `state` at
    /// the last deformation `u`.
    void startFilter(const AnchorJobResult& r, const BoucWenState& state, double u);
    void restartAtAnchor();
    void clearWindows();
    double anchorHistoryNrmse() const;
    void publish();

    BoucWenParameters m_initial;
    std::optional<double> m_uRef, m_fRef;
    ParameterBoundsMap m_userBounds; ///< as configured, by name (for the calibrations)
    RobustUkfSettings m_settings;
    std::optional<BoucWenUkf> m_ukf;
    BoucWenParameters m_anchor; ///< the last anchor (scales included)
    BoucWenParameters m_published; ///< the estimate last verified (or the anchor)
    std::array<double, kBoucWenUkfSize> m_anchorSd{};
    std::vector<double> m_u, m_f;
    double m_uMin = 0.0, m_uMax = 0.0, m_sumF2 = 0.0;
    std::size_t m_nextWarmUpCheck = 0;
    double m_maxAmplitude = 0.0, m_anchorAmplitude = 0.0;
    std::size_t m_anchorSize = 0;
    double m_anchorNrmse = std::numeric_limits<double>::quiet_NaN();
    double m_anchorRms = 0.0; ///< RMS force error of the anchor / fRef [-]
    std::optional<BoucWen> m_anchorLaw; ///< the anchor's model, stepped along the samples
    double m_anchorSse = 0.0;           ///< its squared force errors over the whole history
    std::vector<double> m_window;       ///< squared a-priori errors / fRef^2 (ring)
    std::vector<double> m_anchorWindow; ///< the anchor model's squared errors (same ring)
    double m_anchorWindowSum = 0.0;
    std::size_t m_windowNext = 0;
    double m_windowSum = 0.0;
    int m_recovering = 0;
    bool m_seeded = false;      ///< started from a previous record's calibration
    bool m_ownAnchor = false;   ///< an anchor on this test's history has been applied
    int m_anchors = 0, m_divergences = 0, m_pullBacks = 0;
    std::size_t m_nextCheck = 0; ///< history size of the next guard check
    double m_workerCpu = 0.0, m_anchorCpu = 0.0;
    double m_predicted = std::numeric_limits<double>::quiet_NaN();
    ParameterLayout m_layout;
    // Published in layout order (kRobustUkfParameters, uRef, fRef); NaN bounds: none yet.
    std::array<double, 9> m_estimate{}, m_stddev{};
    std::array<ParameterBounds, 9> m_bounds{};
    Job m_job; ///< the job running (at most one); last, so destroyed (cancelled) first
};

} // namespace hsmu
