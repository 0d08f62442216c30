#pragma once
// SpringElement: a hysteresis law acting on the generalized deformation q = sum c_k u_k.
// Covers the lateral spring between a DOF and ground (q = u_i), the truss / link between two
// DOFs (q = u_j - u_i, tension positive) and the rotational base spring under a *rigid*
// column of height L (q = theta = u_i / L, P = moment, lateral force M / L).

#include "core/structure/Element.h"

#include <memory>

namespace hsmu {

class SpringElement final : public Element {
public:
    SpringElement(std::string name, std::string typeName, std::vector<DofTerm> terms,
                  std::unique_ptr<HysteresisLaw> law);

    static std::unique_ptr<SpringElement> lateral(std::string name, int dof,
                                                  std::unique_ptr<HysteresisLaw> law);
    static std::unique_ptr<SpringElement> truss(std::string name, int dofI, int dofJ,
                                                std::unique_ptr<HysteresisLaw> law);
    /// Rotational spring under a rigid column; height [m] > 0.
    static std::unique_ptr<SpringElement> rotationalRigid(std::string name, int dof, double height,
                                                          std::unique_ptr<HysteresisLaw> law);

    std::string typeName() const override { return m_typeName; }
    ElementStatus setTrial(const Eigen::VectorXd& uFull) override;
    double deformation() const override { return m_law->trialDeformation(); }
    double force() const override { return m_law->trialForce(); }
    double initialGeneralizedStiffness() const override { return m_law->initialTangent(); }
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

private:
    std::string m_typeName;
    std::unique_ptr<HysteresisLaw> m_law;
};

} // namespace hsmu
