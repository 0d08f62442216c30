// SpecimenStation's N-channel parts (SpecimenStation.h, "N actuator channels"): a link2d
// specimen's ChannelRig stepped by one ActuatorLoop per channel, and its journal lines.
#include "comms/controller/SpecimenStation.h"

namespace hsmu::comms {

std::optional<Message> SpecimenStation::targets(const TargetsMsg& m) {
    if (!m_rig)
        return ErrorMsg{ErrorCode::ProtocolViolation,
                        "specimen '" + m_spec.name + "' has one actuator channel: send target"};
    if (!m_configured)
        return ErrorMsg{ErrorCode::NotConfigured, "targets before configure"};
    if (m_holding)
        return ErrorMsg{ErrorCode::Holding,
                        "specimen '" + m_spec.name + "' holds: " + m_holdReason};
    if (m_pending && m_pendingStep == m.step && m.channels.size() == m_loops.size()) {
        bool same = true;
        for (std::size_t i = 0; i < m_loops.size(); ++i)
            same = same && m_loops[i].target() == m.channels[i].command &&
                   m_rig->admitted()[i].mode == m.channels[i].mode;
        if (same)
            return std::nullopt; // already on its way
    }
    auto r = m_rig->admit(m, m_committed);
    if (auto* e = std::get_if<ErrorMsg>(&r)) {
        if (e->code == ErrorCode::Interlock || e->code == ErrorCode::SpecimenFault)
            return trip(e->code, e->reason);
        return *e;
    }
    if (auto* mm = std::get_if<MeasurementsMsg>(&r))
        return *mm;
    std::vector<double> t;
    for (const ChannelTarget& c : m.channels)
        t.push_back(c.command);
    return startStep(m.step, t);
}

Message SpecimenStation::finishChannels() {
    std::vector<double> achieved, commands;
    for (const ActuatorLoop& l : m_loops) {
        achieved.push_back(l.achieved());
        commands.push_back(l.command());
    }
    m_pending = false;
    auto r = m_rig->measure(achieved, commands);
    if (auto* e = std::get_if<ErrorMsg>(&r))
        return trip(e->code, e->reason);
    m_totalHeld += m_loops.front().heldTicks();
    auto& mm = std::get<MeasurementsMsg>(r);
    mm.step = m_pendingStep;
    return mm;
}

Message SpecimenStation::commitChannels(const CommitMsg& m) {
    if (m.step == m_committed && m_committed > 0)
        return AckMsg{MessageType::Commit, m_committed};
    if (m.step != m_committed + 1 || !m_rig->hasTrial(m.step))
        return ErrorMsg{ErrorCode::ProtocolViolation,
                        "commit of step " + std::to_string(m.step) + " without its measurement"};
    if (ControlResult r = m_rig->commit(); !r.ok)
        return trip(ErrorCode::SpecimenFault, r.reason);
    m_committed = m.step;
    const std::vector<double> targets = m_rig->committedCommands();
    for (std::size_t i = 0; i < m_loops.size(); ++i)
        m_loops[i].commit(targets[i]);
    if (m_journal) {
        JournalRecord r;
        r.element = m_index;
        r.step = m_committed;
        const std::vector<double> achieved = m_rig->committedAchieved();
        const MeasurementsMsg& mm = m_rig->committedMeasurement();
        for (std::size_t i = 0; i < targets.size(); ++i)
            r.channels.push_back(
                {targets[i], achieved[i], mm.channels[i].stroke, mm.channels[i].force});
        if (Message e = journal(r); std::holds_alternative<ErrorMsg>(e))
            return e;
    }
    return AckMsg{MessageType::Commit, m_committed};
}

void SpecimenStation::holdLoops() {
    m_rig->hold(m_holdReason);
    const std::vector<double> at = m_rig->committedAchieved();
    for (std::size_t i = 0; i < m_loops.size(); ++i)
        m_loops[i].holdAt(at[i]);
}

} // namespace hsmu::comms
