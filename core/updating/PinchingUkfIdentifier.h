#pragma once
// PinchingUkfIdentifier: the online identifier of a Bouc-Wen-Baber-Noori specimen with
// pinching (`"method": "ukf"` with a boucWenPinching model; docs/method.md, "The pinching
// UKF"): the joint state-parameter UKF of PinchingUkf.h anchored by the pinching calibration
// (CalibrationDefaults.h) of the history measured so far, on the same plan as the robust UKF
// of the plain law (RobustUkfIdentifier.h):
//  1. Warm-up: until the deformation has gone through warmUpReversals turning points (dead
//     band 2 % of its range so far) the estimate stays at the initial model, not reportable.
//  2. Anchor: the default pinching calibration of the history so far (the plain law's
//     optimum, then starts scattered around it) in a fixed normalization: the model's uRef /
//     fRef when the configuration gives them, else derived from the data at the first anchor
//     and kept (published as the estimate's uRef / fRef). The better, by NRMSE over the
//     history, of that fit and the UKF's current estimate is the anchor. The UKF restarts
//     there: (z, e) replayed over the history, P0 from the calibration's standard deviations
//     (1 % to 10 % of each parameter's typical scale), R from the anchor's RMS error, the box
//     the calibration's default box (the user's bounds replacing it by name).
//  3. Track: a UKF step per sample (PinchingUkf: sigma points and means admissible).
//  4. Re-anchor when the history has grown anchorGrowth times since the last global
//     calibration (a global one again), or when the guard finds the anchor stale (a local
//     refit from the anchor and the estimate; global if the law cannot replay the history
//     from either).
//  5. Divergence: the a-priori force error / fRef, RMS over divergenceWindow steps, above
//     divergenceRatio times the larger of the anchor model's own error over those steps, the
//     anchor's RMS error and divergenceFloor (or a non-finite estimate): the step is
//     rejected, the UKF restarts from the anchor and its estimates are not reportable for the
//     next divergenceWindow steps.
//  5b. Law failures: three UKF steps rejected in a row (a sigma point the law cannot
//     integrate), or the anchor's own model failing on the new deformation, bring a new
//     global anchor (the calibration only accepts laws that replay the whole history).
//  6. Guard: every max(50, N / 20) steps the UKF's estimate and the anchor are replayed over
//     the history; the estimate is published if its NRMSE is within driftRatio of the
//     anchor's, else the filter goes back to the anchor, which is published; an anchor whose
//     NRMSE grew past staleRatio times its value at its fit is refitted (local).
//  7. Verdict: as the robust UKF (an anchor over >= verdictReversals turning points with
//     NRMSE above verdictNrmse).
// Cost: the calibrations dominate (seconds on a few thousand samples, docs/benchmarks.md);
// a UKF step is 31 integrations of the pinching law. Values in the law's normalized units.
// Thread rules: none.

#include "core/hysteresis/BoucWenPinching.h"
#include "core/identification/PinchingUkf.h"
#include "core/updating/Identifier.h"

#include <limits>
#include <optional>
#include <vector>

namespace hsmu {

struct CalibrationResult;

struct PinchingUkfIdentifierSettings {
    int warmUpReversals = 2;
    double anchorGrowth = 2.0;
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
    /// Compute time of the last anchor [s].
    double lastComputeSeconds() const override { return m_lastSeconds; }
    std::span<const ParameterBounds> bounds() const override { return m_bounds; }
    bool setBounds(std::size_t index, const ParameterBounds& b) override;

    int anchors() const { return m_anchors; }
    int divergences() const { return m_divergences; }
    double anchorNrmse() const { return m_anchorNrmse; }
    /// The UKF itself (after the first anchor), e.g. for benchmarks.
    PinchingUkf* filter() { return m_ukf ? &*m_ukf : nullptr; }

private:
    IdentificationStatus anchor(bool global, bool diverged);
    /// NRMSE of p over the history and the law's state at its end; false if the law fails.
    bool replay(const BoucWenPinchingParameters& p, BoucWenState& end, double& nrmse) const;
    BoucWenPinchingParameters fromCalibration(const CalibrationResult& r) const;
    void restartAtAnchor();
    void publish(const BoucWenPinchingParameters& p);
    int reversals() const;

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
    std::vector<double> m_u, m_f;
    double m_uMin = 0.0, m_uMax = 0.0;
    std::size_t m_anchorSize = 0, m_globalSize = 0, m_nextCheck = 0;
    double m_anchorNrmse = std::numeric_limits<double>::quiet_NaN();
    double m_anchorRms = 0.0; ///< the anchor's RMS error / fRef
    std::vector<double> m_window, m_anchorWindow; ///< squared a-priori errors / fRef^2 (ring)
    double m_windowSum = 0.0, m_anchorWindowSum = 0.0;
    std::size_t m_windowNext = 0, m_windowFill = 0;
    int m_recovering = 0;
    int m_rejectedInRow = 0;
    int m_anchors = 0, m_divergences = 0;
    double m_predicted = std::numeric_limits<double>::quiet_NaN();
    double m_lastSeconds = 0.0;
};

} // namespace hsmu
