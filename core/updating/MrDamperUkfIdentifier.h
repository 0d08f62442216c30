#pragma once
// MrDamperUkfIdentifier: the online identifier of an MR damper (`"method": "ukf"` with an
// mrDamper model; docs/method.md, "The MR damper UKF"): the joint state-parameter UKF of
// MrDamperUkf.h anchored by the mrDamper calibration (CalibrationDefaults.h) of the history
// measured so far, on the plan of the pinching UKF (PinchingUkfIdentifier.h):
//  1. Warm-up: until the deformation has gone through warmUpReversals turning points (dead
//     band 2 % of its range so far) the estimate stays at the initial model, not reportable.
//  2. Anchor (a job on a worker, ScheduledJob.h): the calibration of the history so far, the
//     samples dt apart (dt: the model's time increment when the identifier is made, the
//     run's step); the first a global search, later ones a local refit warm-started from the
//     anchor and the UKF's estimate, global when the history has grown globalGrowth times
//     since the last global one or the local fit is poor. The better, by NRMSE over the
//     history, of the fit, the previous anchor and the UKF's estimate is the anchor. The UKF
//     restarts there: (w, z) replayed over the history, P0 from the calibration's standard
//     deviations (1 % to 10 % of each parameter's typical scale), R from the anchor's RMS
//     error, the box the calibration's default box (the user's bounds replacing it by name).
//  3. Track: a UKF step per sample; the anchor's model is stepped along beside it with its
//     running squared error.
//  4. Re-anchor when the history has grown anchorGrowth times since the last anchor.
//  5. Divergence: the a-priori force error / fRef, RMS over divergenceWindow steps, above
//     divergenceRatio times the larger of the anchor model's own error over those steps, the
//     anchor's RMS error and divergenceFloor (or a non-finite estimate), or three steps
//     rejected in a row: the UKF restarts from the anchor, a refit is started, and the
//     estimates are not reportable for divergenceWindow steps.
//  6. Guard: every max(50, N / 20) steps the UKF's estimate is replayed over the history (on
//     the stepping thread: one replay, verifyOnStep); it is published if its NRMSE is within
//     driftRatio of the anchor's, else the filter goes back to the anchor, which is published.
//  7. Verdict: an anchor over >= verdictReversals turning points with NRMSE above
//     verdictNrmse says the model family cannot represent the specimen.
// Scales: the model's uRef / fRef when the configuration gives them, else derived from the
// data at the first anchor (HistoryScales.h) and kept; user bounds are in those scales. They
// are published with the estimate (uRef, fRef), as the robust UKF's, so that the auxiliary
// model and the twins that take them hold the physical law that was fitted.
// The warm-up, anchoring, tracking, divergence recovery, guard and jobs are AnchoredUkf.h's
// (one machinery with the robust and pinching UKFs); this class gives the MR damper's parts:
// the filter (MrDamperUkf), the anchor job (mrDamperAnchorJob), the replay with the samples'
// times and the plan of point 4. The estimates depend on the samples only (the jobs' results
// are applied at fixed steps): an online run and an offline replay of its record agree bit for
// bit. The destructor cancels a running job.
// Thread rules: observe() and the rest from one thread; the worker only reads its own copy of
// the inputs.

#include "core/hysteresis/MrDamper.h"
#include "core/updating/AnchoredUkf.h"
#include "core/updating/MrDamperUkf.h"

#include <array>
#include <limits>
#include <optional>
#include <vector>

