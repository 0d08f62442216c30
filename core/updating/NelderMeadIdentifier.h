#pragma once
// NelderMeadIdentifier: the online refit over the stored history (docs/method.md, "Online
// refits over the history"; the paper's Figures 1-2) as an Identifier: it stores the measured
// history every step and, when the Inspector requests an update (model error above its
// threshold) and the cooldown has passed, fits the named parameters over the history (the
// law replayed from its virgin state, the error over the last `windowSteps` samples). The
// fit is accepted only if it lowers the RMS error over that window; its compute time is
// reported.
//
// Two fits (settings.calibrated):
//  - calibration (default, for the laws CalibrationDefaults knows: boucWen, boucWenPinching,
//    bilinear): the bounded Levenberg-Marquardt of Calibration.h inside the user's bounds.
//    Every trigger runs a local fit warm-started from the current estimate (one start, the
//    reduced history then the whole); the global search runs as well when
//      (a) no global fit has run yet (and the deformation has reversed twice), or
//      (b) the history has grown to kGlobalGrowth (2) times its size at the last global fit,
//          or
//      (c) the local fit is poor: its NRMSE over the window above max(kPoorNrmse (0.10),
//          1.25 x the NRMSE the last global fit reached);
//    the better of the two is the result. The global search is the default calibration
//    (calibrateHistory: for boucWenPinching the plain law's optimum, then starts scattered
//    around it) inside the user's bounds when every parameter not fitted is one it fixes
//    (A0 = 1, deltaA = 0, uRef, fRef); otherwise CalibrationDefaults' starts in the fitted
//    parameters plus the current estimate and the local result, two polished, the others
//    held at the current estimate. Levenberg-Marquardt's iterations per phase are
//    max(5, maxEvaluations / (p + 1)) (p fitted parameters: one Jacobian costs p + 1
//    replays), so maxEvaluations still bounds the cost of one start.
//  - simplex: the paper's Nelder-Mead (HistoryFit.h) from the current estimate, at most
//    maxEvaluations replays; also the fallback for a law without calibration defaults.
// The method keeps its name ("nelderMead" in configurations, "Nelder-Mead" in messages).
// Values in the law's units (normalized for Bouc-Wen with the model's uRef / fRef, which
// stay fixed).

#include "core/identification/HistoryFit.h"
#include "core/updating/Identifier.h"

namespace hsmu {

class HysteresisLaw;
struct CalibrationSpec;
struct CalibrationRequest;

struct NelderMeadIdentifierSettings {
    std::vector<std::string> parameters; ///< fitted parameter names
    ParameterBoundsMap bounds;           ///< per fitted parameter (required, finite)
    int maxEvaluations = 300;            ///< replays per trigger (simplex) / per start
    int cooldownSteps = 100;             ///< steps between two triggers
    int windowSteps = 0;                 ///< RMS over the last N points (0 = all)
    bool calibrated = true;              ///< the calibration's fit (else the simplex)
};

class NelderMeadIdentifier final : public Identifier {
public:
    static constexpr double kGlobalGrowth = 2.0;
    static constexpr double kPoorNrmse = 0.10;

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

private:
    IdentificationStatus simplexRefit();
    IdentificationStatus calibratedRefit();
    CalibrationRequest refitRequest() const;
    /// Every parameter not fitted is one the default calibration fixes (A0 = 1, deltaA = 0,
    /// uRef, fRef) for a Bouc-Wen law: the global fit is the default calibration itself.
    bool wholeDefaultSet() const;
    /// The calibration spec of a refit (no starts); false if the law has no defaults.
    bool refitSpec(CalibrationSpec& spec, std::vector<std::vector<double>>& globalStarts) const;
    /// The fitted parameters of m_all into m_estimate (layout order).
    void publish();

    std::string m_law;
    ParameterValues m_all; ///< every parameter of the law (current estimate)
    NelderMeadIdentifierSettings m_s; ///< bounds by name, as the calibrations take them
    ParameterLayout m_layout;
    std::vector<double> m_estimate, m_stddev;
    std::vector<ParameterBounds> m_bounds;
    std::vector<double> m_u, m_f;
    int m_sinceTrigger;
    int m_triggers = 0;
    int m_globalFits = 0;
    int m_lastEvaluations = 0;
    std::size_t m_globalSize = 0; ///< history size at the last global fit (0: none yet)
    double m_globalNrmse = 0.0;   ///< NRMSE the last global fit reached
    double m_lastSeconds = 0.0;
};

} // namespace hsmu
