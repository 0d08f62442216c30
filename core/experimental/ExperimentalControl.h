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
// Thread rules: one thread at a time (the test's), except emergencyHold(), which any thread
// may call at any time (docs/protocol.md, "Emergency hold").

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

namespace hsmu {

struct ControlMeasurement {
    double deformation = 0.0; ///< measured specimen deformation
    double force = 0.0;       ///< measured specimen force
};

/// What the actuator reported with the last measurement (docs/recording.md, /elements/actuator).
/// Positions in the specimen's deformation units; NaN / -1 where the control has no such channel.
struct ActuatorChannels {
    double commanded = std::numeric_limits<double>::quiet_NaN(); ///< actuator command at measurement
    double measured = std::numeric_limits<double>::quiet_NaN();  ///< measured position
    std::int64_t heldTicks = -1; ///< controller ticks held waiting for a late target (-1: none)
    std::int64_t flags = -1;     ///< native protocol flags (bit 0 fractured, bit 1 replayed); -1: none
};

/// What a specimen carries from earlier tests (a controller that keeps its specimens between
/// console sessions: hsmu-controller, docs/protocol.md "Reset"; docs/console.md, "A specimen
/// loaded by an earlier test"). Deformation in the specimen's units.
struct PriorLoading {
    std::uint64_t committedSteps = 0; ///< steps committed before this test
    double lastDeformation = 0.0;     ///< target of the last of them (where it stands)
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
    /// Two-phase commit (sites): send the commit without waiting for its acknowledgement;
    /// the next commit() completes it. Default: nothing (commit() does everything).
    virtual ControlResult beginCommit() { return ControlResult::success(); }
    /// Whether the link to the specimen is up (in-process controls: always).
    virtual bool connected() const { return true; }
    /// Seconds from the last setTarget() to the arrival of its measurement, when the control
    /// knows it (TcpControl: the frame's arrival on the link's io thread); NaN: unknown (the
    /// element then times setTarget() .. measure() itself).
    virtual double replyLatency() const { return std::numeric_limits<double>::quiet_NaN(); }
    /// Go to a safe hold: keep the current position, accept no new target until resumed.
    virtual void hold(const std::string& reason) = 0;
    /// Leave the hold (operator action).
    virtual void resume() = 0;
    /// A warning the control raised since the last call (e.g. a sensor channel it stopped
    /// trusting), "" when none; the test records it as an alarm after the step's commit.
    virtual std::string takeNotice() { return {}; }
    /// Out of band: any thread, any time (also while another thread is blocked in measure()
    /// or commit()). Sends the hold to the lab at once with at most a short bounded send,
    /// wakes a call blocked on the link so that it returns a fault promptly, and refuses new
    /// targets until resume(). The test still calls hold() afterwards on its own thread.
    /// Default: nothing, for controls whose calls never block (the in-process virtual
    /// specimen): the test holds them at its next step boundary (HybridTest::emergencyHold).
    virtual void emergencyHold(const std::string& reason) { (void)reason; }
    /// After prepare(), before the first step: what the specimen carries from earlier tests;
    /// nullopt when the control
    /// always starts from a virgin specimen (the in-process virtual specimen, OpenFresco).
    virtual std::optional<PriorLoading> priorLoading() const { return std::nullopt; }
    /// After prepare(), before the first target: ask the lab for a virgin specimen (committed
    /// steps 0). A control or lab that cannot give one returns a fault naming why (a rig's
    /// specimen is replaced by hand at the controller).
    virtual ControlResult freshSpecimen() {
        return ControlResult::fault("this control cannot replace its specimen: " + description());
    }
    /// The actuator channels of the last measurement; nullopt when the control has none.
    virtual std::optional<ActuatorChannels> actuatorChannels() const { return std::nullopt; }

    // N actuator channels (a multi-DOF specimen behind an experimental setup, docs/setups.md
    // "Multi-DOF elements"): one command and one measured stroke and force per actuator.
    // A one-channel control needs none of these (the defaults map them on setTarget/measure).
    /// Number of actuator channels.
    virtual int channelCount() const { return 1; }
    /// Command every channel at once: the stroke [m] of a displacement-controlled channel, the
    /// force [kN] of a force-controlled one (ActuatorChannelSpec). Nothing moves on a fault.
    virtual ControlResult setTargets(const Eigen::VectorXd& commands);
    /// Measured strokes and forces of every channel after the last setTargets().
    virtual ControlResult measureChannels(Eigen::VectorXd& strokes, Eigen::VectorXd& forces);
};

} // namespace hsmu
