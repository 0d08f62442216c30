#pragma once
// NelderMeadIdentifier: the online refit over the stored history (docs/method.md, "Online
// refits over the history"; the paper's Figures 1-2) as an Identifier: it stores the measured
// history every step and, when the Inspector requests an update (model error above its
// threshold) and the cooldown has passed, fits the named parameters over the history (the
// law replayed from its virgin state, the error over the last `windowSteps` samples). The
// fit is accepted only if it lowers the RMS error over that window (judged on the whole
// history, whatever the fit ran on); its compute time is reported.
//
// Scales and bounds (as the calibration and the robust UKF, docs/method.md "Scaling from the
// data"): a fitted parameter without configured bounds takes the calibration's default box
// (CalibrationDefaults.h) for the history seen so far, for any law with calibration defaults
// (others need bounds: std::invalid_argument). A Bouc-Wen law whose configuration gives no
// uRef / fRef runs on scales derived from the data (HistoryScales.h) at the first trigger
// whose history has them, re-derived at later triggers and taken when either moved by more
// than kRescaleFactor (1.5); the estimate is re-expressed exactly in the new scales (the same
// physical model) and uRef / fRef are published after the fitted parameters in the layout,
// so that the auxiliary model and the twins take them. Bounds are published once known
// (NaN before the first refit for the data-derived ones).
//
// Cost (settings.refitSamples, refitGrowth): (a) a calibrated refit runs only once the
// history has grown by refitGrowth (10 %) since the last refit (besides the cooldown), so a
// record of N samples costs about ln(N / N0) / ln(1.1) refits after the first at N0 (the
// simplex refits likewise past kSimplexSpacedSamples (10000) samples; before, the paper's
// cooldown alone, as paper-bilinear-nelder-mead's 3000 steps keep it);
// (b) on a history longer than refitSamples (2000) samples the calibrated fits run on the
// reduced history of refitSamples samples (Calibration.h, polishSamples; not with a window),
// warm-started from the current estimate; the acceptance replay is over the whole history.
// finalFit() (offline, after the last sample) has no such budget.
//
// Two fits (settings.calibrated):
//  - calibration (default, for the laws CalibrationDefaults knows: boucWen, boucWenPinching,
//    bilinear): the bounded Levenberg-Marquardt of Calibration.h inside the box above.
//    Every trigger runs a local fit warm-started from the current estimate (one start, the
//    reduced history then the whole); the global search runs as well when
//      (a) no global fit has run yet (and the deformation has reversed twice), or
//      (b) the history has grown to kGlobalGrowth (2) times its size at the last global fit,
//          or
//      (c) the local fit is poor: its NRMSE over the window above max(kPoorNrmse (0.10),
//          1.25 x the NRMSE the last global fit reached), once the history has grown by
//          kPoorGrowth (1.25) since the last global fit (not at the final fit);
//    the better of the two is the result. The global search is the default calibration
//    (calibrateHistory: for boucWenPinching the plain law's optimum, then starts scattered
//    around it; with derived scales its own, which the estimate then takes) inside the box
//    when every parameter not fitted is one it fixes (A0 = 1, deltaA = 0, uRef, fRef);
//    otherwise CalibrationDefaults' starts in the fitted parameters plus the current
//    estimate and the local result, two polished, the others held at the current estimate.
//    Levenberg-Marquardt's iterations per phase are max(5, maxEvaluations / (p + 1)) (p
//    fitted parameters: one Jacobian costs p + 1 replays), so maxEvaluations still bounds
//    the cost of one start.
//  - simplex: the paper's Nelder-Mead (HistoryFit.h) from the current estimate, at most
//    maxEvaluations replays; also the fallback for a law without calibration defaults.
// The method keeps its name ("nelderMead" in configurations, "Nelder-Mead" in messages).
// Values in the law's units (normalized for Bouc-Wen with uRef / fRef). A rate-dependent
// model (mrDamper) is replayed with the samples a step apart, the step being the model's time
// increment when the identifier is made (the run's dt); its refits go through its
// calibration defaults in the model's own uRef / fRef.

#include "core/identification/HistoryFit.h"
#include "core/updating/Identifier.h"

#include <array>
#include <optional>

namespace hsmu {

class HysteresisLaw;
struct CalibrationSpec;
struct CalibrationRequest;
struct HistoryScales;

struct NelderMeadIdentifierSettings {
    std::vector<std::string> parameters; ///< fitted parameter names
    /// per fitted parameter (finite); missing: the calibration's default box from the data
    ParameterBoundsMap bounds;
    /// The configuration's scales (Bouc-Wen laws); missing: derived from the data
    std::optional<double> uRef, fRef;
    int maxEvaluations = 300;            ///< replays per trigger (simplex) / per start
    int cooldownSteps = 100;             ///< steps between two triggers
    int windowSteps = 0;                 ///< RMS over the last N points (0 = all)
    bool calibrated = true;              ///< the calibration's fit (else the simplex)
    std::size_t refitSamples = 2000;     ///< cost budget of one refit on long histories
    double refitGrowth = 0.1;            ///< ... and the growth between two refits there
};

class NelderMeadIdentifier final : public Identifier {
public:
    static constexpr double kGlobalGrowth = 2.0;
    static constexpr double kPoorNrmse = 0.10;
    static constexpr double kPoorGrowth = 1.25;
    static constexpr double kRescaleFactor = 1.5;
    static constexpr std::size_t kSimplexSpacedSamples = 10000;

