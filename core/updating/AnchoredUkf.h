#pragma once
// AnchoredUkf: the one machinery of the anchored online filters (docs/method.md, "The robust
// UKF", "The pinching UKF", "The MR damper UKF"): a joint state-parameter UKF of a law run every
// step, anchored by calibrations of the history measured so far. Written once here; the robust
// (Bouc-Wen), pinching and MR damper identifiers are configurations of it, each giving the
// law-specific parts (a small interface, below): the filter's step and restart, the anchor's
// calibration job, the replay that verifies a candidate, the anchor model's catch-up and which
// job to start when none runs.
//
//  1. Warm-up. Until the deformation has gone through warmUpReversals turning points (dead band
//     2 % of its range so far, counted every max(1, N / 50) samples) the estimate stays at the
//     initial model, not reportable.
//  2. Anchor: a calibration of the history so far (the law's job, anchorWork()); its result
//     becomes the anchor, the filter restarts there (startFilter()): (z, e) replayed over the
//     history, P0 from the calibration's standard deviations, R from the anchor's RMS error.
//  3. Track: a filter step per sample (stepFilter()); the anchor's model is stepped along
//     beside it with its running squared error over the whole history.
//  4. Re-anchor when the law's plan() says so (the history or the amplitude grew, a global
//     search due).
//  5. Divergence: the a-priori force error / fRef, RMS over the last divergenceWindow steps,
//     above divergenceRatio times the larger of the anchor model's own error over the same
//     steps (what the model family can do there), the anchor's RMS error over its history and
//     divergenceFloor (once the window has filled since the last restart, if fullWindowOnly);
//     or a non-finite estimate or prediction: the step is rejected (ok false,
//     a message saying why), the filter restarts at the anchor, a local refit is started and
//     the estimates are not reportable for the next divergenceWindow steps.
//  5b. Law failures: three filter steps rejected in a row (a sigma point the law cannot
//     integrate) restart the filter at the anchor and start a local refit; the anchor's own
//     model failing on the new deformation starts a global one (the filter keeps its state:
//     the anchor's is behind).
//  6. Guard, every max(50, N / 20) steps: the anchor's NRMSE over the whole history comes from
//     its running error (no replay); one that grew past staleRatio times its value at its fit
//     is refitted (a local anchor). Else the filter's estimate is replayed over the history (a
//     job, verifyWork(); on the stepping thread if verifyOnStep): within driftRatio of the
//     anchor's NRMSE it is published; a worse one sends the filter back to the anchor, which
//     is published. So the estimate the auxiliary model and the Reporter receive has been
//     verified on the history measured so far.
//  7. Verdict: the anchor job's modelInadequate (an anchor over >= verdictReversals turning
//     points with NRMSE above verdictNrmse) is passed on in the status.
// Jobs (ScheduledJob.h): anchors and the guard's replays run on a worker thread, one at a
// time, on a copy of the history at step N_k; the result is applied at the step where the
// history reaches N_k + max(50, N_k / 20), observe() waiting for the worker there only if it
// is late, and caught up over the samples since N_k on the stepping thread (the anchor's model
// stepped over them). So the estimates depend on the samples only: an online run and an
// offline replay of its record agree bit for bit. The destructor cancels a running job.
// Values in the law's normalized units. Thread rules: observe() and the rest from one thread;
// the worker only reads its own copy of the inputs (the law's work closures copy them).

#include "core/identification/HistoryScales.h"
#include "core/updating/Identifier.h"
#include "core/updating/RobustUkfJobs.h"
#include "core/updating/ScheduledJob.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hsmu {

