#pragma once
// ExperimentalLink2d: a multi-DOF experimental element (docs/setups.md, "Multi-DOF elements"):
// a two-node 2D link / beam-column with 3 basic DOFs (axial, shear, rotation; eq. L1 of
// core/structure/Link2dKinematics.h) between two nodes of 3 DOFs each, whose specimen is driven
// through an experimental setup (core/experimental/setup; OpenFresco's element -> setup ->
// control layers) by N actuator channels of one control (ExperimentalControl::setTargets).
//
// Per step: d = A u (L1); strokes s = S(d) (setup, eq. S1); each channel's command is its
// stroke (displacement control) or its held force (force control, constant or following its
// schedule at the target's test time, setTargetTime; ActuatorChannel.h eq. F1); every
// channel's limits are checked before any command leaves. The measured strokes s_m and forces
// f_m come back through the setup: d_m = S^-1(s_m) (the DOFs no actuator fixes taken from the
// trial d, eq. S4), q = J(d_m)^T f_m (eq. S3); the structure gets A^T q (eq. L2) and K0 gets
// A^T J0^T diag(k_c) J0 A, k_c the displacement channels' initial stiffness (force channels: 0).
// The setup's basic DOFs are the element's (axial, shear, rotation) in this order: a column
// (element at 90 deg) with a setup drawn in the lab's frame takes OpenFresco's -phiLocX, as in
// OpenFresco. The record's one column per element reports the primary basic DOF (commanded,
// measured deformation and basic force); basicDeformations()/basicForces()/actuator strokes
// and forces give all of them.
// Geometry (Link2dGeometry::transformation): linear (L1-L2) or corotational (eq. L3-L5 of
// Link2dKinematics.h): d from the exact chord, nodal forces B(u)^T q, K0 the tangent at rest
// (its geometric part from the force channels' loads at t = 0, q0 = J0^T f0); a collapsed chord
// holds the test before any command leaves.
// Faults: a setup whose basic size is not 3, a channel count different from the setup's
// actuators or the control's channels, a Jacobian at rest that fails: std::invalid_argument at
// construction naming the element, the setup and the count; a setup fault at run time (e.g. an
// actuator shrinking to zero length) holds the test naming the setup.

#include "core/experimental/ActuatorChannel.h"
#include "core/experimental/ExperimentalElement.h"
#include "core/experimental/setup/ExperimentalSetup.h"
#include "core/structure/Link2dKinematics.h"

#include <memory>
#include <vector>

namespace hsmu {

class ExperimentalLink2d final : public ExperimentalElement {
public:
    /// primary: the basic DOF the record's column reports (0 axial, 1 shear, 2 rotation).
    ExperimentalLink2d(std::string name, const Link2dGeometry& geometry,
                       std::unique_ptr<ExperimentalSetup> setup,
                       std::vector<ActuatorChannelSpec> channels,
                       std::unique_ptr<ExperimentalControl> control, int primary = 1);

    std::optional<std::string> targetViolation(const Eigen::VectorXd& uFull) const override;
    void setTargetTime(double time) override { m_targetTime = time; }
    ElementStatus sendTrial(const Eigen::VectorXd& uFull) override;
    ElementStatus setTrial(const Eigen::VectorXd& uFull) override;
    ElementStatus commit() override;
    void revert() override;
    double deformation() const override { return m_dMeas[m_primary]; }
    double force() const override { return m_q[m_primary]; }
    double initialGeneralizedStiffness() const override { return m_kb0(m_primary, m_primary); }
    void addNodalForces(Eigen::VectorXd& rFull) const override;
    void addInitialStiffness(std::vector<Eigen::Triplet<double>>& k,
                             const std::vector<int>& freeOf) const override;

    int basicDofCount() const override { return 3; }
    ControlMeasurement basicMeasurement(int k) const override { return {m_dMeas[k], m_q[k]}; }
    double commandedBasicDeformation(int k) const override { return m_dTrial[k]; }

    const ExperimentalSetup& setup() const { return *m_setup; }
    const std::vector<ActuatorChannelSpec>& channels() const { return m_channels; }
    const Eigen::Vector3d& commandedBasic() const { return m_dTrial; } ///< trial d [m, m, rad]
    const Eigen::VectorXd& basicDeformations() const { return m_dMeas; } ///< measured d
    const Eigen::VectorXd& basicForces() const { return m_q; }           ///< q [kN, kN, kN m]
    const Eigen::VectorXd& commands() const { return m_cmd; }   ///< per channel: stroke or force
    const Eigen::VectorXd& strokes() const { return m_sMeas; }  ///< measured [m]
    const Eigen::VectorXd& actuatorForces() const { return m_fMeas; } ///< measured [kN]
    /// A^T J0^T diag(k_c) J0 A's basic part: J0^T diag(k_c) J0 (3 x 3).
    const Eigen::Matrix3d& basicInitialStiffness() const { return m_kb0; }

private:
    /// Why u cannot be evaluated (a corotational element's collapsed chord), naming the element.
    std::optional<std::string> chordFault(const Eigen::VectorXd& uFull) const;
    /// The commands for basic displacements d (strokes of displacement channels, held forces
    /// of force channels), or why they must not leave.
    std::optional<std::string> commandsFor(const Eigen::Vector3d& d, Eigen::VectorXd& cmd) const;

    Link2dKinematics m_kin;
    std::unique_ptr<ExperimentalSetup> m_setup;
    std::vector<ActuatorChannelSpec> m_channels;
    int m_primary;
    Eigen::Matrix3d m_kb0;
    Eigen::Vector3d m_q0 = Eigen::Vector3d::Zero(); // basic forces held at rest (corotational K0)
    Link2dVector6 m_ue = Link2dVector6::Zero(), m_cUe = Link2dVector6::Zero(); // trial, committed
    bool m_linkSent = false;
    double m_targetTime = 0.0; // [s] the next target's test time (scheduled forces)
    Eigen::Vector3d m_dTrial = Eigen::Vector3d::Zero();
    Eigen::VectorXd m_cmd, m_sMeas, m_fMeas, m_dMeas, m_q;
    Eigen::VectorXd m_lastStroke; // committed commanded stroke per channel (increment limit)
    Eigen::VectorXd m_cSMeas, m_cFMeas, m_cDMeas, m_cQ; // committed measurement
};

} // namespace hsmu
