#pragma once
// ActuatorLoop: one actuator channel of hsmu-controller at the loop rate (1 / h Hz): at every
// tick the predictor-corrector (PredictorCorrector.h) gives the command, the actuator model
// (ActuatorDynamics.h: ideal, lag, delay, servoHydraulic) tracks it, and the channel's bound
// is checked on what the actuator reached. The one channel of a SpecimenStation and each
// channel of an N-channel rig (ChannelRig.h) are one ActuatorLoop each, so both hold late
// targets, pace and trip the same way (docs/method.md, "The lab loop").
// Units are the channel's own: a stroke [m] on a displacement-controlled channel, a force [kN]
// on a force-controlled one (its force loop predicts, lags and waits the same way).
// Bound B (setLimits): |command| <= B on every tick (the corrector saturates there) and an
// achieved value with |a| > B (or not finite) is a trip; increment I: |command - h0| <= I
// until the target is reached (h0 the last committed target). B, I infinite, NaN or <= 0: none.
// History: h0 (newest), h1, h2 the last committed targets, the predictor's three points.
// Thread rules: one thread.

#include "comms/controller/ActuatorDynamics.h"
#include "comms/controller/PredictorCorrector.h"

#include <optional>
#include <string>

namespace hsmu::comms {

class ActuatorLoop {
public:
    /// quantity: how a trip names the achieved value ("actuator position |d|").
    ActuatorLoop(const ActuatorModel& model, double rate,
                 std::string quantity = "actuator position |d|");

    /// N ticks per step, P prediction ticks, R hold-ramp ticks (PredictorCorrector.h).
    void setTiming(int ticksPerStep, int predictTicks, int holdRampTicks);
    void setLimits(double bound, double increment);
    /// Start a step from the current command with the committed history.
    void beginStep();
    void setTarget(double target) { m_pc.setTarget(target); }
    /// Freeze the command (a hold or a trip); the actuator stays where it is.
    void stop() { m_pc.stop(); }
    /// One tick of predictor and actuator: nullopt, or why the achieved value trips.
    std::optional<std::string> tick();
    /// The step's target is committed: the history shifts and the next step begins.
    void commit(double target);
    /// The actuator at rest at `position`, the command at h0 (where a committed step's command
    /// ends), committed targets h0, h1, h2 (a reset).
    void restore(double position, double h0, double h1, double h2);
    /// A journaled step replayed at a restart: target committed, the actuator at rest at
    /// `position` (a lag's whole state, so a restart continues it exactly; a delay line is
    /// filled with it and a servo rests there: their inner state is not journaled).
    void replayCommit(double target, double position) { restore(position, target, m_h0, m_h1); }
    /// Back at rest at `position` with the committed history kept (a hold of an N-channel rig).
    void holdAt(double position) { restore(position, m_h0, m_h1, m_h2); }

    PredictorCorrector::Phase phase() const { return m_pc.phase(); }
    double command() const { return m_pc.command(); }
    double target() const { return m_pc.target(); }
    double achieved() const { return m_actuator.position(); }
    int heldTicks() const { return m_pc.heldTicks(); }
    double committedTarget() const { return m_h0; }
    double bound() const { return m_bound; }
    /// The largest |command| ever given (NaN counts as infinite).
    double peakCommand() const { return m_peak; }
    const ActuatorModel& model() const { return m_actuator.model(); }

private:
    PredictorCorrector m_pc;
    ActuatorDynamics m_actuator;
    std::string m_quantity;
    double m_bound = 0.0;
    double m_h0 = 0.0, m_h1 = 0.0, m_h2 = 0.0;
    double m_peak = 0.0;
};

} // namespace hsmu::comms
