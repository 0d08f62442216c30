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
    /// k0, alpha, beta, gamma, n, deltaNu, deltaEta.
    const ParameterLayout& layout() const override { return m_layout; }
    IdentificationStatus observe(double deformation, double force, bool updateRequested) override;
    std::span<const double> estimate() const override { return m_estimate; }
    std::span<const double> standardDeviation() const override { return m_stddev; }
    double predictedForce() const override { return m_predicted; }
    std::span<const ParameterBounds> bounds() const override { return m_bounds; }
    bool setBounds(std::size_t index, const ParameterBounds& b) override;

    BoucWenUkf& filter() { return m_ukf; }
    /// Lock a parameter at its current estimate (or unlock it).
    bool setLocked(std::size_t index, bool locked) override;
    bool locked(std::size_t index) const override;
    bool canLock() const override { return true; }

private:
    void publish(const BoucWenUkfStep* step);
    BoucWenUkf m_ukf;
    ParameterLayout m_layout;
    // The published estimate, standard deviations and bounds, in layout order.
    std::array<double, 7> m_estimate{}, m_stddev{};
    std::array<ParameterBounds, 7> m_bounds{};
    double m_predicted = 0.0;
};

} // namespace hsmu
