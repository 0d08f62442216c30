// SpecimenStation's state journal (SpecimenStation.h, StateJournal.h): its records written,
// and replayed at a restart through a fresh specimen, one channel or N.
#include "comms/controller/SpecimenStation.h"

namespace hsmu::comms {

bool SpecimenStation::replay(const JournalRecord& r, std::string& error) {
    const std::string where = "specimen '" + m_spec.name + "': ";
    switch (r.kind) {
    case JournalRecord::Kind::Configure:
        m_dt = r.dt;
        if (m_rig)
            m_rig->prepare(m_dt);
        else
            m_specimen->prepare(m_dt);
        return true;
    case JournalRecord::Kind::Reset:
        makeSpecimen();
        m_committed = 0;
        m_last = m_trial = Trial{};
        for (ActuatorLoop& l : m_loops)
            l.restore(0.0, 0.0, 0.0, 0.0);
        return true;
    case JournalRecord::Kind::Commit:
        break;
    }
    if (!(m_dt > 0.0) || r.step != m_committed + 1) {
        error = where + "journaled step " + std::to_string(r.step) + " does not follow step " +
                std::to_string(m_committed);
        return false;
    }
    if (m_rig)
        return replayChannels(r, error);
    if (!r.channels.empty()) {
        error = where + "journaled step " + std::to_string(r.step) +
                " has several actuator channels, the specimen one";
        return false;
    }
    ControlMeasurement cm;
    if (!m_specimen->setTarget(r.achieved).ok || !m_specimen->measure(cm).ok ||
        !m_specimen->commit().ok || cm.deformation != r.deformation || cm.force != r.force) {
        error = where + "replaying step " + std::to_string(r.step) +
                " does not give the recorded measurement (was the configuration changed?)";
        return false;
    }
    m_last.valid = true;
    m_last.step = r.step;
    m_last.target = r.target;
    m_last.achieved = r.achieved;
    m_last.measurement = MeasurementMsg{r.step, r.deformation, r.force, r.target, 0, 0};
    m_committed = r.step;
    m_loops.front().replayCommit(r.target, r.achieved); // a restarted rig rests where it stopped
    return true;
}

Message SpecimenStation::journal(const JournalRecord& r) {
    std::string why;
    if (m_journal->append(r, why))
        return AckMsg{};
    // The step stands, but a restart would forget it: stop until the operator looks.
    return trip(ErrorCode::Internal, why);
}

bool SpecimenStation::replayChannels(const JournalRecord& r, std::string& error) {
    std::vector<double> t, a, s, f;
    for (const JournalChannel& c : r.channels) {
        t.push_back(c.target);
        a.push_back(c.achieved);
        s.push_back(c.stroke);
        f.push_back(c.force);
    }
    if (std::string why = m_rig->replay(r.step, t, a, s, f); !why.empty()) {
        error = "specimen '" + m_spec.name + "': " + why;
        return false;
    }
    m_committed = r.step;
    for (std::size_t i = 0; i < m_loops.size(); ++i)
        m_loops[i].replayCommit(t[i], a[i]); // a restarted rig rests where it stopped
    return true;
}

} // namespace hsmu::comms
