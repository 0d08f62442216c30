#include "core/structure/Link2dElement.h"

#include <stdexcept>

namespace hsmu {

namespace {
std::vector<DofTerm> primaryTerms(const std::string& name, const Link2dGeometry& g, int primary)
{
    if (primary < 0 || primary > 2)
        throw std::invalid_argument("element '" + name + "': primary basic DOF must be 0, 1 or 2");
    return Link2dKinematics(name, g).terms(primary);
}
} // namespace

Link2dElement::Link2dElement(std::string name, const Link2dGeometry& geometry,
                             std::array<Link2dBasicDof, 3> dofs, int primary)
    : Element(name, primaryTerms(name, geometry, primary)), m_kin(name, geometry),
      m_dofs(std::move(dofs)), m_primary(primary)
{
    if (!m_dofs[m_primary].law)
        throw std::invalid_argument("element '" + name + "': the primary basic DOF needs a law");
    for (int i = 0; i < 3; ++i)
        m_q[i] = m_dofs[i].law ? 0.0 : heldForce(i);
}

double Link2dElement::heldForce(int i) const
{
    return scheduledForce(m_dofs[i].forceSchedule, m_dofs[i].heldForce, m_time); // eq. F1
}

bool Link2dElement::timeDependent() const
{
    for (const auto& dof : m_dofs)
        if (!dof.law && !dof.forceSchedule.empty())
            return true;
    return false;
}

ElementStatus Link2dElement::setTrial(const Eigen::VectorXd& uFull)
{
    m_ue = m_kin.local(uFull);
    if (m_kin.corotational()) {
        if (const std::string why = m_kin.chordFault(m_ue); !why.empty())
            return ElementStatus::failure(name() + ": " + why);
        m_d = m_kin.basicAt(m_ue); // eq. L3
    } else {
        m_d = m_kin.basic(uFull); // eq. L1
    }
    for (int i = 0; i < 3; ++i) {
        HysteresisLaw* law = m_dofs[i].law.get();
        if (!law) {
            m_q[i] = heldForce(i);
            continue;
        }
        if (LawStatus s = law->setTrialDeformation(m_d[i]); s != LawStatus::Ok)
            return ElementStatus::failure(name() + ": basic DOF " + std::to_string(i) + ": " +
                                          lawStatusName(s));
        m_q[i] = law->trialForce();
    }
    return ElementStatus::success();
}

double Link2dElement::initialGeneralizedStiffness() const
{
    return m_dofs[m_primary].law->initialTangent();
}

ElementStatus Link2dElement::commit()
{
    for (auto& dof : m_dofs)
        if (dof.law)
            dof.law->commit();
    m_committedTime = m_time;
    m_committedUe = m_ue;
    return ElementStatus::success();
}

void Link2dElement::revert()
{
    m_time = m_committedTime;
    m_ue = m_committedUe;
    for (int i = 0; i < 3; ++i)
        if (HysteresisLaw* law = m_dofs[i].law.get()) {
            law->revert();
            m_d[i] = law->committedDeformation();
            m_q[i] = law->committedForce();
        } else {
            m_q[i] = heldForce(i);
        }
}

void Link2dElement::addNodalForces(Eigen::VectorXd& rFull) const
{
    m_kin.addNodalForces(m_ue, m_q, rFull); // eq. L2 or L4
}

Link2dMatrix66 Link2dElement::tangentStiffness() const
{
    Eigen::Matrix3d kb = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 3; ++i)
        if (m_dofs[i].law)
            kb(i, i) = m_dofs[i].law->trialTangent();
    return m_kin.tangent(m_ue, kb, m_q);
}

void Link2dElement::addInitialStiffness(std::vector<Eigen::Triplet<double>>& k,
                                        const std::vector<int>& freeOf) const
{
    Eigen::Matrix3d kb = Eigen::Matrix3d::Zero();
    for (int i = 0; i < 3; ++i)
        if (m_dofs[i].law)
            kb(i, i) = m_dofs[i].law->initialTangent();
    if (!m_kin.corotational()) {
        m_kin.addStiffness(kb, k, freeOf);
        return;
    }
    // the tangent at rest: the laws' forces are 0 there, the held ones act (eq. L5)
    Eigen::Vector3d q0 = Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i)
        if (!m_dofs[i].law)
            q0[i] = scheduledForce(m_dofs[i].forceSchedule, m_dofs[i].heldForce, 0.0);
    m_kin.addMatrix(m_kin.tangent(Link2dVector6::Zero(), kb, q0), k, freeOf);
}

} // namespace hsmu
