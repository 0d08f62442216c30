#pragma once
// FlexibleColumnSpring: rotational base spring under an *elastic* cantilever column of height
// L and flexural rigidity EI, in series. With chord rotation q = u / L (u = lateral top
// displacement of the DOF) and spring rotation theta, compatibility and equilibrium give
//
//   q = theta + M(theta) L / (3 EI),        lateral force V = M / L,
//
// (cantilever tip flexibility L^3 / (3 EI) for V = M / L). theta is found by a safeguarded
// Newton iteration on the spring law (its trials start from the committed state each time).
// For a rigid column use SpringElement::rotationalRigid.

#include "core/structure/Element.h"

#include <memory>

namespace hsmu {

class FlexibleColumnSpring final : public Element {
public:
    /// height [m] > 0, ei [kN m^2] > 0, law: moment [kN m] vs rotation [rad].
    FlexibleColumnSpring(std::string name, int dof, double height, double ei,
                         std::unique_ptr<HysteresisLaw> law);

    std::string typeName() const override { return "rotationalBaseSpring"; }
    ElementStatus setTrial(const Eigen::VectorXd& uFull) override;
    double deformation() const override { return m_law->trialDeformation(); }
    double force() const override { return m_law->trialForce(); }
    double initialGeneralizedStiffness() const override;
    ElementStatus commit() override;
    void revert() override { m_law->revert(); }
    HysteresisLaw* law() override { return m_law.get(); }
    const HysteresisLaw* law() const override { return m_law.get(); }
    bool swapLaw(std::unique_ptr<HysteresisLaw>& law) override
    {
        if (!law)
            return false;
        m_law.swap(law);
        return true;
    }

    double columnFlexibility() const { return m_flex; } ///< L / (3 EI) [rad per kN m]

private:
    std::unique_ptr<HysteresisLaw> m_law;
    double m_flex;
};

} // namespace hsmu
