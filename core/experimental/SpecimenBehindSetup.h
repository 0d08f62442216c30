#pragma once
// SpecimenBehindSetup: a specimen simulated as a whole in its basic system (CantileverColumn)
// behind an experimental setup, driven by its actuators (docs/setups.md, "The specimen as a
// whole"). Given each channel's achieved command a (a stroke [m] on a displacement-controlled
// channel, a force [kN] on a force-controlled one) it finds the basic displacements d (3) and
// the actuator forces f (m) with (eq. W4)
//   s_i(d) = a_i          (displacement channel i, eq. S1)
//   f_i    = a_i          (force channel i)
//   q(d)   = J(d)^T f     (the specimen's basic forces balance the actuators', eq. S3; a basic
//                          DOF no actuator acts on is free: q_k = 0 there)
// by Newton on x = (d, f) from the committed state, the Jacobian [[J_c, 0], [0, I_f],
// [K - G, -J^T]] with G = d(J^T f)/dd by central differences (h = 1e-7; 0 for a linear setup)
// and K the specimen's tangent, to |s_i - a_i| <= 1e-15 + 1e-12 |a_i| m,
// |f_i - a_i| <= 1e-12 max(1, |a_i|) kN and |q - J^T f| <= 1e-12 max(1, |q|) per row (once the
// residual stops falling: 1e-12 max(1, |q|_inf, |f|_inf), the round-off floor of a small shear
// beside a large axial force), at most 50 iterations; else a fault naming the setup. The measured strokes are s(d), the forces f.
// Units: the setup's (m, rad) and the specimen's (kN, kN m).

#include "core/experimental/ActuatorChannel.h"
#include "core/experimental/CantileverColumn.h"
#include "core/experimental/setup/ExperimentalSetup.h"

#include <memory>
#include <vector>

namespace hsmu {

class SpecimenBehindSetup {
public:
    /// Throws std::invalid_argument: a null part, a setup not of 3 basic DOFs, a mode per
    /// actuator missing.
    SpecimenBehindSetup(std::unique_ptr<ExperimentalSetup> setup,
                        std::unique_ptr<CantileverColumn> specimen,
                        std::vector<ActuatorMode> modes);

    int actuatorCount() const { return static_cast<int>(m_modes.size()); }
    void setTimeIncrement(double dt) { m_specimen->setTimeIncrement(dt); }
    /// Solve eq. W4 for the achieved commands a; "" or why not (nothing changes then).
    std::string solve(const Eigen::VectorXd& a);
    const Eigen::VectorXd& strokes() const { return m_s; }            ///< trial [m]
    const Eigen::VectorXd& forces() const { return m_f; }             ///< trial [kN]
    const Eigen::Vector3d& basicDisplacements() const { return m_d; } ///< trial d
    double committedStroke(int i) const { return m_cs[i]; }
    double committedForce(int i) const { return m_cf[i]; }
    /// The stiffness actuator i sees pushing alone, the others force-free: 1 / (J K^-1 J^T)_ii
    /// [kN/m] (K initial or at the trial; 0 when K is singular).
    double channelStiffness(int i, bool initial) const;
    const CantileverColumn& specimen() const { return *m_specimen; }
    const ExperimentalSetup& setup() const { return *m_setup; }
    void commit();
    void revert();
    std::string description() const;

private:
    std::unique_ptr<ExperimentalSetup> m_setup;
    std::unique_ptr<CantileverColumn> m_specimen;
    std::vector<ActuatorMode> m_modes;
    Eigen::Vector3d m_d = Eigen::Vector3d::Zero(), m_cd = Eigen::Vector3d::Zero();
    Eigen::VectorXd m_s, m_f, m_cs, m_cf;
};

} // namespace hsmu
