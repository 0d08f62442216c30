#pragma once
// PlanarActuatorSetup: the 2D family of OpenFresco's multi-actuator setups (TwoActuators2d,
// ThreeActuators2d, ThreeActuatorsJntOff2d, InvertedVBrace2d, InvertedVBraceJntOff2d,
// ChevronBrace2d). A rigid loading beam (platform) carries the element's control point; each
// actuator is a straight pin-ended link from a fixed base point to an attachment point on the
// platform (docs/setups.md, "The planar family").
//
// Basic DOFs d = (u, v, theta): the control point's displacement along local x and y [m] and
// the platform's rotation [rad], counter-clockwise positive. With phiLocX (OpenFresco's
// -phiLocX, [deg]) the element's (u, v) are first rotated into the setup's frame:
// (u, v)_setup = R(phiLocX) (u, v)_element.
// Actuator i: attachment a_i and base b_i in the setup frame at rest, relative to the control
// point [m]; rest length La_i = |a_i - b_i|; unit rest direction e_i = (a_i - b_i) / La_i.
//   exact (-nlGeom):  s_i = |(u, v) + R(theta) a_i - b_i| - La_i                  (eq. S1)
//   linear:           s_i = e_i . (u - theta a_iy, v + theta a_ix)                 (eq. S1L)
// Jacobian row i (exact): [n_x, n_y, n . R'(theta) a_i], n the current unit direction (eq. S2);
// linear: the exact row at d = 0. Forces q = J^T f (ExperimentalSetup.h, eq. S3).
// Measured displacements: the linear formulation solves J0_c d_c = s - J0_g d_g; the exact one
// runs Newton on s(d) = s from the given (trial) displacements, and from the linear solution
// when that fails, to |residual| <= 1e-13 max La (eq. S4).
// Singular geometry (actuators that cannot fix the controlled DOFs, e.g. parallel and
// coincident) is refused by the setups' create() at configuration time, and at run time by
// strokes()/basicDisplacements() with a SetupResult naming the setup.

#include "core/experimental/setup/ExperimentalSetup.h"

#include <vector>

namespace hsmu {

struct PlanarActuator {
    Eigen::Vector2d attach; ///< [m] attachment on the platform, setup frame, from the control point
    Eigen::Vector2d base;   ///< [m] fixed end, same frame
};

enum class SetupGeometry {
    Linear, ///< small displacements (OpenFresco's default)
    Exact   ///< large displacements, exact geometry (OpenFresco's -nlGeom)
};

class PlanarActuatorSetup : public ExperimentalSetup {
public:
    /// controlledDofs: the basic DOFs the actuators fix (size == actuators.size(), indices into
    /// (u, v, theta)); the others are taken as given by basicDisplacements().
    /// Preconditions (checked by the setups' create()): |a_i - b_i| > 0; the controlled
    /// columns of J0 have full rank.
    PlanarActuatorSetup(std::string typeName, std::vector<PlanarActuator> actuators,
                        SetupGeometry geometry, double phiLocXDeg, std::vector<int> controlledDofs);

    std::string typeName() const override { return m_typeName; }
    int basicSize() const override { return 3; }
    int actuatorCount() const override { return static_cast<int>(m_actuators.size()); }
    SetupGeometry geometry() const { return m_geometry; }
    const std::vector<PlanarActuator>& actuators() const { return m_actuators; }
    /// R(phiLocX): (u, v)_setup = R (u, v)_element (the drawing of core/experimental/SetupSketch).
    Eigen::Matrix2d elementToSetup() const {
        Eigen::Matrix2d r;
        r << m_cphi, -m_sphi, m_sphi, m_cphi;
        return r;
    }

    SetupResult strokes(const Eigen::VectorXd& d, Eigen::VectorXd& s) const override;
    SetupResult jacobian(const Eigen::VectorXd& d, Eigen::MatrixXd& J) const override;
    SetupResult basicDisplacements(const Eigen::VectorXd& s, const Eigen::VectorXd& given,
                                   Eigen::VectorXd& d) const override;
    /// q = J(d)^T f without heap allocation (the measured path runs every step).
    SetupResult basicForces(const Eigen::VectorXd& d, const Eigen::VectorXd& f,
                            Eigen::VectorXd& q) const override;
    /// Closed form of eq. S5: with r = (u, v) + R(theta) a - b, n = r / |r|,
    /// sdot = n . rdot, sddot = n . rddot + (|rdot|^2 - (n . rdot)^2) / |r|; linear: J0 v, J0 a.
    SetupResult actuatorRates(const Eigen::VectorXd& d, const Eigen::VectorXd& v,
                              const Eigen::VectorXd& a, Eigen::VectorXd& sv,
                              Eigen::VectorXd& sa) const override;

    /// "" when the controlled DOFs are fixed by the actuators at rest, else why not (used by
    /// the setups' create() after their own parameter checks).
    std::string restSingularity() const;

private:
    // at most 3 actuators (one per basic DOF): fixed-capacity matrices, no heap
    using Rows = Eigen::Matrix<double, Eigen::Dynamic, 3, 0, 3, 3>;
    using Square = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
    using Small = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;

    Eigen::Vector3d toSetupFrame(const Eigen::VectorXd& d) const;
    Eigen::Vector3d toElementFrame(const Eigen::Vector3d& dl) const;
    struct Pose {
        double u, v, theta, c, s; ///< setup frame; c, s of theta (exact) or 1, 0 (linear)
    };
    Pose pose(const Eigen::Vector3d& dl) const;
    bool stroke(int i, const Pose& p, double& s) const;  // false: zero length (exact)
    bool rowAt(int i, const Pose& p, double* row) const; // exact row of S2; false: zero length
    SetupResult jacobianLocal(const Eigen::Vector3d& dl, Rows& J) const;
    Square controlledColumns(const Rows& J) const;
    SetupResult solveControlled(const Rows& J, const Small& rhs, Small& x) const;
    /// S4's Newton iteration from dl (setup frame) on the controlled DOFs.
    SetupResult newton(const Eigen::VectorXd& s, Eigen::Vector3d& dl) const;
    static std::string singularity(const Eigen::MatrixXd& Jc);
    /// |det| of Jc with unit columns: 1 for orthogonal columns, 0 when singular (square Jc).
    static double normalizedVolume(const Square& Jc);

    std::string m_typeName;
    std::vector<PlanarActuator> m_actuators;
    std::vector<double> m_La;
    SetupGeometry m_geometry;
    double m_cphi = 1.0, m_sphi = 0.0;
    std::vector<int> m_controlled, m_given;
    Rows m_J0; // the Jacobian at rest (S1L), setup frame
};

/// Parses OpenFresco's actuator position word ("left"/"l", "right"/"r"); false otherwise.
bool parseActuatorSide(const std::string& word, bool& right);

} // namespace hsmu
