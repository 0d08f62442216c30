#pragma once
// ExperimentalSetup: the layer between an experimental element and its control system
// (docs/setups.md, "The contract"), as OpenFresco's expSetup. It turns the element's basic
// displacements into actuator strokes (trial) and the measured actuator strokes and forces back
// into basic displacements and forces (measured).
//
// Units: basic displacements [m] for translations, [rad] for rotations; strokes [m] (positive:
// the actuator lengthens); actuator forces [N] (positive: tension, i.e. the force that does
// positive work on a lengthening stroke); basic forces [N] for translations, [N m] for
// rotations. Any consistent set works (kN, kN m) as long as it is consistent.
// Basic DOF order: the setup's own (each setup's header; OpenFresco's order).
//
// Force transformation: by virtual work, q . dd = f . ds for every admissible dd, so the
// basic forces are q = J(d)^T f with J = ds/dd (docs/setups.md, eq. S3). Setups whose actuators
// fix fewer DOFs than the element has (TwoActuators2d, FourActuators3d, OneActuator,
// NoTransformation) take the remaining basic displacements from a given vector (the trial's)
// when they recover d; the exact setups also start their Newton iteration there.
// No call throws or aborts: a fault returns a SetupResult naming the setup and the cause.
// Thread rules: const methods are reentrant (no mutable state).

#include <Eigen/Dense>

#include <string>
#include <utility>

namespace hsmu {

struct SetupResult {
    bool ok = true;
    std::string reason; ///< "<setup type>: <what, which parameter>" when !ok
    static SetupResult success() { return {}; }
    static SetupResult fault(std::string why) { return {false, std::move(why)}; }
};

class ExperimentalSetup {
public:
    virtual ~ExperimentalSetup() = default;
    /// OpenFresco's type name ("TwoActuators2d", ...).
    virtual std::string typeName() const = 0;
    /// Number of basic DOFs n of the element this setup serves.
    virtual int basicSize() const = 0;
    /// Number of actuators m.
    virtual int actuatorCount() const = 0;

    /// Trial: basic displacements d (n) -> actuator strokes s (m) (eq. S1).
    virtual SetupResult strokes(const Eigen::VectorXd& d, Eigen::VectorXd& s) const = 0;
    /// ds/dd at d (m x n), [m/m] and [m/rad] (eq. S2). The linear formulation's is constant.
    virtual SetupResult jacobian(const Eigen::VectorXd& d, Eigen::MatrixXd& J) const = 0;
    /// Measured: strokes s (m) -> basic displacements d (n). The basic DOFs the actuators do not
    /// fix are copied from `given` (size n; e.g. the trial d); the others solve s(d) = s.
    virtual SetupResult basicDisplacements(const Eigen::VectorXd& s, const Eigen::VectorXd& given,
                                           Eigen::VectorXd& d) const = 0;
    /// Measured: actuator forces f (m) at basic displacements d (n) -> basic forces
    /// q = J(d)^T f (n) (eq. S3). Setups may override it with a faster form of the same.
    virtual SetupResult basicForces(const Eigen::VectorXd& d, const Eigen::VectorXd& f,
                                    Eigen::VectorXd& q) const;
    /// Load cells the setup reads besides the actuators (OpenFresco's extra daq forces, e.g.
    /// FourActuators3d's two axial-load rods); basicForces then also takes m + this many forces.
    virtual int loadCellCount() const { return 0; }

    /// Trial rates (eq. S5): basic velocities v and accelerations a (n) at d -> actuator
    /// velocities sv = J(d) v [m/s] and accelerations sa = J(d) a + Jdot(d, v) v [m/s^2].
    /// Here Jdot v = (J(d + h v) - J(d - h v)) v / (2 h) with h |v|_inf = 1e-5 (m or rad): exact
    /// for the linear formulations (J constant), O(1e-10) relative otherwise; the planar family
    /// overrides it with the closed form.
    virtual SetupResult actuatorRates(const Eigen::VectorXd& d, const Eigen::VectorXd& v,
                                      const Eigen::VectorXd& a, Eigen::VectorXd& sv,
                                      Eigen::VectorXd& sa) const;
};

} // namespace hsmu
