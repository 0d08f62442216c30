#pragma once
// ExperimentalControl: the seam between a hybrid test and the lab (ARCHITECTURE.md).
// Implementations: the in-process VirtualSpecimen (core), the TCP link to hsmu-controller and
// the OpenFresco-compatible links (comms). Swapping one for another changes nothing in
// core/experiment.
//
// Per integration step the test calls setTarget(d) once, then measure(), then commit() when
// the step is accepted. Deformation and force are in the specimen's own units (rotation [rad]
// and moment [kN m] for a rotational spring; [m] and [kN] for a lateral one).
// No call may block without a deadline; a fault is returned, never thrown.

#include <string>

namespace hsmu {

struct ControlMeasurement {
    double deformation = 0.0; ///< measured specimen deformation
    double force = 0.0;       ///< measured specimen force
};

struct ControlResult {
    bool ok = true;
    std::string reason; ///< why, when !ok
    static ControlResult success() { return {}; }
    static ControlResult fault(std::string why) { return {false, std::move(why)}; }
};

class ExperimentalControl {
public:
    virtual ~ExperimentalControl() = default;
    /// One line for logs and the status bar, e.g. "virtual specimen (boucWen, noise 1 %)".
    virtual std::string description() const = 0;
    /// Called once before the first step with the integration step dt [s].
    virtual ControlResult prepare(double dt) = 0;
    /// Command the specimen toward deformation d.
    virtual ControlResult setTarget(double d) = 0;
    /// Measured response after the last target.
    virtual ControlResult measure(ControlMeasurement& out) = 0;
    /// The step was accepted.
    virtual ControlResult commit() = 0;
    /// Go to a safe hold: keep the current position, accept no new target until resumed.
    virtual void hold(const std::string& reason) = 0;
    /// Leave the hold (operator action).
    virtual void resume() = 0;
    /// A warning the control raised since the last call (e.g. a sensor channel it stopped
    /// trusting), "" when none; the test records it as an alarm after the step's commit.
    virtual std::string takeNotice() { return {}; }
};

} // namespace hsmu
