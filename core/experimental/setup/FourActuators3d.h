#pragma once
// FourActuators3d: a column top driven by four horizontal actuators on two levels
// (docs/setups.md, "FourActuators3d"), OpenFresco's
//   `expSetup FourActuators3d $tag $L1 $L2 $L3 $L4 $a1 $a2 $a3 $a4 $h $h1 $h2 $arlN $arlS
//    $LrodN $LrodS $Hbeam <-nlGeom> <-phiLocX $deg>`
// Lengths [m], phiLocX [deg].
//
// Geometry (setup frame, origin at the control point on the lower actuator level, z up):
// actuator 1 along x at (-a1, 0, 0), actuator 2 along y at (0, -a2, 0), actuator 3 along x at
// (-a3, 0, h), actuator 4 along y at (0, -a4, h); their bases L1..L4 beyond the attachments
// (at rest: (-a1 - L1, 0, 0), (0, -a2 - L2, 0), (-a3 - L3, 0, h), (0, -a4 - L4, h)).
// The actuators fix the platform's translations (ux, uy) and its rotation vector (phix, phiy, 0)
// (no vertical translation, no twist).
// Basic DOFs: OpenFresco's six, with its mapping D = (ux, uy, phix, phiy) =
// (-d(1), -d(3), -d(4), -d(2)) (0-based), then (ux, uy) and (phix, phiy) each turned by
// [[c, s], [-s, c]], c, s of phiLocX; d(0) and d(5) carry no actuator (given when measured).
//   exact (-nlGeom):  s_i = |(ux, uy, 0) + R(phix, phiy, 0) a_i - b_i| - L_i, R by Rodrigues'
//                     formula from the rotation vector (OpenFresco's A B C product is the same
//                     rotation, checked to 1e-16 in docs/setups.md)
//   linear:           s_i = e_i . (u + phi x a_i)   (OpenFresco has no linear version)
// Jacobian: ds_i/d(Ra) = n_i; d(R a)/dphi = -R [a]x J_r(phi) (J_r the right Jacobian of SO(3)).
//
// Axial-load rods (docs/setups.md, "FourActuators3d", eqs. S6-S9): two rods, north and south,
// each a straight pin-ended link from a floor anchor to a pin on the platform on the column
// axis at height h1, LrodN / LrodS long (pin to pin), vertical at rest: anchor k at
// (0, 0, h1 - Lrod_k). Their forces come from two load cells (OpenFresco's daq forces 1 and 2)
// and enter the basic forces by virtual work like the actuators', q += Jrod^T frod (eq. S7),
// with Jrod = d(rod length)/dd: the axial load in d(0) and, through the rods' inclination under
// the platform's motion, their P-Delta in the lateral forces and moments. The rods see the
// platform's vertical translation uz = d(0) (the actuators do not: their strokes are OpenFresco's,
// eq. S1). Linear formulation: the rods' length to second order in d (eq. S8), so the P-Delta
// stays, linear in d. h2, arlN, arlS and Hbeam are OpenFresco's (its rods' force in the y-z plane
// follows the spreader beam); kept for a script's numbers, not used (docs/setups.md).
// Force sign: as the actuators' (ExperimentalSetup.h), positive when it does positive work on a
// lengthening rod, so a rod in tension T that pulls the platform down reads -T.

#include "core/experimental/setup/ExperimentalSetup.h"
#include "core/experimental/setup/PlanarActuatorSetup.h"

#include <array>
#include <memory>

namespace hsmu {

struct FourActuators3dParams {
    double L1 = 0, L2 = 0, L3 = 0, L4 = 0; ///< actuator lengths at rest [m]
    double a1 = 0, a2 = 0, a3 = 0, a4 = 0; ///< attachment offsets from the column axis [m]
    double h = 0;                          ///< height of the upper actuator level [m]
    double h1 = 0; ///< height of the rods' top pins above the lower level [m]
    double h2 = 0, arlN = 0, arlS = 0, Hbeam = 0; ///< OpenFresco's, unused here [m]
    double LrodN = 0, LrodS = 0;                  ///< the rods' pin-to-pin lengths [m]
    SetupGeometry geometry = SetupGeometry::Linear;
    double phiLocX = 0.0; ///< [deg]
};

class FourActuators3d : public ExperimentalSetup {
public:
    /// nullptr with error naming the parameter: L1..L4, LrodN, LrodS <= 0 or not finite, a1..a4,
    /// h, h1, h2, arlN, arlS, Hbeam not finite, h = 0 (both levels at one height: the rotations
    /// cannot be controlled).
    static std::unique_ptr<FourActuators3d> create(const FourActuators3dParams& p,
                                                   std::string& error);

    std::string typeName() const override { return "FourActuators3d"; }
    int basicSize() const override { return 6; }
    int actuatorCount() const override { return 4; }
    SetupResult strokes(const Eigen::VectorXd& d, Eigen::VectorXd& s) const override;
    SetupResult jacobian(const Eigen::VectorXd& d, Eigen::MatrixXd& J) const override;
    SetupResult basicDisplacements(const Eigen::VectorXd& s, const Eigen::VectorXd& given,
                                   Eigen::VectorXd& d) const override;
    /// f: the 4 actuator forces (rods unloaded), or OpenFresco's 6 daq forces (fN, fS, f1..f4):
    /// q = J^T f_act + Jrod^T (fN, fS) (eqs. S3, S7) [N, N m].
    SetupResult basicForces(const Eigen::VectorXd& d, const Eigen::VectorXd& f,
                            Eigen::VectorXd& q) const override;
    /// Load cells besides the actuators: the two rods.
    int loadCellCount() const override { return 2; }

    /// The rods' lengths (north, south) at d [m] (eq. S6; linear: S8).
    SetupResult rodLengths(const Eigen::VectorXd& d, Eigen::Vector2d& lengths) const;
    /// d(rod length)/dd (2 x 6) at d (eq. S6's gradient; linear: S8's).
    SetupResult rodJacobian(const Eigen::VectorXd& d, Eigen::MatrixXd& Jrod) const;

private:
    using Mat4x6 = Eigen::Matrix<double, 4, 6>;
    explicit FourActuators3d(const FourActuators3dParams& p);
    Eigen::Vector4d internal(const Eigen::VectorXd& d) const { return m_T * d; }
    bool strokesInternal(const Eigen::Vector4d& x, Eigen::Vector4d& s) const;
    bool jacobianInternal(const Eigen::Vector4d& x, Eigen::Matrix4d& J) const;
    using Vec5 = Eigen::Matrix<double, 5, 1>;
    // rods: internal (ux, uy, uz, phix, phiy) = T5 d
    void rodInternal(const Vec5& x, Eigen::Vector2d& len, Eigen::Matrix<double, 2, 5>& G) const;

    FourActuators3dParams m_p;
    std::array<Eigen::Vector3d, 4> m_attach, m_base;
    std::array<double, 4> m_La;
    Mat4x6 m_T;                       // internal (ux, uy, phix, phiy) = T d
    Eigen::Matrix<double, 5, 6> m_T5; // rods' internal (ux, uy, uz, phix, phiy) = T5 d
};

} // namespace hsmu
