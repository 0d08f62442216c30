#pragma once
// UkfIdentifier: the Identifier of a Bouc-Wen specimen by the joint state-parameter UKF
// (BoucWenUkf; docs/method.md, The paper's UKF), run every step. Parameter values and standard
// deviations are in the law's normalized units. Identified: k0, alpha, beta, gamma, n, deltaNu,
// deltaEta (A0 and deltaA stay fixed, as in the paper).

#include "core/identification/BoucWenUkf.h"
#include "core/updating/Identifier.h"

#include <array>

namespace hsmu {

class UkfIdentifier final : public Identifier {
public:
    /// bounds: per parameter name (missing names keep Table III); throws std::invalid_argument
    /// naming the parameter if a bound is not admissible.
    UkfIdentifier(const BoucWenParameters& initial, const BoucWenUkfSettings& settings,
                  const ParameterBoundsMap& bounds);

    std::string methodName() const override { return "UKF"; }
    std::vector<std::string> parameterNames() const override;
    IdentificationStatus observe(double deformation, double force, bool updateRequested) override;
    ParameterValues estimate() const override;
    ParameterValues standardDeviation() const override;
    double predictedForce() const override { return m_predicted; }
    const ParameterBoundsMap& bounds() const override { return m_bounds; }
    bool setBounds(const std::string& name, const ParameterBounds& b) override;
    std::vector<std::string> estimateNames() const override;
    void estimateValues(std::vector<double>& out) const override;
    void standardDeviationValues(std::vector<double>& out) const override;
    void boundsValues(std::vector<ParameterBounds>& out) const override;

    BoucWenUkf& filter() { return m_ukf; }
    /// Lock a parameter at its current estimate (or unlock it).
    bool setLocked(const std::string& name, bool locked) override;
    bool locked(const std::string& name) const override;
    bool canLock() const override { return true; }

private:
    void publish(const BoucWenUkfStep* step);
    BoucWenUkf m_ukf;
    ParameterBoundsMap m_bounds;
    // The published estimate and standard deviations, indexed by BoucWenUkfIndex.
    std::array<double, kBoucWenUkfSize> m_estimate{}, m_stddev{};
    double m_predicted = 0.0;
};

} // namespace hsmu
