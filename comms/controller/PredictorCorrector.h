#pragma once
// PredictorCorrector: the actuator command generator of the lab's outer loop (docs/method.md,
// The lab loop), one call per tick of the controller's loop (1024 Hz by default).
//
// A step lasts N ticks. After the previous step is committed the command is extrapolated
// from the last three committed targets h0 (newest), h1, h2 by the quadratic through them
// (Newton backward differences, s = i / N the fraction of the step elapsed):
//   p(s) = h0 + s (h0 - h1) + s (s + 1) / 2 (h0 - 2 h1 + h2)
// for at most P ticks. If the target has not arrived by then it is late (the event-driven
// scheme): the step's clock stops (heldTicks() counts the late ticks) and the actuator slows
// to a hold. With v0 the command's increment of the last tick and R = holdRampTicks(), the
// k-th late tick moves the command by
//   v_k = v0 (R - k) / R   (k = 1 .. R; 0 after: the hold)
// so the speed falls linearly to zero, never above |v0|, and the command travels at most
// |v0| (R - 1) / 2 further (R = 0: it stops at once).
// When the target T arrives at tick i the command goes from its value c0 to T over the
// R' = N - min(i, P) remaining ticks, with j = 1 .. R', s = j / R':
//   on time (no late tick): linearly, c_j = c0 + (T - c0) s;
//   late: smoothly resumed from the current per-tick speed v (0 once held) by the cubic
//   Hermite c_j = c0 + R' v (s^3 - 2 s^2 + s) + (T - c0) (2 s^2 - s^3), whose speed starts
//   at v and ends at the linear correction's (T - c0) / R' (at most 4/3 of it from rest);
// and equals T exactly at j = R' (Arrived).
// Increment limit (setIncrementLimit, the interlock's): every command before the target is
// reached stays within h0 +- limit, the range a legal target can ask for (targets past it are
// refused before they reach the corrector).
// stop() freezes the command at once (a hold or an interlock trip); after it no prediction is
// made: the next target is reached over N - P ticks from where the command stopped.
// Pure arithmetic: no clock, no threads; a simulated clock (fast pace) and the wall clock
// (real time) drive it alike. In fast pace the target arrives as prediction ends (no late
// tick), so deceleration and smooth resumption play no part there.

namespace hsmu::comms {

class PredictorCorrector {
public:
    enum class Phase { Predicting, Late, Correcting, Arrived, Stopped };

    /// N >= 1 ticks per step, 0 <= P < N prediction ticks (clamped).
    void setTiming(int ticksPerStep, int predictTicks);
    /// R >= 0 ticks over which a late command slows to a hold (negative: 0).
    void setHoldRamp(int ticks);
    /// |command - h0| <= limit until the target is reached (infinite or NaN: no limit).
    void setIncrementLimit(double limit);
    /// |command| <= limit on every tick (the interlock's deformation limit; infinite, NaN or
    /// <= 0: no bound). A prediction or a correction that would overshoot saturates there.
    void setDeformationLimit(double limit);
    /// Start a step from the command c with committed targets h0 (last), h1, h2.
    void beginStep(double c, double h0, double h1, double h2);
    /// The step's target arrived: start (or restart) the correction toward it.
    void setTarget(double target);
    /// Freeze the command (hold); the next setTarget corrects without predicting.
    void stop();
    /// Advance one tick; returns the command for this tick.
    double tick();

    Phase phase() const { return m_phase; }
    double command() const { return m_command; }
    double target() const { return m_target; }
    /// The command's increment of the last tick (per tick; 0 when held or stopped).
    double velocity() const { return m_velocity; }
    int heldTicks() const { return m_held; }
    int ticksPerStep() const { return m_n; }
    int predictTicks() const { return m_p; }
    int holdRampTicks() const { return m_ramp; }
    /// Ticks of the step's own clock elapsed (frozen while late or stopped).
    int tickInStep() const { return m_i; }

private:
    /// Move the command to c (clamped into h0 +- the increment limit); sets the velocity.
    void moveTo(double c);
    int m_n = 1, m_p = 0, m_ramp = 0;
    Phase m_phase = Phase::Stopped;
    int m_i = 0, m_j = 0, m_remaining = 1, m_held = 0;
    double m_command = 0.0, m_from = 0.0, m_target = 0.0, m_velocity = 0.0;
    double m_lateVelocity = 0.0;  ///< v0: the speed when the target became late
    double m_resumeVelocity = 0.0; ///< v at setTarget after late ticks (smooth resumption)
    bool m_smooth = false;         ///< this correction resumes from a late step
    double m_limit = 0.0;          ///< increment limit (0: none)
    double m_bound = 0.0;          ///< deformation limit |command| (0: none)
    double m_h0 = 0.0, m_h1 = 0.0, m_h2 = 0.0;
};

} // namespace hsmu::comms
