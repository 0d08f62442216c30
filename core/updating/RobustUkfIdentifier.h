#pragma once
// RobustUkfIdentifier: the default online identifier of a Bouc-Wen specimen (docs/method.md,
// "The robust UKF"): the joint state-parameter UKF (BoucWenUkf) anchored by least-squares
// calibrations (Calibration.h) of the history measured so far.
//
//  1. Warm-up. Until the specimen has gone through warmUpReversals turning points (dead band
//     2 % of its deformation range so far) the estimate stays at the initial model and
//     nothing is reported: there is nothing yet to identify.
//  2. Anchor. The law is calibrated on the history so far (multi-start Levenberg-Marquardt;
//     with the current estimate as one more start once tracking) and the better of that fit
//     and the current estimate, by NRMSE over the history, becomes the anchor. Scales: the
//     model's uRef / fRef when the configuration gives them, else derived once from the data
//     at the first anchor (HistoryScales.h) and then published as the estimate's uRef / fRef
//     so that the auxiliary model and the twins take them with the other parameters. The UKF
//     restarts at the anchor: parameters, the law's (z, e) replayed over the history, P0 from
//     the calibration's standard deviations (1 % to 10 % of each parameter's typical scale),
//     R from the anchor's RMS error (noise levels scaled from the data: the model error, not
//     the sensor's noise, bounds what the filter can explain).
//  3. Track. The UKF runs every step (unscented transform a = 1, kappa = 0, b = 2: positive
//     weights), sigma points and means kept admissible (BoucWenUkf.h).
//  4. Re-anchor when the history has grown by anchorGrowth since the last anchor (with the
//     calibration's multi-start), or the deformation amplitude by amplitudeGrowth (new
//     cycles the anchor has not seen; a local refit from the anchor and the estimate).
//  5. Divergence. The a-priori force error (UKF prediction - measured) / fRef, RMS over the
//     last divergenceWindow steps, above divergenceRatio times the larger of: the anchor
//     model's own error over the same steps (stepped along beside the filter: what the model
//     family can do there, so a specimen the law cannot follow is not a divergence), the
//     anchor's RMS error over its history, and divergenceFloor; or a non-finite estimate:
//     the step is rejected
//     (ok false, a message saying why), the UKF restarts from the last anchor, and for the
//     next divergenceWindow steps its estimates are not reportable (the Reporter passes
//     nothing to the twins until it has recovered).
//  5b. Guard. Every max(50, N / 20) steps the UKF's estimate and the anchor are replayed
//     over the whole history: an estimate within driftRatio of the anchor's NRMSE becomes
//     the published estimate; a worse one sends the filter back to the anchor, which is
//     published (the one-step prediction can stay good while the parameters drift: the
//     filter follows the force through z); an anchor whose NRMSE grew past staleRatio times
//     its value at its fit is refitted (step 2). So the estimate the auxiliary model and the
//     Reporter receive (updated, between the checks it stays) has always been verified on
//     the history measured so far.
//  6. Verdict. When an anchor over at least verdictReversals turning points fits no better
//     than verdictNrmse, the status carries the best NRMSE: the Inspector says that the model
//     family cannot represent the specimen.
// Values are in the law's normalized units. Thread rules: none.

#include "core/identification/BoucWenUkf.h"
#include "core/identification/Calibration.h"
#include "core/updating/Identifier.h"

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
    std::vector<std::string> parameterNames() const override;
    IdentificationStatus observe(double deformation, double force, bool updateRequested) override;
    ParameterValues estimate() const override;
    ParameterValues standardDeviation() const override;
    double predictedForce() const override { return m_predicted; }
    const ParameterBoundsMap& bounds() const override { return m_bounds; }
    bool setBounds(const std::string& name, const ParameterBounds& b) override;

    int anchors() const { return m_anchors; }
    int divergences() const { return m_divergences; }
    /// NRMSE of the last anchor over the history it saw (NaN before the first).
    double anchorNrmse() const { return m_anchorNrmse; }

private:
    /// global: the calibration's multi-start (first anchor, history doubled); else a local
    /// refit from the anchor and the current estimate.
    IdentificationStatus anchor(bool diverged, bool global);
    /// The law's (z, e) after replaying the history with p; false if the law fails.
    bool replayState(const BoucWenParameters& p, BoucWenState& state, double& nrmse) const;
    void publish();
    BoucWenParameters fromCalibration(const CalibrationResult& r) const;

    BoucWenParameters m_initial;
    std::optional<double> m_uRef, m_fRef;
    ParameterBoundsMap m_userBounds, m_bounds;
    RobustUkfSettings m_settings;
    std::optional<BoucWenUkf> m_ukf;
    BoucWenParameters m_anchor; ///< the last anchor (scales included)
    BoucWenParameters m_published; ///< the estimate last verified (or the anchor)
    std::array<double, kBoucWenUkfSize> m_anchorSd{};
    std::vector<double> m_u, m_f;
    double m_maxAmplitude = 0.0, m_anchorAmplitude = 0.0;
    std::size_t m_anchorSize = 0;
    double m_anchorNrmse = std::numeric_limits<double>::quiet_NaN();
    double m_anchorRms = 0.0; ///< RMS force error of the anchor / fRef [-]
    std::optional<BoucWen> m_anchorLaw;  ///< the anchor's model, stepped along the samples
    std::vector<double> m_window;        ///< squared a-priori errors / fRef^2 (ring)
    std::vector<double> m_anchorWindow;  ///< the anchor model's squared errors (same ring)
    double m_anchorWindowSum = 0.0;
    std::size_t m_windowNext = 0;
    double m_windowSum = 0.0;
    int m_recovering = 0;
    int m_anchors = 0, m_divergences = 0, m_pullBacks = 0;
    std::size_t m_nextCheck = 0; ///< history size of the next guard check
    double m_predicted = std::numeric_limits<double>::quiet_NaN();
    ParameterValues m_estimate, m_stddev;
};

} // namespace hsmu
