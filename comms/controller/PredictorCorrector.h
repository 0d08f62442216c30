#pragma once
// PredictorCorrector: the actuator command generator of the lab's outer loop (METHOD.md
// section 8), one call per tick of the controller's loop (1024 Hz by default).
//
// A step lasts N ticks. After the previous step is committed the command is extrapolated
// from the last three committed targets h0 (newest), h1, h2 by the quadratic through them
// (Newton backward differences, s = i / N the fraction of the step elapsed):
//   p(s) = h0 + s (h0 - h1) + s (s + 1) / 2 (h0 - 2 h1 + h2)
// for at most P ticks. If the target has not arrived by then it is late: the command holds
// (the step's clock stops; heldTicks() counts the ticks). When the target T arrives at tick i
// the command is corrected linearly from its value c0 to T over the R = N - min(i, P)
// remaining ticks, c_j = c0 + (T - c0) j / R, and equals T exactly at j = R (Arrived).
// stop() freezes the command (a hold); after it no prediction is made: the next target is
// reached over N - P ticks from where the command stopped.
// Pure arithmetic: no clock, no threads; a simulated clock (fast pace) and the wall clock
// (real time) drive it alike.

namespace hsmu::comms {

class PredictorCorrector {
public:
    enum class Phase { Predicting, Late, Correcting, Arrived, Stopped };

    /// N >= 1 ticks per step, 0 <= P < N prediction ticks (clamped).
    void setTiming(int ticksPerStep, int predictTicks);
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
    int heldTicks() const { return m_held; }
    int ticksPerStep() const { return m_n; }
    int predictTicks() const { return m_p; }
    /// Ticks of the step's own clock elapsed (frozen while late or stopped).
    int tickInStep() const { return m_i; }

private:
    int m_n = 1, m_p = 0;
    Phase m_phase = Phase::Stopped;
    int m_i = 0, m_j = 0, m_remaining = 1, m_held = 0;
    double m_command = 0.0, m_from = 0.0, m_target = 0.0;
    double m_h0 = 0.0, m_h1 = 0.0, m_h2 = 0.0;
};

} // namespace hsmu::comms
