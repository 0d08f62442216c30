#include "gui/cli/RthsLink.h"

#include "gui/cli/RthsCommand.h"

#include <random>
#include <utility>

namespace hsmu::gui {

bool RthsLink::open(const std::string& host, std::uint16_t port, const std::string& token,
                    unsigned decimation, double duration, std::string& description, std::string& error,
                    bool resume)
{
    if (!m_link.connect(host, port, kConnectTimeout, error)) {
        error = RthsCommand::tr("cannot reach the controller %1:%2: %3")
                    .arg(QString::fromStdString(host)).arg(port).arg(QString::fromStdString(error)).toStdString();
        return false;
    }
    const std::uint64_t session = std::random_device{}() | (std::uint64_t(std::random_device{}()) << 32);
    m_link.send(comms::HelloMsg{comms::kProtocolVersion, session, token, {}}, error);
    const auto ack = m_link.receive(kConnectTimeout, error);
    if (!ack || !std::holds_alternative<comms::HelloAckMsg>(*ack)) {
        const auto* e = ack ? std::get_if<comms::ErrorMsg>(&*ack) : nullptr;
        error = RthsCommand::tr("the controller refused the monitor: %1")
                    .arg(QString::fromStdString(e ? e->reason : error)).toStdString();
        return false;
    }
    description = std::get<comms::HelloAckMsg>(*ack).description;
    if (!resume)
        return m_link.send(comms::RthsStartMsg{decimation, duration}, error);
    if (!m_link.send(comms::ResumeMsg{}, error))
        return false;
    for (;;) { // its answer comes before the resumed run's telemetry
        const auto answer = m_link.receive(kConnectTimeout, error);
        if (!answer)
            return false;
        if (const auto* a = std::get_if<comms::AckMsg>(&*answer); a && a->acked == comms::MessageType::Resume)
            return true;
        if (const auto* e = std::get_if<comms::ErrorMsg>(&*answer)) {
            error = RthsCommand::tr("the controller did not resume the run: %1")
                        .arg(QString::fromStdString(e->reason)).toStdString();
            return false;
        }
    }
}

RthsLink::Event RthsLink::next()
{
    Event ev;
    for (;;) {
        std::string error;
        const auto m = m_link.receive(kFrameTimeout, error);
        if (m_abandoned.load()) {
            ev.error = "abandoned by the monitor";
            return ev;
        }
        if (!m && m_link.isOpen())
            continue;
        if (!m) {
            ev.lost = true;
            ev.error = error;
            return ev;
        }
        if (const auto* t = std::get_if<comms::TelemetryMsg>(&*m)) {
            ev.kind = Event::Kind::Telemetry;
            ev.telemetry = *t;
            return ev;
        }
        if (const auto* u = std::get_if<comms::RthsUpdateAppliedMsg>(&*m)) {
            std::lock_guard lock(m_updatesMutex);
            m_updates.push_back(*u);
            continue;
        }
        if (const auto* p = std::get_if<comms::RthsProposalMsg>(&*m)) {
            UpdateEvent e{int(p->tick), 0.0, "damper twin", ParameterLayout(p->names), p->values, false, p->message};
            e.decision = static_cast<UpdateDecision>(p->decision);
            e.ok = e.decision == UpdateDecision::Applied;
            e.proposal = int(p->id);
            std::lock_guard lock(m_updatesMutex);
            m_proposals.push_back(std::move(e));
            continue;
        }
        if (const auto* e = std::get_if<comms::ErrorMsg>(&*m); e && e->code == comms::ErrorCode::UpdateRefused) {
            std::lock_guard lock(m_updatesMutex);
            m_updates.push_back(comms::RthsUpdateAppliedMsg{0, false, e->reason, {}, {}});
            continue;
        }
        if (const auto* e = std::get_if<comms::ErrorMsg>(&*m)) {
            ev.error = RthsCommand::tr("the controller: %1").arg(QString::fromStdString(e->reason)).toStdString();
            return ev;
        }
        if (const auto* end = std::get_if<comms::RthsEndMsg>(&*m)) {
            ev.kind = Event::Kind::End;
            ev.end = *end;
            return ev;
        }
        // acks (rths-start, holds) and anything else: not events of the run
    }
}

bool RthsLink::hold(const std::string& reason, bool emergency)
{
    std::string error;
    return emergency ? m_link.send(comms::EmergencyHoldMsg{reason}, error)
                     : m_link.send(comms::HoldMsg{reason}, error);
}

bool RthsLink::update(const std::vector<std::string>& names, const std::vector<double>& values)
{
    std::string error;
    return m_link.send(comms::RthsUpdateMsg{names, values}, error);
}

std::vector<comms::RthsUpdateAppliedMsg> RthsLink::takeUpdates()
{
    std::lock_guard lock(m_updatesMutex);
    return std::exchange(m_updates, {});
}

UpdateEvent RthsLink::eventOf(const comms::RthsUpdateAppliedMsg& u)
{
    UpdateEvent e{int(u.tick), 0.0, "damper twin", ParameterLayout(u.names), u.values, u.applied, u.message};
    e.decision = u.applied ? UpdateDecision::Applied : UpdateDecision::Refused;
    return e;
}

bool RthsLink::decide(std::uint32_t id, bool approve)
{
    std::string error;
    return m_link.send(comms::RthsDecisionMsg{id, approve}, error);
}

std::vector<UpdateEvent> RthsLink::takeProposals()
{
    std::lock_guard lock(m_updatesMutex);
    return std::exchange(m_proposals, {});
}

void RthsLink::abandon()
{
    m_abandoned = true;
    m_link.interrupt();
}

void RthsLink::bye(const std::string& why)
{
    std::string error;
    m_link.send(comms::ByeMsg{why}, error);
}

} // namespace hsmu::gui
