#pragma once
// Link2dElement: a numerical two-node 2D link / beam-column with 3 basic DOFs (axial, shear,
// rotation; Link2dKinematics.h, eq. L1-L2), each carried by its own hysteresis law, or by a
// held basic force (e.g. a constant axial load: q = P whatever d, no stiffness; or a force
// following a schedule of test time, ForceSchedule.h eq. F1, like the specimen's
// force-controlled actuator), or by nothing (q = 0). The all-numerical twin of an ExperimentalLink2d (docs/setups.md,
// "Multi-DOF elements"). Units: basic forces [kN], [kN m] with deformations [m], [rad].
// deformation() / force() report the primary basic DOF (the record's one column per element).
// Geometry: linear (eq. L1-L2, the default) or corotational (Link2dGeometry::transformation,
// eq. L3-L5: exact large displacements; the nodal forces B(u)^T q, K0 the tangent at rest,
// geometric stiffness of the forces held at t = 0 included).

#include "core/structure/ForceSchedule.h"
#include "core/structure/Link2dKinematics.h"

#include <array>
#include <memory>

namespace hsmu {

struct Link2dBasicDof {
    std::unique_ptr<HysteresisLaw> law; ///< nullptr: the held force below
    double heldForce = 0.0;             ///< q when law is nullptr (0: a free DOF)
    ForceSchedule forceSchedule;        ///< q(t) instead of heldForce when not empty
};

class Link2dElement final : public Element {
public:
    /// primary: the basic DOF (0 axial, 1 shear, 2 rotation) deformation() reports; it must
    /// carry a law. Throws std::invalid_argument naming the element otherwise.
    Link2dElement(std::string name, const Link2dGeometry& geometry,
                  std::array<Link2dBasicDof, 3> dofs, int primary = 1);

    std::string typeName() const override { return "link2d"; }
    bool timeDependent() const override;
    void setTargetTime(double time) override { m_time = time; }
    ElementStatus setTrial(const Eigen::VectorXd& uFull) override;
    double deformation() const override { return m_d[m_primary]; }
    double force() const override { return m_q[m_primary]; }
    double initialGeneralizedStiffness() const override;
    ElementStatus commit() override;
    void revert() override;
    HysteresisLaw* law() override { return m_dofs[m_primary].law.get(); }
    const HysteresisLaw* law() const override { return m_dofs[m_primary].law.get(); }
    bool swapLaw(std::unique_ptr<HysteresisLaw>& law) override
    {
        return swapBasicLaw(m_primary, law);
    }
    int basicDofCount() const override { return 3; }
    HysteresisLaw* basicLaw(int k) override
    {
        return k >= 0 && k < 3 ? m_dofs[std::size_t(k)].law.get() : nullptr;
    }
    /// Only a DOF that carries a law takes another (a held force stays one).
    bool swapBasicLaw(int k, std::unique_ptr<HysteresisLaw>& law) override
    {
        if (!law || !basicLaw(k))
            return false;
        m_dofs[std::size_t(k)].law.swap(law);
        return true;
    }

    void addNodalForces(Eigen::VectorXd& rFull) const override;
    void addInitialStiffness(std::vector<Eigen::Triplet<double>>& k,
                             const std::vector<int>& freeOf) const override;

    /// The element's 6 x 6 tangent at the trial state (eq. L2 / L5): B^T Kb B with the laws'
    /// trial tangents (0 on a held or free DOF), plus the geometric stiffness of q.
    Link2dMatrix66 tangentStiffness() const;
    const Eigen::Vector3d& basicDeformations() const { return m_d; } ///< trial d
    const Eigen::Vector3d& basicForces() const { return m_q; }       ///< trial q
    const Link2dKinematics& kinematics() const { return m_kin; }

private:
    double heldForce(int i) const; // [kN] or [kN m] of a DOF without a law, at m_time

    Link2dKinematics m_kin;
    std::array<Link2dBasicDof, 3> m_dofs;
    int m_primary;
    double m_time = 0.0, m_committedTime = 0.0; // [s] of the trial / the committed state
    Eigen::Vector3d m_d = Eigen::Vector3d::Zero(), m_q = Eigen::Vector3d::Zero();
    Link2dVector6 m_ue = Link2dVector6::Zero(), m_committedUe = Link2dVector6::Zero(); // u_e
};

} // namespace hsmu
