#pragma once
// RthsRunner: a whole RTHS run over a record that can hold and resume (docs/rths.md, "Hold and
// resume"). run() ticks RthsLoop until the record's end or a hold (the gate's before a tick: the
// operator, an emergency hold, the link, the deadline-miss policy; or the loop's own: a limit);
// resume() lets the next run() go on from the tick where it held, with everything the run had
// (structure, plant, compensator and its estimates, PID, sensors' noise stream, damper and twin,
// update sources) as it stopped. During a hold nothing ticks: the simulated plant and the
// numerical substructure stand still, so a run held before tick K and resumed equals the unheld
// run bit for bit at the simulated pace (at the real-time pace the pacer's schedule restarts at
// the resume; a real rig's actuator holding its last command meanwhile is outside that equality).
// Every tick is in the outputs once; result() evaluates J1..J9 over all of them.
// Thread rules: every call on one thread at a time (the caller's; the runner spawns none).

#include "core/rths/RthsBenchmark.h"

#include <vector>

namespace hsmu::rths {

class RthsRunner {
public:
    /// gate, observer and updates as runRths; not owned, they must outlive the runner.
    /// duration > 0 stops earlier [s].
    RthsRunner(const Partition& partition, const GroundMotion& groundMotion,
               const RthsSettings& settings, TickGate* gate = nullptr, double duration = 0.0,
               TickObserver* observer = nullptr, TwinUpdateSource* updates = nullptr);

    /// Tick until the end or a hold; returns true when the record's end was reached.
    bool run();
    /// Held (run() stopped early, not resumed yet).
    bool held() const { return !m_hold.empty(); }
    /// Why the run held ("" when it did not): the gate's or the loop's sentence, with the tick.
    const std::string& hold() const { return m_hold; }
    /// The tick the next run() starts with (the ticks so far).
    long next() const { return m_next; }
    long length() const { return m_n; } ///< the ticks of the whole run
    bool finished() const { return m_next >= m_n; }
    /// Let the next run() go on from next(): "" when it may, else why not (nothing changed):
    /// not held; or held by a limit whose channel is still past it (the plant's stroke, force
    /// or velocity, re-checked now; a command beyond the stroke is never resumed: the state
    /// that gave it has not moved). On success the gate's resume(next()) and the observer's
    /// onResume(next(), its time, ...) are told.
    std::string resume();
    /// The run so far, evaluated (J1..J9, frequency index, tracking indicator over every tick);
    /// hold() as its hold.
    RthsRun result() const;

private:
    Partition m_partition;
    RthsSettings m_settings;
    RthsLoop m_loop;
    TickGate* m_gate;
    TickObserver* m_observer;
    TwinUpdateSource* m_updates;
    long m_n = 0, m_next = 0;
    Eigen::MatrixXd m_reference;
    RthsRun m_run; // outputs so far (hybrid kept in m_hybrid until result())
    std::vector<Eigen::VectorXd> m_hybrid;
    std::string m_hold;
    bool m_loopHeld = false; // the hold is the loop's own (a limit)
};

} // namespace hsmu::rths