namespace hsmu {

struct MrDamperUkfIdentifierSettings : AnchoredUkfSettings {
    MrDamperUkfIdentifierSettings() {
        parameterNoise = 1e-7;
        fullWindowOnly = true;
        verifyOnStep = true;
    }
    int localIterations = 12;   ///< Levenberg-Marquardt iterations of a local refit
    double poorFitRatio = 1.25; ///< a local refit worse than this x the anchor's: global
};

/// What an anchor job computes (a pure function of its input; in the filter's scales).
struct MrDamperAnchorInput {
    std::vector<double> u, f, t;      ///< the history so far (physical units, s)
    std::optional<double> uRef, fRef; ///< the scales (given or fixed at the first anchor)
    std::optional<MrDamperParameters> anchor, estimate;
    double anchorNrmse = 0.0;
    MrDamperParameters initial; ///< the model (A; in the filter's scales when known)
    ParameterBoundsMap userBounds;
    bool global = true;
    MrDamperUkfIdentifierSettings settings;
};

struct MrDamperAnchorResult {
    bool ok = false;
    bool cancelled = false;
    std::string reason;
    bool global = false;
    MrDamperParameters best;    ///< the anchor (in its scales)
    MrDamperState state;        ///< the law's state at the snapshot's last sample
    double velocity = 0.0;      ///< the velocity of the last sample's step (physical)
    double nrmse = 0.0;         ///< over the snapshot
    double squaredErrors = 0.0; ///< sum of (F_law - F)^2 over the snapshot
    double rmsForce = 0.0;      ///< RMS(F) over the snapshot
    MrDamperUkf::Values sd{};   ///< P0 (normalized)
    MrDamperUkf::Box box{};
    bool rescaled = false;      ///< never: the scales stay those of the first anchor
    std::optional<double> modelInadequate;
    int residualEvaluations = 0;
    double cpuSeconds = 0.0;
};

MrDamperAnchorResult mrDamperAnchorJob(const MrDamperAnchorInput& in,
                                       const std::atomic<bool>* cancel = nullptr);

class MrDamperUkfIdentifier final
    : public AnchoredUkf<MrDamperParameters, MrDamper, MrDamperAnchorResult> {
public:
    /// model: the specimen's model (an MrDamper whose time increment is the samples' step).
    /// uRef / fRef: the configuration's scales, or std::nullopt (from the data). bounds: user
    /// bounds by name (the rest: CalibrationDefaults' box). Throws std::invalid_argument for a
    /// model without a time increment or a bound that is not one of the identified names.
    MrDamperUkfIdentifier(const MrDamper& model, std::optional<double> uRef,
                          std::optional<double> fRef, const ParameterBoundsMap& bounds,
                          const MrDamperUkfIdentifierSettings& settings = {});

    std::string methodName() const override { return "UKF (MR damper)"; }
    /// mrDamperUkfParameterNames() (c0, c1, k0, k1, f0, alpha, beta, gamma, n), then uRef and
    /// fRef (not filtered, no bounds).
    const ParameterLayout& layout() const override { return m_layout; }
    std::span<const double> estimate() const override { return m_estimate; }
    std::span<const double> standardDeviation() const override { return m_stddev; }
    std::span<const ParameterBounds> bounds() const override { return m_bounds; }
    bool setBounds(std::size_t index, const ParameterBounds& b) override;

private:
    const char* filterName() const override { return "MR damper UKF"; }
    bool filtering() const override { return m_ukf.has_value(); }
    FilterStep stepFilter(double u, double f) override;
    std::string startFilter(const MrDamperAnchorResult& r, const MrDamperState& state,
                            double u) override;
    void restartFilter(const MrDamperState& state, double u) override;
    AnchorWork anchorWork(bool global, bool diverged) override;
    VerifyWork verifyWork(const MrDamperParameters& candidate) const override;
    MrDamper anchorLaw(const MrDamperAnchorResult& r, double uPrevious) const override;
    double fRef(const MrDamperParameters& p) const override { return p.fRef; }
    double uRef(const MrDamperParameters& p) const override { return p.uRef; }
    bool finite(const MrDamperParameters& p) const override;
    void publish(const MrDamperParameters& p) override;
    AnchorPlan plan(std::size_t n) override;
    void appended() override { m_t.push_back(double(m_u.size() - 1) * m_dt); }

    MrDamperParameters m_model; ///< the configured model
    double m_dt;
    std::optional<double> m_uRef, m_fRef;
    ParameterBoundsMap m_userBounds;
    ParameterLayout m_layout;
    std::array<double, kMrDamperUkfParameters + 2> m_estimate{}, m_stddev{};
    std::array<ParameterBounds, kMrDamperUkfParameters + 2> m_bounds{};
    MrDamperUkfIdentifierSettings m_settings;
    std::optional<MrDamperUkf> m_ukf;
    std::vector<double> m_t; ///< the samples' times [s]
};

} // namespace hsmu
