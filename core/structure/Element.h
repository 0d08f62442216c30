#pragma once
// Element: one member of the structural model, numerical or experimental.
//
// An element sees the structure through DofTerms: its generalized deformation is
// q = sum_k c_k u[dof_k] (full-DOF indices), and a generalized force P puts c_k P on DOF k.
// Examples: lateral spring q = u_i (c = 1); rotational base spring under a rigid column of
// height L, q = theta = u_i / L (c = 1/L, P = moment); truss q = u_j - u_i.
//
// Trial / commit / revert like a hysteresis law: setTrial() never changes committed state.

#include "core/hysteresis/HysteresisLaw.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

namespace hsmu {

struct DofTerm {
    int dof = 0;              ///< full-DOF index
    double coefficient = 1.0; ///< dq/du_dof
};

/// Outcome of an element evaluation; message says why when !ok, limit tells a safety limit
/// (nothing past it was sent) from any other fault.
struct ElementStatus {
    bool ok = true;
    std::string message;
    bool limit = false;
    static ElementStatus success() { return {}; }
    static ElementStatus failure(std::string why) { return {false, std::move(why), false}; }
    static ElementStatus limitReached(std::string why) { return {false, std::move(why), true}; }
};

class Element {
public:
    explicit Element(std::string name, std::vector<DofTerm> terms);
    virtual ~Element() = default;
    Element(const Element&) = delete;
    Element& operator=(const Element&) = delete;

    const std::string& name() const { return m_name; }
    const std::vector<DofTerm>& terms() const { return m_terms; }
    /// Configuration type name, e.g. "lateralSpring".
    virtual std::string typeName() const = 0;
    virtual bool isExperimental() const { return false; }

    /// Generalized deformation q = sum c_k u[dof_k] for full-DOF displacements u.
    double kinematicDeformation(const Eigen::VectorXd& uFull) const;

    /// Evaluate at full-DOF displacements u from the committed state.
    virtual ElementStatus setTrial(const Eigen::VectorXd& uFull) = 0;
    /// Two-phase trial (sites, docs/configuration.md): issue the trial at u without waiting
    /// for its response; the next setTrial(u) completes it. Structure::setTrial sends every
    /// experimental element's trial before it awaits any, so that a step costs the slowest
    /// site's round trip, not the sum. Default: nothing to send (setTrial does everything).
    virtual ElementStatus sendTrial(const Eigen::VectorXd& /*uFull*/) { return ElementStatus::success(); }
    /// Two-phase commit: send the commit without waiting; the next commit() completes it.
    virtual ElementStatus beginCommit() { return ElementStatus::success(); }
    /// Whether the element's force depends on test time (a scheduled force: Link2dElement's
    /// held basic forces, ForceSchedule.h); the stepping loop then tells it the time first.
    virtual bool timeDependent() const { return false; }
    /// The test time [s] of the step whose trial comes next (HybridTest calls it before that
    /// step's targets are checked and its trial set): a scheduled force is taken at it.
    virtual void setTargetTime(double /*time*/) {}
    /// The site (lab, controller) answering for the element; "" for a numerical element.
    virtual std::string site() const { return {}; }
    /// Deformation of the element's own law (rotation, displacement) at the trial state.
    virtual double deformation() const = 0;
    /// Force of the element's own law (moment, force) at the trial state.
    virtual double force() const = 0;
    /// Generalized force P conjugate to q (equals force() unless the element is compound).
    virtual double generalizedForce() const { return force(); }
    /// Tangent dP/dq of the virgin element (for the initial stiffness matrix).
    virtual double initialGeneralizedStiffness() const = 0;

    virtual ElementStatus commit() = 0;
    virtual void revert() = 0;

    /// The law an updating scheme may change; nullptr if none (e.g. experimental).
    virtual HysteresisLaw* law() { return nullptr; }
    virtual const HysteresisLaw* law() const { return nullptr; }
    /// Swap the law law() returns with `law` (not null; the old law comes back in it), between
    /// steps: an operator-approved change of the law's form (an OffsetLaw around it,
    /// ModelUpdater::approveOffsets). The element's committed state is the new law's from the
    /// next trial on. False (nothing swapped) if the element has no law to change.
    virtual bool swapLaw(std::unique_ptr<HysteresisLaw>& /*law*/) { return false; }

    /// Basic DOFs (docs/setups.md, "Multi-DOF elements"): 1 for a one-DOF element, whose one
    /// law is law(); 3 for a link2d (0 axial, 1 shear, 2 rotation).
    virtual int basicDofCount() const { return 1; }
    /// The law carried by basic DOF k (0 <= k < basicDofCount()); nullptr if that DOF has
    /// none (a held force, a free DOF, an experimental element). One-DOF: law() for k = 0.
    virtual HysteresisLaw* basicLaw(int k) { return k == 0 ? law() : nullptr; }
    /// swapLaw() for basic DOF k's law. One-DOF: swapLaw() for k = 0.
    virtual bool swapBasicLaw(int k, std::unique_ptr<HysteresisLaw>& law)
    {
        return k == 0 && swapLaw(law);
    }

    /// Add c_k P to R[dof_k] (full DOFs). A multi-DOF element (Link2d, ExperimentalLink2d)
    /// adds A^T q instead, q its basic forces (docs/setups.md, "Multi-DOF elements", eq. L1-L2).
    virtual void addNodalForces(Eigen::VectorXd& rFull) const;
    /// Append c c^T k0 as triplets over the free DOFs (row freeOf[dof_a], column
    /// freeOf[dof_b]); Eigen sums duplicates when the sparse matrix is built. A multi-DOF
    /// element appends A^T Kb0 A.
    virtual void addInitialStiffness(std::vector<Eigen::Triplet<double>>& k,
                                     const std::vector<int>& freeOf) const;

private:
    std::string m_name;
    std::vector<DofTerm> m_terms;
};

} // namespace hsmu
