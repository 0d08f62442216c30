#include "core/structure/SpringElement.h"

namespace hsmu {

SpringElement::SpringElement(std::string name, std::string typeName, std::vector<DofTerm> terms,
                             std::unique_ptr<HysteresisLaw> law)
    : Element(std::move(name), std::move(terms)), m_typeName(std::move(typeName)),
      m_law(std::move(law))
{
}

std::unique_ptr<SpringElement> SpringElement::lateral(std::string name, int dof,
                                                      std::unique_ptr<HysteresisLaw> law)
{
    return std::make_unique<SpringElement>(std::move(name), "lateralSpring",
                                           std::vector<DofTerm>{{dof, 1.0}}, std::move(law));
}

std::unique_ptr<SpringElement> SpringElement::truss(std::string name, int dofI, int dofJ,
                                                    std::unique_ptr<HysteresisLaw> law)
{
    return std::make_unique<SpringElement>(std::move(name), "truss",
                                           std::vector<DofTerm>{{dofI, -1.0}, {dofJ, 1.0}},
                                           std::move(law));
}

std::unique_ptr<SpringElement> SpringElement::rotationalRigid(std::string name, int dof,
                                                              double height,
                                                              std::unique_ptr<HysteresisLaw> law)
{
    return std::make_unique<SpringElement>(std::move(name), "rotationalBaseSpring",
                                           std::vector<DofTerm>{{dof, 1.0 / height}},
                                           std::move(law));
}

ElementStatus SpringElement::setTrial(const Eigen::VectorXd& uFull)
{
    const LawStatus s = m_law->setTrialDeformation(kinematicDeformation(uFull));
    if (s != LawStatus::Ok) {
        const std::string why = m_law->failureReason();
        return ElementStatus::failure(name() + ": " + (why.empty() ? lawStatusName(s) : why));
    }
    return ElementStatus::success();
}

ElementStatus SpringElement::commit()
{
    m_law->commit();
    return ElementStatus::success();
}

} // namespace hsmu
