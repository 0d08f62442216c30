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
//     integrate), or the anchor's own model failing on the new deformation, start a refit
//     (global if the law cannot replay the history from the anchor or the estimate).
//  6. Guard: every max(50, N / 20) steps the UKF's estimate is replayed over the history (a
//     job); it is published if its NRMSE is within driftRatio of the anchor's, else the filter
//     goes back to the anchor, which is published.
//  7. Verdict: as the robust UKF (an anchor over >= verdictReversals turning points with
//     NRMSE above verdictNrmse).
// Jobs (ScheduledJob.h, as the robust UKF): the anchors (2, 4, 5, 5b) and the guard's replays
// (6) run on a worker thread, one at a time, on a copy of the history at step N_k; the result
// is applied at the step where the history reaches N_k + max(50, N_k / 20), observe() waiting
// there only if the worker is late, and caught up over the samples since N_k on the stepping
// thread. So the estimates depend on the samples only: an online run and an offline replay
// agree bit for bit. The destructor cancels a running job.
// Cost: a UKF step is 31 integrations of the pinching law (docs/benchmarks.md: the stepping
// thread's cost per step, the worker's per anchor). Values in the law's normalized units.
// Thread rules: observe() and the rest from one thread; the worker only reads its own copy of
// the inputs.

#include "core/hysteresis/BoucWenPinching.h"
#include "core/identification/PinchingUkf.h"
#include "core/updating/Identifier.h"
#include "core/updating/PinchingUkfJobs.h"
#include "core/updating/RobustUkfJobs.h"
#include "core/updating/ScheduledJob.h"

#include <limits>
#include <optional>
#include <vector>

namespace hsmu {

struct PinchingUkfIdentifierSettings {
    int warmUpReversals = 2;
    double anchorGrowth = 2.0;  ///< re-anchor (locally) when the history grew by this factor
    double globalGrowth = 4.0;  ///< ... globally when it grew by this since the last global
    double rescaleFactor = 1.5; ///< derived scales re-taken when they moved by more
    PinchingAnchorBudget budget;
    int divergenceWindow = 50;
    double divergenceRatio = 4.0;
    double divergenceFloor = 0.02;
    double parameterNoise = 1e-5; ///< random walk per step, fraction of the box width
    double driftRatio = 1.05;
    double staleRatio = 1.1;
    double verdictNrmse = 0.25;
    int verdictReversals = 4;
};

class PinchingUkfIdentifier final : public Identifier {
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
    IdentificationStatus observe(double deformation, double force, bool updateRequested) override;
    std::span<const double> estimate() const override { return m_estimate; }
    std::span<const double> standardDeviation() const override { return m_stddev; }
    double predictedForce() const override { return m_predicted; }
    /// Worker CPU time of the last anchor [s].
    double lastComputeSeconds() const override { return m_lastSeconds; }
    std::span<const ParameterBounds> bounds() const override { return m_bounds; }
    bool setBounds(std::size_t index, const ParameterBounds& b) override;

    int anchors() const { return m_anchors; }
    int globalAnchors() const { return m_globalAnchors; }
    int divergences() const { return m_divergences; }
    double anchorNrmse() const { return m_anchorNrmse; }
    /// The UKF itself (after the first anchor), e.g. for benchmarks.
    PinchingUkf* filter() { return m_ukf ? &*m_ukf : nullptr; }
    /// Worker CPU spent in jobs so far [s], of which in anchors; jobs started; applications
    /// that had to wait for the worker (informative: depends on the machine).
    double workerCpuSeconds() const { return m_workerCpu; }
    double anchorCpuSeconds() const { return m_anchorCpu; }
    int jobs() const { return m_job.started(); }
    int waits() const { return m_job.waits(); }

private:
    struct JobOutcome {
        PinchingAnchorJobResult anchor;
        VerifyJobResult verify;
    };
    struct JobMeta {
        bool anchor = false; ///< else a guard replay of `candidate`
        bool diverged = false;
        bool discarded = false; ///< a divergence came after a guard replay was started
        double anchorNrmseAtStart = 0.0;
        BoucWenPinchingParameters candidate;
    };
    using Job = ScheduledJob<JobMeta, JobOutcome>;
    void startAnchor(bool global, bool diverged);
    void startVerify(const BoucWenPinchingParameters& candidate);
    IdentificationStatus applyJob();
    IdentificationStatus applyAnchor(const JobMeta& job, std::size_t startSize,
                                     const PinchingAnchorJobResult& r);
    double anchorHistoryNrmse() const;
    void restartAtAnchor();
    void clearWindows();
    void publish(const BoucWenPinchingParameters& p);
    bool warmedUp();

    BoucWenPinchingParameters m_initial;
    std::optional<double> m_uRef, m_fRef;
    ParameterBoundsMap m_userBounds; ///< as configured, by name (for the calibrations)
    ParameterLayout m_layout;
    /// Published in layout order; NaN bounds: none.
    std::array<double, kPinchingUkfParameters + 2> m_estimate{}, m_stddev{};
    std::array<ParameterBounds, kPinchingUkfParameters + 2> m_bounds{};
    PinchingUkfIdentifierSettings m_settings;
    std::optional<PinchingUkf> m_ukf;
    BoucWenPinchingParameters m_anchor, m_published;
    std::array<double, kPinchingUkfParameters> m_anchorSd{};
    std::optional<BoucWenPinching> m_anchorLaw; ///< the anchor's model, stepped along
    double m_anchorSse = 0.0;                   ///< its squared force errors over the history
    std::vector<double> m_u, m_f;
    double m_uMin = 0.0, m_uMax = 0.0, m_sumF2 = 0.0;
    std::size_t m_nextWarmUpCheck = 0;
    std::size_t m_anchorSize = 0, m_globalSize = 0, m_nextCheck = 0;
    double m_anchorNrmse = std::numeric_limits<double>::quiet_NaN();
    double m_anchorRms = 0.0; ///< the anchor's RMS error / fRef
    std::vector<double> m_window, m_anchorWindow; ///< squared a-priori errors / fRef^2 (ring)
    double m_windowSum = 0.0, m_anchorWindowSum = 0.0;
    std::size_t m_windowNext = 0, m_windowFill = 0;
    int m_recovering = 0;
    int m_rejectedInRow = 0;
    int m_anchors = 0, m_globalAnchors = 0, m_divergences = 0;
    double m_predicted = std::numeric_limits<double>::quiet_NaN();
    double m_lastSeconds = 0.0, m_workerCpu = 0.0, m_anchorCpu = 0.0;
    Job m_job; ///< the job running (at most one); last, so destroyed (cancelled) first
};

} // namespace hsmu
