#include "core/rths/RthsRunner.h"

#include "core/rths/DamperReference.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hsmu::rths {

RthsRunner::RthsRunner(const Partition& partition, const GroundMotion& groundMotion,
                       const RthsSettings& settings, TickGate* gate, double duration,
                       TickObserver* observer, TwinUpdateSource* updates)
    : m_partition(partition), m_settings(settings), m_loop(partition, groundMotion, settings),
      m_gate(gate), m_observer(observer), m_updates(updates)
{
    const double h = m_loop.period();
    const double length = duration > 0.0 ? std::min(duration, groundMotion.duration())
                                         : groundMotion.duration();
    m_n = long(std::floor(length / h + 1e-9)) + 1;
    for (auto* v : {&m_run.time, &m_run.desired, &m_run.command, &m_run.measured, &m_run.force})
        v->reserve(std::size_t(m_n));
    m_hybrid.reserve(std::size_t(m_n));
    // The reference before the loop (cheap: RK4 of the linear structure), so that each tick
    // can be recorded with it as it happens.
    // With a damper: the reference run of the same configuration with the damper in the
    // numerical model (J4..J9 compare against it, docs/rths.md "A damper and its twin").
    m_reference = referenceResponse(partition.reference, groundMotion, h, m_n,
                                    referenceDampers(partition, settings.damper));
}

bool RthsRunner::run()
{
    if (held())
        return false;
    RthsRun& run = m_run;
    for (long k = m_next; k < m_n; ++k) {
        std::string gateHold;
        if (m_gate && !m_gate->admit(k, gateHold)) {
            m_hold = gateHold;
            break;
        }
        for (TwinUpdate u; m_updates && m_updates->next(k, u);) {
            run.updates.push_back(m_loop.updateTwin(u));
            if (m_observer)
                m_observer->onUpdate(k, run.updates.back());
        }
        for (UpdateEvent e; m_updates && m_updates->nextEvent(k, e);) {
            run.updates.push_back(e);
            if (m_observer)
                m_observer->onUpdate(k, run.updates.back());
        }
        const bool advanced = m_loop.tick();
        if (m_gate)
            m_gate->done(k);
        const RthsTick& t = m_loop.last(); // sampled even when the tick held
        run.time.push_back(t.time);
        run.desired.push_back(t.desired);
        run.command.push_back(t.command);
        run.measured.push_back(t.measured);
        run.force.push_back(t.force);
        m_hybrid.push_back(t.floors);
        if (m_observer)
            m_observer->onTick(k, t, m_reference.row(k));
        if (m_updates && advanced)
            m_updates->observe(k, t.measured, t.damperForce);
        run.peakForce = std::max(run.peakForce, std::abs(m_loop.plant().force()));
        run.peakStroke = std::max(run.peakStroke, std::abs(m_loop.plant().displacement()));
        run.peakVelocity = std::max(run.peakVelocity, std::abs(m_loop.plant().velocity()));
        m_next = k + 1;
        if (!advanced) {
            m_hold = m_loop.holdReason();
            m_loopHeld = true;
            break;
        }
    }
    return finished() && !held();
}

std::string RthsRunner::resume()
{
    if (!held())
        return "the run is not held: nothing to resume";
    if (m_loopHeld) {
        if (const std::string why = m_loop.resume(); !why.empty())
            return "resume refused: " + why;
    }
    std::ostringstream o;
    o.precision(6);
    o << "resumed before tick " << m_next << " (t = " << double(m_next) * m_loop.period()
      << " s) after: " << m_hold;
    m_hold.clear();
    m_loopHeld = false;
    if (m_gate)
        m_gate->resume(m_next);
    if (m_observer)
        m_observer->onResume(m_next, double(m_next) * m_loop.period(), o.str());
    return {};
}

RthsRun RthsRunner::result() const
{
    RthsRun run = m_run;
    run.hold = m_hold;
    if (m_loop.twin())
        run.twin = m_loop.twin()->law().parameters();
    const auto floors = m_partition.reference.m.rows();
    const long m = long(run.time.size());
    run.hybrid.resize(m, floors);
    for (long k = 0; k < m; ++k)
        run.hybrid.row(k) = m_hybrid[std::size_t(k)].transpose();
    run.reference = m_reference.topRows(m);
    if (m < 2)
        return run;
    const auto col = [](const Eigen::MatrixXd& a, int i) {
        return std::vector<double>(a.col(i).data(), a.col(i).data() + a.rows());
    };
    const int j = m_partition.specimen.dof;
    auto& c = run.criteria.j;
    const TrackingReport tracking = trackingReport(run.desired, run.measured, m_loop.period());
    c[0] = tracking.j1;
    c[1] = tracking.j2;
    c[2] = tracking.j3;
    c[3] = normalizedRmsError(col(run.reference, j), run.measured);
    c[4] = peakError(col(run.reference, j), run.measured);
    // J6..J9: the two numerical floors after the specimen's (the benchmark's floors 2 and 3).
    int slot = 0;
    for (int i = 0; i < int(floors) && slot < 2; ++i) {
        if (i == j)
            continue;
        c[5 + slot] = normalizedRmsError(col(run.reference, i), col(run.hybrid, i));
        c[7 + slot] = peakError(col(run.reference, i), col(run.hybrid, i));
        ++slot;
    }
    run.frequency = tracking.frequency;
    run.trackingIndicator = tracking.indicator;
    return run;
}

} // namespace hsmu::rths