/// The settings every anchored filter shares (each law's settings add to them).
struct AnchoredUkfSettings {
    int warmUpReversals = 2;       ///< turning points before the first anchor
    double anchorGrowth = 2.0;     ///< re-anchor when the history grew by this factor
    double globalGrowth = 4.0;     ///< ... globally when it grew by this since the last global
    int divergenceWindow = 50;     ///< [steps]
    double divergenceRatio = 4.0;  ///< window RMS error / the anchor's that diverges
    double divergenceFloor = 0.02; ///< errors below this fraction of fRef never diverge
    /// Judge the window only once it has filled since the last restart (the pinching and MR
    /// damper UKFs; the robust UKF judges the window zero-padded from the first step).
    bool fullWindowOnly = false;
    /// The guard's replay on the stepping thread, applied at once (the MR damper UKF: one
    /// replay of the history per guard step), instead of a job applied max(50, N / 20) later.
    bool verifyOnStep = false;
    double parameterNoise = 1e-5;  ///< random walk per step, fraction of the box width
    double driftRatio = 1.05;      ///< estimate's history NRMSE / the anchor's: pull back
    double staleRatio = 1.1;       ///< anchor's history NRMSE / at its fit: refit
    double verdictNrmse = 0.25;    ///< an anchor worse than this: the model family is poor
    int verdictReversals = 4;      ///< ... judged once the history has this many reversals
    double rescaleFactor = 1.5;    ///< derived scales re-taken when they moved by more
};

/// The next job when none runs (AnchoredUkf::plan()).
enum class AnchorPlan {
    GlobalAnchor, ///< an anchor with the calibration's global search
    LocalAnchor,  ///< a local refit from the anchor and the estimate
    Guard,        ///< at the guard's step: a refit if the anchor is stale, else a verification
    VerifyOnly,   ///< at the guard's step: a verification (no refit)
    Nothing
};

/// Parameters: the law's parameter set; Law: the law (stepped along as the anchor's model);
/// Anchor: the anchor job's result (ok, reason, cancelled, global, best, state, nrmse,
/// squaredErrors, rmsForce, rescaled, modelInadequate, cpuSeconds).
template <class Parameters, class Law, class Anchor>
class AnchoredUkf : public Identifier {
public:
    using State = decltype(std::declval<const Law&>().committedState());

    IdentificationStatus observe(double deformation, double force, bool updateRequested) override;
    double predictedForce() const override { return m_predicted; }
    /// Worker CPU time of the last anchor [s].
    double lastComputeSeconds() const override { return m_lastSeconds; }

    int anchors() const { return m_anchors; }
    int globalAnchors() const { return m_globalAnchors; }
    int divergences() const { return m_divergences; }
    /// NRMSE of the last anchor over the history it saw (NaN before the first).
    double anchorNrmse() const { return m_anchorNrmse; }
    /// The step distance, in samples, between starting a job on a history of n samples and
    /// applying its result.
    static std::size_t jobDelay(std::size_t n) { return scheduledJobDelay(n); }
    /// Worker CPU spent in jobs so far [s], of which in anchors; jobs started; applications
    /// that had to wait for the worker (informative: depends on the machine).
    double workerCpuSeconds() const { return m_workerCpu; }
    double anchorCpuSeconds() const { return m_anchorCpu; }
    int jobs() const { return m_job.started(); }
    int waits() const { return m_job.waits(); }
    /// The published estimate as a whole law.
    const Parameters& published() const { return m_published; }

protected:
    struct FilterStep {
        bool ok = true;
        std::string reason;      ///< why the step was rejected
        double predictedForce = 0.0; ///< a-priori (physical units)
        Parameters estimate;     ///< after the update
    };
    using AnchorWork = std::function<Anchor(const std::atomic<bool>& cancel)>;
    using VerifyWork = std::function<VerifyJobResult()>;

    AnchoredUkf(const Parameters& initial, const AnchoredUkfSettings& settings)
        : m_common(settings), m_anchor(initial), m_published(initial) {
        m_window.assign(std::size_t(std::max(1, settings.divergenceWindow)), 0.0);
        m_anchorWindow = m_window;
    }

