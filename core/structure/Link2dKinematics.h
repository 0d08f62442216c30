#pragma once
// Link2dKinematics: the basic system of a two-node 2D link / beam-column (docs/setups.md,
// "Multi-DOF elements"). Node i and node j carry 3 DOFs each (x, y translation [m],
// rotation [rad], counter-clockwise positive); a DOF index < 0 is a support (always zero).
// The element points from i to j at angle phi from the global x axis, length L [m].
//
// Basic displacements d = (axial, shear, rotation), the cantilever system fixed at node i
// (OpenFresco's twoNodeLink order: axial along the element, shear across it):
//   du = u_j - u_i (translations), c = cos phi, s = sin phi
//   d_axial = c du_x + s du_y
//   d_shear = -s du_x + c du_y - L theta_i
//   d_rot   = theta_j - theta_i                                                  (eq. L1)
// i.e. d = A u_e with A constant (3 x 6, small displacements); rigid-body motions give d = 0.
// Basic forces q (axial [N], shear [N], moment [N m]) act on node j; by virtual work the nodal
// forces are A^T q and the stiffness A^T Kb A (eq. L2).

#include "core/structure/Element.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <string>
#include <vector>

namespace hsmu {

/// The name of basic DOF k (0 "axial", 1 "shear", 2 "rotation"); "" outside 0..2.
const char* link2dBasicDofName(int k);
/// Basic DOF k's deformation unit ("m", "m", "rad") and force unit ("kN", "kN", "kN m") in
/// the presets' units; "" outside 0..2.
const char* link2dBasicDeformationUnit(int k);
const char* link2dBasicForceUnit(int k);
/// The index of a basic DOF's name ("axial", "shear", "rotation"); -1 for any other text.
int link2dBasicDofIndex(const std::string& name);

struct Link2dGeometry {
    /// Full-DOF indices: (x_i, y_i, theta_i, x_j, y_j, theta_j); < 0: a support.
    std::array<int, 6> dofs{-1, -1, -1, -1, -1, -1};
    double length = 0.0;   ///< L [m], > 0
    double angleDeg = 90.0; ///< phi [deg] of i -> j from the global x axis (90: a column)
};

class Link2dKinematics {
public:
    /// Throws std::invalid_argument naming the element when L is not finite and > 0, the angle
    /// is not finite, or a DOF repeats.
    Link2dKinematics(const std::string& element, const Link2dGeometry& g);

    const Link2dGeometry& geometry() const { return m_g; }
    /// A (3 x 6) of eq. L1.
    const Eigen::Matrix<double, 3, 6>& matrix() const { return m_a; }
    /// d = A u_e at full-DOF displacements u (eq. L1).
    Eigen::Vector3d basic(const Eigen::VectorXd& uFull) const;
    /// rFull += A^T q (eq. L2).
    void addNodalForces(const Eigen::Vector3d& q, Eigen::VectorXd& rFull) const;
    /// Triplets of A^T Kb A over the free DOFs (supports skipped) (eq. L2).
    void addStiffness(const Eigen::Matrix3d& kb, std::vector<Eigen::Triplet<double>>& k,
                      const std::vector<int>& freeOf) const;
    /// DofTerms of basic row `row` (for Structure's DOF checks and Element::terms()).
    std::vector<DofTerm> terms(int row) const;

private:
    Link2dGeometry m_g;
    Eigen::Matrix<double, 3, 6> m_a;
};

} // namespace hsmu