    /// model: the specimen's numerical model (its law name and initial parameters).
    /// Throws std::invalid_argument naming a parameter without finite bounds or unknown.
    NelderMeadIdentifier(const HysteresisLaw& model, const NelderMeadIdentifierSettings& s);

    std::string methodName() const override { return "Nelder-Mead"; }
    /// The fitted parameters, in the settings' order.
    const ParameterLayout& layout() const override { return m_layout; }
    IdentificationStatus observe(double deformation, double force, bool updateRequested) override;
    std::span<const double> estimate() const override { return m_estimate; }
    /// Zeros (the fits give no standard deviation).
    std::span<const double> standardDeviation() const override { return m_stddev; }
    double predictedForce() const override;
    std::span<const ParameterBounds> bounds() const override { return m_bounds; }
    bool setBounds(std::size_t index, const ParameterBounds& b) override;
    double lastComputeSeconds() const override { return m_lastSeconds; }

    int triggers() const { return m_triggers; }
    int globalFits() const { return m_globalFits; }
    /// Replays of the history by the last trigger.
    int lastEvaluations() const { return m_lastEvaluations; }
    /// The scales are derived from the data (a Bouc-Wen law without configured uRef / fRef).
    bool derivesScales() const { return m_deriveScales; }
    /// Every parameter of the law at the current estimate.
    const ParameterValues& values() const { return m_all; }

    /// One more fit over the whole history (offline, after the last sample: no window, no
    /// sample budget, no growth rule); the estimate changes only if it lowers the RMS force
    /// error over the history. Its status says what ran.
    IdentificationStatus finalFit();

private:
    IdentificationStatus refit(bool final);
    IdentificationStatus simplexRefit(bool final);
    IdentificationStatus calibratedRefit(bool final);
    CalibrationRequest refitRequest(bool final) const;
    /// Derive the scales from the history (derived mode): the first time, or when they moved
    /// by more than kRescaleFactor (always at the final fit); the estimate is re-expressed in
    /// them. False when the history has no scales yet (nothing is fitted then).
    bool updateScales(bool final, std::string& note);
    /// The box of every fitted parameter: the user's, else the default box of the law for
    /// these scales; false where a parameter has neither.
    bool fittedBox(const HistoryScales& scales, std::vector<ParameterBounds>& box) const;
    /// Every parameter not fitted is one the default calibration fixes (A0 = 1, deltaA = 0,
    /// uRef, fRef) for a Bouc-Wen law: the global fit is the default calibration itself.
    bool wholeDefaultSet() const;
    /// The calibration spec of a refit (no starts); false if the law has no defaults.
    bool refitSpec(bool final, CalibrationSpec& spec,
                   std::vector<std::vector<double>>& globalStarts) const;
    /// The calibration's budget applies (a history longer than refitSamples, no window).
    bool budgeted(bool final) const;
    /// The fitted parameters of m_all into m_estimate (layout order).
    void publish();

    std::string m_law;
    ParameterValues m_all; ///< every parameter of the law (current estimate)
    NelderMeadIdentifierSettings m_s; ///< bounds by name, as the calibrations take them
    bool m_deriveScales = false; ///< uRef / fRef from the data (published in the layout)
    bool m_scaled = false;       ///< the derived scales have been taken once
    std::array<double, 2> m_scaleBasis{1.0, 1.0}; ///< uRef, fRef last derived from the data
    ParameterLayout m_layout;
    std::vector<double> m_estimate, m_stddev;
    std::vector<ParameterBounds> m_bounds;
    std::vector<double> m_u, m_f;
    /// A rate-dependent model (mrDamper): the samples' times, k dt with the model's time
    /// increment at construction (the run's step); empty otherwise.
    std::vector<double> m_t;
    double m_dt = 0.0;
    int m_sinceTrigger;
    std::size_t m_lastRefitSize = 0; ///< history size at the last refit
    int m_triggers = 0;
    int m_globalFits = 0;
    int m_lastEvaluations = 0;
    std::size_t m_globalSize = 0; ///< history size at the last global fit (0: none yet)
    double m_globalNrmse = 0.0;   ///< NRMSE the last global fit reached
    double m_lastSeconds = 0.0;
};

} // namespace hsmu
