#pragma once
// NelderMeadIdentifier: the paper's Nelder-Mead identification (its Figures 1-2) as an
// Identifier: it stores the measured history every step and, when the Inspector requests an
// update (model error above its threshold) and the cooldown has passed, fits the named
// parameters over the history (HistoryFit: the law replayed from its virgin state). The fit
// is accepted only if it lowers the RMS error; its compute time is reported.
// Works for any law LawFactory builds ("boucWen", "bilinear"); values in the law's units.

#include "core/identification/HistoryFit.h"
#include "core/updating/Identifier.h"

namespace hsmu {

class HysteresisLaw;

struct NelderMeadIdentifierSettings {
    std::vector<std::string> parameters; ///< fitted parameter names
    ParameterBoundsMap bounds;           ///< per fitted parameter (required, finite)
    int maxEvaluations = 300;            ///< replays per trigger
    int cooldownSteps = 100;             ///< steps between two triggers
    int windowSteps = 0;                 ///< RMS over the last N points (0 = all)
};

class NelderMeadIdentifier final : public Identifier {
public:
    /// model: the specimen's numerical model (its law name and initial parameters).
    /// Throws std::invalid_argument naming a parameter without finite bounds or unknown.
    NelderMeadIdentifier(const HysteresisLaw& model, const NelderMeadIdentifierSettings& s);

    std::string methodName() const override { return "Nelder-Mead"; }
    std::vector<std::string> parameterNames() const override { return m_s.parameters; }
    IdentificationStatus observe(double deformation, double force, bool updateRequested) override;
    ParameterValues estimate() const override;
    ParameterValues standardDeviation() const override;
    double predictedForce() const override;
    const ParameterBoundsMap& bounds() const override { return m_s.bounds; }
    bool setBounds(const std::string& name, const ParameterBounds& b) override;
    double lastComputeSeconds() const override { return m_lastSeconds; }

    int triggers() const { return m_triggers; }

private:
    std::string m_law;
    ParameterValues m_all; ///< every parameter of the law (current estimate)
    NelderMeadIdentifierSettings m_s;
    std::vector<double> m_u, m_f;
    int m_sinceTrigger;
    int m_triggers = 0;
    double m_lastSeconds = 0.0;
};

} // namespace hsmu