    // The law-specific parts.
    /// "UKF", "pinching UKF" ...: the messages' subject.
    virtual const char* filterName() const = 0;
    virtual bool filtering() const = 0;
    virtual FilterStep stepFilter(double u, double f) = 0;
    /// The filter at r.best with the law's internal state `state` at the deformation u, its box,
    /// P0 from r.sd and R from anchorRms(); "" or why it cannot start.
    virtual std::string startFilter(const Anchor& r, const State& state, double u) = 0;
    /// The filter back at the anchor (m_anchor, the last anchor's sd) in `state` at u.
    virtual void restartFilter(const State& state, double u) = 0;
    /// The anchor job on a copy of the history so far (diverged: without the estimate).
    virtual AnchorWork anchorWork(bool global, bool diverged) = 0;
    /// The replay of a candidate over a copy of the history so far.
    virtual VerifyWork verifyWork(const Parameters& candidate) const = 0;
    /// The anchor's model at r.best in r.state at the deformation uPrevious (to catch up).
    virtual Law anchorLaw(const Anchor& r, double uPrevious) const = 0;
    virtual double fRef(const Parameters& p) const = 0;
    virtual double uRef(const Parameters& p) const = 0;
    virtual bool finite(const Parameters& p) const = 0;
    /// m_published = p and the published values.
    virtual void publish(const Parameters& p) = 0;
    /// The next job when none runs, at history size n (the guard's step is the base's).
    virtual AnchorPlan plan(std::size_t n) = 0;
    /// More of the anchor message (", zetaS 0.84").
    virtual std::string anchorNote(const Anchor&) const { return ""; }
    /// A history sample was appended (e.g. its time).
    virtual void appended() {}

    // For the laws' plan() and work.
    bool warmedUp();
    double anchorHistoryNrmse() const {
        return m_sumF2 > 0 ? std::sqrt(m_anchorSse / m_sumF2) : 0.0;
    }
    /// The anchor's RMS force error / fRef (R of the filter started at it).
    double anchorRms() const { return m_anchorRms; }
    /// Takes a seed's anchor (fitted elsewhere: no history of this test yet) in `state` at u.
    bool takeSeed(const Anchor& r, const State& state, double u, std::string& error);
    void startAnchor(bool global, bool diverged);

    AnchoredUkfSettings m_common;
    Parameters m_anchor, m_published;
    Anchor m_fit{};   ///< the last anchor job's result applied (its sd, box ...)
    bool m_ownAnchor = false; ///< an anchor on this test's history has been applied
    std::vector<double> m_u, m_f;
    double m_maxAmplitude = 0.0, m_anchorAmplitude = 0.0;
    std::size_t m_anchorSize = 0, m_globalSize = 0, m_nextCheck = 0;
    int m_anchors = 0, m_globalAnchors = 0, m_divergences = 0, m_pullBacks = 0;
    double m_workerCpu = 0.0, m_anchorCpu = 0.0;

private:
    struct JobOutcome {
        Anchor anchor{};
        VerifyJobResult verify;
    };
    struct JobMeta {
        bool anchor = false; ///< else a guard replay of `candidate`
        bool diverged = false;
        bool discarded = false; ///< a divergence came after a guard replay was started
        double startAmplitude = 0.0;
        double anchorNrmseAtStart = 0.0;
        Parameters candidate{};
    };
    using Job = ScheduledJob<JobMeta, JobOutcome>;

    void startVerify(const Parameters& candidate);
    IdentificationStatus applyJob();
    /// The guard's verdict on `candidate` replayed as v, against the anchor's NRMSE na.
    IdentificationStatus applyVerify(const Parameters& candidate, double na,
                                     const VerifyJobResult& v);
    IdentificationStatus applyAnchor(const JobMeta& job, std::size_t startSize, const Anchor& r);
    IdentificationStatus recover(bool anchorFailed, bool lawFailed, double rms, double reference);
    void clearWindows();
    void setAnchor(const Anchor& r, Law law, double sse, std::size_t startSize);

    double m_uMin = 0.0, m_uMax = 0.0, m_sumF2 = 0.0;
    std::size_t m_nextWarmUpCheck = 0;
    double m_anchorNrmse = std::numeric_limits<double>::quiet_NaN();
    double m_anchorRms = 0.0;
    std::optional<Law> m_anchorLaw; ///< the anchor's model, stepped along the samples
    double m_anchorSse = 0.0;       ///< its squared force errors over the whole history
    std::vector<double> m_window, m_anchorWindow; ///< squared a-priori errors / fRef^2 (ring)
    double m_windowSum = 0.0, m_anchorWindowSum = 0.0;
    std::size_t m_windowNext = 0, m_windowFill = 0;
    int m_recovering = 0, m_rejectedInRow = 0;
    double m_predicted = std::numeric_limits<double>::quiet_NaN();
    double m_lastSeconds = 0.0;
    Job m_job; ///< the job running (at most one); last, so destroyed (cancelled) first
};

} // namespace hsmu

#include "core/updating/AnchoredUkfImpl.h"
