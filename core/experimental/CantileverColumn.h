#pragma once
// CantileverColumn: a column specimen simulated as a whole in its basic system (docs/setups.md,
// "The specimen as a whole"), the cantilever system of a link2d element fixed at node i
// (eq. L1): basic displacements d = (d_a axial [m], D lateral [m], phi top rotation [rad]),
// basic forces q = (N [kN], V [kN], M [kN m]) at node j.
//   axial:   N = law_a(d_a)                                        (e.g. elastic EA / L)
//   hinge:   a moment-rotation law M_h(theta_h) at the base (Bouc-Wen, pinching, ...), with an
//            elastic column (EI [kN m^2], length L [m]) above it; the column's end deformations
//            D_e = D - L theta_h, phi_e = phi - theta_h give (eq. W1)
//              V_e = EI / L^3 (12 D_e - 6 L phi_e),  M = EI / L^3 (-6 L D_e + 4 L^2 phi_e),
//            and the hinge carries the column's base moment (eq. W2)
//              R(theta_h) = M_h(theta_h) - EI / L^2 (6 D_e - 2 L phi_e) = 0,
//            solved by Newton from the committed theta_h (dR/dtheta_h = k_h + 4 EI / L), to
//            |R| <= 1e-12 max(1, |M_h|) kN m, at most 50 iterations;
//   P-Delta: the axial force at the displaced top adds N D / L to the shear (eq. W3,
//            OpenSees' PDelta transformation in the basic system): V = V_e + N D / L.
// So with an elastic hinge k_h and a free top (M = 0) under a compression P = -N the lateral
// stiffness is k - P / L, k = 1 / (L^2 / k_h + L^3 / (3 EI)).
// Tangent (consistent): dtheta_h/d(D, phi) = EI / L^2 (6, -2 L) / (k_h + 4 EI / L).
// Trials start from the committed state (the laws' own rule); commit() / revert() as a law's.

#include "core/hysteresis/HysteresisLaw.h"

#include <Eigen/Dense>

#include <memory>
#include <string>

namespace hsmu {

class CantileverColumn {
public:
    /// Throws std::invalid_argument naming the parameter: a null law, L or EI not finite > 0.
    CantileverColumn(std::unique_ptr<HysteresisLaw> axial, std::unique_ptr<HysteresisLaw> hinge,
                     double length, double ei);

    void setTimeIncrement(double dt);
    /// q and K at d; "" or why not (the hinge's Newton, a law's refusal).
    std::string setTrial(const Eigen::Vector3d& d);
    const Eigen::Vector3d& trialForces() const { return m_q; }
    const Eigen::Matrix3d& trialTangent() const { return m_k; }
    /// The tangent at rest (initial tangents of both laws, N = 0).
    Eigen::Matrix3d initialTangent() const;
    double hingeRotation() const { return m_hinge->trialDeformation(); } ///< theta_h [rad]
    double hingeMoment() const { return m_hinge->trialForce(); }         ///< M_h [kN m]
    void commit();
    void revert();
    std::string description() const;

private:
    Eigen::Matrix3d tangent(double ka, double kh, double n, double lateral) const;
    std::unique_ptr<HysteresisLaw> m_axial, m_hinge;
    double m_l, m_ei;
    Eigen::Vector3d m_q = Eigen::Vector3d::Zero();
    Eigen::Matrix3d m_k = Eigen::Matrix3d::Zero();
};

} // namespace hsmu
