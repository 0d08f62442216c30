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
//
// Corotational geometry (large displacements; "geometry": "corotational"): with the current
// chord Dl = L e0 + du (e0 = (c, s)), its length Ln = |Dl| and its angle beta_i measured from
// node i's turned axis R(theta_i) e0 (beta_i = atan2(e_i x Dl, e_i . Dl), in (-pi, pi]):
//   d_axial = Ln - L                      (chord elongation)
//   d_shear = L beta_i                    (L times the chord's rotation relative to node i,
//                                          the sign of L1: -L (theta_i - chord angle))
//   d_rot   = theta_j - theta_i                                                  (eq. L3)
// exact for any rigid-body motion (d = 0 to rounding whatever the rotation) and L1 to first
// order. B = dd/du_e (3 x 6), e = Dl / Ln, n = (-e_y, e_x):
//   row axial = (-e, 0, e, 0), row shear = (-L n / Ln, -L, L n / Ln, 0), row rot = (0,0,-1,0,0,1)
// nodal forces B^T q (eq. L4) and the tangent (eq. L5)
//   K = B^T Kb B + q_a G(n n^T / Ln) - q_s L G((e n^T + n e^T) / Ln^2),
//   G(H) = [[H, -H], [-H, H]] on the translations (x_i, y_i, x_j, y_j).
// At rest B = A, so K0 = A^T Kb0 A + the geometric terms of the forces held at rest.

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

/// Small displacements (eq. L1-L2) or exact large displacements (eq. L3-L5). Linear is 0: a
/// value-initialized one (TestConfig.h declares the type without its enumerators) is linear.
enum class Link2dTransformation { Linear = 0, Corotational };

/// "linear" / "corotational" (the configuration's "geometry").
const char* link2dTransformationName(Link2dTransformation t);
/// The transformation named `name`; false for any other text.
bool link2dTransformationFromName(const std::string& name, Link2dTransformation& t);

struct Link2dGeometry {
    /// Full-DOF indices: (x_i, y_i, theta_i, x_j, y_j, theta_j); < 0: a support.
    std::array<int, 6> dofs{-1, -1, -1, -1, -1, -1};
    double length = 0.0;   ///< L [m], > 0
    double angleDeg = 90.0; ///< phi [deg] of i -> j from the global x axis (90: a column)
    Link2dTransformation transformation = Link2dTransformation::Linear;
};

using Link2dVector6 = Eigen::Matrix<double, 6, 1>;
using Link2dMatrix36 = Eigen::Matrix<double, 3, 6>;
using Link2dMatrix66 = Eigen::Matrix<double, 6, 6>;

class Link2dKinematics {
public:
    /// Throws std::invalid_argument naming the element when L is not finite and > 0, the angle
    /// is not finite, or a DOF repeats.
    Link2dKinematics(const std::string& element, const Link2dGeometry& g);

    const Link2dGeometry& geometry() const { return m_g; }
    bool corotational() const
    {
        return m_g.transformation == Link2dTransformation::Corotational;
    }
    /// A (3 x 6) of eq. L1.
    const Eigen::Matrix<double, 3, 6>& matrix() const { return m_a; }
    /// The element's six displacements u_e at full-DOF displacements u (0 at a support).
    Link2dVector6 local(const Eigen::VectorXd& uFull) const;
    /// d at full-DOF displacements u: A u_e (eq. L1) or eq. L3. NaN (corotational) when the
    /// chord collapses (chordFault() says so).
    Eigen::Vector3d basic(const Eigen::VectorXd& uFull) const;
    /// d at u_e (eq. L1 or L3; NaN when the chord collapses).
    Eigen::Vector3d basicAt(const Link2dVector6& ue) const;
    /// Why u_e cannot be evaluated (corotational: the chord shorter than 1e-9 L), or "".
    std::string chordFault(const Link2dVector6& ue) const;
    /// B = dd/du_e at u_e: A (linear) or eq. L3's B.
    Link2dMatrix36 transformationAt(const Link2dVector6& ue) const;
    /// The geometric stiffness sum_k q_k d^2 d_k / du_e^2 (eq. L5; 0 when linear).
    Link2dMatrix66 geometricStiffness(const Link2dVector6& ue, const Eigen::Vector3d& q) const;
    /// K = B^T Kb B + geometricStiffness(u_e, q) (eq. L2 / L5), the element's 6 x 6 tangent.
    Link2dMatrix66 tangent(const Link2dVector6& ue, const Eigen::Matrix3d& kb,
                           const Eigen::Vector3d& q) const;
    /// rFull += A^T q (eq. L2).
    void addNodalForces(const Eigen::Vector3d& q, Eigen::VectorXd& rFull) const;
    /// rFull += B(u_e)^T q (eq. L2 or L4).
    void addNodalForces(const Link2dVector6& ue, const Eigen::Vector3d& q,
                        Eigen::VectorXd& rFull) const;
    /// Triplets of A^T Kb A over the free DOFs (supports skipped) (eq. L2).
    void addStiffness(const Eigen::Matrix3d& kb, std::vector<Eigen::Triplet<double>>& k,
                      const std::vector<int>& freeOf) const;
    /// Triplets of a 6 x 6 element matrix over the free DOFs (supports skipped).
    void addMatrix(const Link2dMatrix66& ke, std::vector<Eigen::Triplet<double>>& k,
                   const std::vector<int>& freeOf) const;
    /// DofTerms of basic row `row` (for Structure's DOF checks and Element::terms()).
    std::vector<DofTerm> terms(int row) const;

private:
    /// The chord Dl, its unit vector e, length Ln, and beta_i of eq. L3.
    struct Chord {
        Eigen::Vector2d e;
        double length, beta;
    };
    Chord chord(const Link2dVector6& ue) const;

    Link2dGeometry m_g;
    Eigen::Matrix<double, 3, 6> m_a;
};

} // namespace hsmu
