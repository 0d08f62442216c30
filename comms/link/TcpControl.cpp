#include "comms/link/TcpControl.h"

#include "comms/link/LinkClient.h"
#include "core/util/ReasonText.h"

#include <algorithm>
#include <chrono>
#include <thread>

namespace hsmu::comms {

namespace {

bool closesConnection(ErrorCode c) {
    switch (c) {
    case ErrorCode::Malformed:
    case ErrorCode::UnsupportedVersion:
    case ErrorCode::Unauthorized:
    case ErrorCode::Busy:
    case ErrorCode::UnknownElement:
    case ErrorCode::Timeout:
        return true;
    default:
        return false;
    }
}

} // namespace

TcpControl::TcpControl(std::string host, std::uint16_t port, std::string element,
                       const SafetyLimits& limits, const TcpControlOptions& options)
    : m_link(std::make_unique<LinkClient>(
          LinkClientOptions{options.heartbeatInterval, options.silenceTimeout, options.tls})),
      m_host(std::move(host)), m_port(port), m_element(std::move(element)), m_limits(limits),
      m_opt(options) {}

TcpControl::~TcpControl() {
    if (m_link->isOpen()) {
        std::string ignore;
        m_link->send(ByeMsg{"test finished"}, ignore);
    }
    m_link->close();
}

std::string TcpControl::downReason() const {
    if (!m_linkError.empty())
        return m_linkError;
    const std::string reason = m_link->closeReason();
    return reason.empty() ? std::string("connection closed") : reason;
}

std::string TcpControl::where() const {
    const bool v6 = m_host.find(':') != std::string::npos;
    return (m_opt.tls ? "tls://" : "tcp://") + (v6 ? "[" + m_host + "]" : m_host) + ":" +
           std::to_string(m_port);
}

std::string TcpControl::description() const {
    return (m_opt.tls ? "TLS link " : "TCP link ") + where() + " to " +
           (m_controllerDescription.empty() ? "specimen '" + m_element + "'"
                                            : m_controllerDescription);
}

bool TcpControl::linkUp() const {
    return m_link->isOpen();
}

ControlResult TcpControl::linkFault(const std::string& what) {
    m_link->close();
    m_linkError = what;
    m_awaitingMeasurement = false;
    return ControlResult::fault("link to " + where() + ": " + what);
}

ControlResult TcpControl::refused(const ErrorMsg& e) {
    const std::string text = std::string(errorCodeName(e.code)) + ": " + e.reason;
    if (closesConnection(e.code)) {
        m_link->close();
        m_linkError = text;
    }
    return ControlResult::fault("controller at " + where() + ": " + text);
}

std::string TcpControl::emergencyText() const {
    std::lock_guard lock(m_emergencyMutex);
    return "emergency hold: " + m_emergencyReason;
}

ControlResult TcpControl::noReply(const std::string& what, const std::string& error) {
    if (emergency()) {
        m_awaitingMeasurement = false;
        return ControlResult::fault(where() + ": " + emergencyText() + " (" + what +
                                    " not awaited)");
    }
    return linkFault(what + ": " + error);
}

ControlResult TcpControl::await(MessageType acked, double timeout) {
    std::string error;
    const auto m = m_link->receive(timeout, error);
    if (!m)
        return noReply(std::string("no ") + messageTypeName(acked) + " acknowledgement", error);
    if (const auto* e = std::get_if<ErrorMsg>(&*m))
        return refused(*e);
    const auto* a = std::get_if<AckMsg>(&*m);
    if (!a || a->acked != acked)
        return linkFault(std::string("expected the ") + messageTypeName(acked) +
                         " acknowledgement, received " + messageTypeName(messageTypeOf(*m)));
    if (acked == MessageType::Commit && a->step != m_committed + 1)
        return linkFault("commit acknowledged for step " + std::to_string(a->step) + ", expected " +
                         std::to_string(m_committed + 1));
    return ControlResult::success();
}

ControlResult TcpControl::handshake(bool initial) {
    std::string error;
    m_awaitingMeasurement = false;
    m_connectFailed = false;
    if (!m_link->connect(m_host, m_port, m_opt.connectTimeout, error)) {
        m_connectFailed = true;
        m_linkError = error;
        return ControlResult::fault("link to " + where() + ": " + error);
    }
    HelloMsg hello;
    hello.sessionId = m_opt.sessionId;
    hello.token = m_opt.token;
    hello.element = m_element;
    if (!m_link->send(hello, error))
        return linkFault(error);
    const auto m = m_link->receive(m_opt.stepDeadline, error);
    if (!m)
        return noReply("no answer to the hello", error);
    if (const auto* e = std::get_if<ErrorMsg>(&*m))
        return refused(*e);
    const auto* ack = std::get_if<HelloAckMsg>(&*m);
    if (!ack)
        return linkFault(std::string("expected hello-ack, received ") +
                         messageTypeName(messageTypeOf(*m)));
    if (ControlResult r = checkChannels(*ack); !r.ok)
        return r;
    m_controllerDescription = ack->description;
    m_controllerCommitted = ack->committedSteps;
    if (initial) {
        m_committed = ack->committedSteps;
        m_lastCommittedTarget = ack->lastCommittedTarget;
        bool held = ack->holding;
        if (m_committed > 0 && m_opt.freshSpecimen) {
            if (ControlResult r = sendReset(); !r.ok)
                return r;
            held = false; // a new specimen
        }
        if (held) {
            // A trip left by an earlier session (the controller ends a console's own hold with
            // its session): nothing is armed until someone clears it at the controller.
            m_link->close();
            m_linkError = reasonText("held-from-previous-session", {ack->holdReason});
            return ControlResult::fault(
                reasonText("controller-refused", {where(), m_linkError}));
        }
    } else if (ack->committedSteps != m_committed && ack->committedSteps != m_committed + 1) {
        // +1: the controller committed the step whose acknowledgement was lost; the retried
        // step gets that step's measurement and commit again, idempotently.
        return linkFault("the controller's specimen is at step " +
                         std::to_string(ack->committedSteps) + " but the test committed " +
                         std::to_string(m_committed) +
                         " (was it restarted without its --state file?); cannot resume "
                         "without a jump");
    }
    ConfigureMsg c;
    c.dt = m_dt;
    c.maxDeformation = m_limits.maxDeformation;
    c.maxForce = m_limits.maxForce;
    c.maxIncrement = m_limits.maxIncrement;
    if (!m_link->send(c, error))
        return linkFault(error);
    if (ControlResult r = await(MessageType::Configure, m_opt.stepDeadline); !r.ok)
        return r;
    m_linkError.clear();
    return ControlResult::success();
}

ControlResult TcpControl::sendReset() {
    std::string error;
    if (!m_link->send(ResetMsg{}, error))
        return linkFault(error);
    if (ControlResult r = await(MessageType::Reset, m_opt.stepDeadline); !r.ok)
        return r;
    m_committed = 0;
    m_controllerCommitted = 0;
    m_lastCommittedTarget = 0.0;
    m_measured = false;
    return ControlResult::success();
}

std::optional<PriorLoading> TcpControl::priorLoading() const {
    return PriorLoading{m_committed, m_lastCommittedTarget};
}

ControlResult TcpControl::freshSpecimen() {
    if (emergency())
        return ControlResult::fault(where() + ": " + emergencyText());
    if (!m_link->isOpen())
        return ControlResult::fault("link to " + where() + " is down (" + downReason() + ")");
    if (m_committed == 0)
        return ControlResult::success(); // virgin already
    return sendReset();
}

ControlResult TcpControl::reconnect() {
    const int attempts = std::max(1, m_opt.reconnectAttempts);
    ControlResult last;
    for (int i = 0; i < attempts; ++i) {
        if (emergency())
            return ControlResult::fault(where() + ": " + emergencyText());
        if (i > 0)
            std::this_thread::sleep_for(std::chrono::duration<double>(m_opt.reconnectDelay));
        last = handshake(false);
        if (last.ok) {
            ++m_reconnects;
            return last;
        }
        if (!m_connectFailed)
            break; // refused, or the specimen is not where the test left it
    }
    return last;
}

ControlResult TcpControl::prepare(double dt) {
    if (!(dt > 0.0))
        return ControlResult::fault("TCP link: dt must be > 0");
    m_dt = dt;
    const int attempts = std::max(1, m_opt.reconnectAttempts);
    ControlResult r;
    for (int i = 0; i < attempts; ++i) {
        if (i > 0)
            std::this_thread::sleep_for(std::chrono::duration<double>(m_opt.reconnectDelay));
        r = handshake(true);
        if (r.ok || !m_connectFailed) // a refusal (busy, token, ...) is not retried
            break;
    }
    return r;
}

std::optional<ControlResult> TcpControl::targetRefusal() const {
    if (emergency())
        return ControlResult::fault(where() + ": " + emergencyText());
    if (m_holding)
        return ControlResult::fault("TCP link is holding: " + m_holdReason);
    if (!m_link->isOpen())
        return ControlResult::fault("link to " + where() + " is down (" + downReason() +
                                    "); resume to reconnect");
    return std::nullopt;
}

ControlResult TcpControl::setTarget(double d) {
    if (multiChannel())
        return ControlResult::fault(where() + ": specimen '" + m_element + "' has " +
                                    std::to_string(channelCount()) +
                                    " actuator channels; one target given");
    if (auto refusal = targetRefusal())
        return *refusal;
    m_sentTarget = d;
    return sendTarget();
}

ControlResult TcpControl::measure(ControlMeasurement& out) {
    if (ControlResult r = receiveMeasurement(); !r.ok)
        return r;
    out.deformation = multiChannel() ? m_lastN.channels[0].stroke : m_last.deformation;
    out.force = multiChannel() ? m_lastN.channels[0].force : m_last.force;
    return ControlResult::success();
}

ControlResult TcpControl::beginCommit() {
    m_commitSent = false;
    std::string error;
    if (!emergency() && m_link->isOpen() && m_link->send(CommitMsg{m_committed + 1}, error))
        m_commitSent = true;
    return ControlResult::success();
}

ControlResult TcpControl::commit() {
    const bool sent = m_commitSent;
    m_commitSent = false;
    if (emergency())
        return ControlResult::fault(where() + ": " + emergencyText());
    if (!m_link->isOpen())
        return recoverCommit("link down (" + downReason() + ")");
    std::string error;
    if (!sent && !m_link->send(CommitMsg{m_committed + 1}, error))
        return recoverCommit(error);
    ControlResult r = await(MessageType::Commit, m_opt.stepDeadline);
    if (r.ok) {
        ++m_committed;
        return r;
    }
    // Interrupted by an emergency hold: the step is retried after the resume (a commit the
    // controller did make is then answered idempotently: same measurement, same ack).
    return m_link->isOpen() || emergency() ? r : recoverCommit(downReason());
}

ControlResult TcpControl::recoverCommit(const std::string& why) {
    // The integrator has already completed this step when commit() is called, so a lost
    // commit is settled here rather than by holding and retrying the step: reconnect, and
    // either the controller did commit (its step count says so) or the step is measured again
    // (same target, no new trial on a running controller; a restarted one recomputes it from
    // its journal, which must give the very same measurement) and committed.
    const int attempts = std::max(1, m_opt.reconnectAttempts);
    ControlResult last = ControlResult::fault("link to " + where() + ": commit lost: " + why);
    for (int i = 0; i < attempts; ++i) {
        if (emergency())
            return ControlResult::fault(where() + ": " + emergencyText());
        if (i > 0)
            std::this_thread::sleep_for(std::chrono::duration<double>(m_opt.reconnectDelay));
        if (ControlResult h = handshake(false); !h.ok) {
            last = ControlResult::fault(
                "link to " + where() + ": the commit of step " + std::to_string(m_committed + 1) +
                " is in doubt (sent, never acknowledged: the controller may have made it, or may "
                "still make it when it wakes; the console's records end at step " +
                std::to_string(m_committed) + "); first: " + why + "; then: " + h.reason);
            if (!m_connectFailed)
                break;
            continue;
        }
        ++m_reconnects;
        if (m_controllerCommitted == m_committed + 1) {
            ++m_committed;
            return ControlResult::success();
        }
        const MeasurementMsg before = m_last;
        const MeasurementsMsg beforeN = m_lastN;
        if (auto refusal = targetRefusal())
            return *refusal;
        if (ControlResult t = sendTarget(); !t.ok)
            return t;
        if (ControlResult mr = receiveMeasurement(); !mr.ok)
            return mr;
        const auto same = [](const MeasurementsMsg& a, const MeasurementsMsg& b) {
            if (a.channels.size() != b.channels.size())
                return false;
            for (std::size_t i = 0; i < a.channels.size(); ++i)
                if (a.channels[i].stroke != b.channels[i].stroke ||
                    a.channels[i].force != b.channels[i].force)
                    return false;
            return true;
        };
        if (multiChannel() ? !same(m_lastN, beforeN)
                           : (m_last.deformation != before.deformation ||
                              m_last.force != before.force))
            return ControlResult::fault("controller at " + where() + ": step " +
                                        std::to_string(m_committed + 1) +
                                        " measured differently after the reconnect; not committed");
        std::string error;
        if (!m_link->send(CommitMsg{m_committed + 1}, error))
            return linkFault(error);
        if (ControlResult c = await(MessageType::Commit, m_opt.stepDeadline); !c.ok)
            return c;
        ++m_committed;
        return ControlResult::success();
    }
    return last;
}

void TcpControl::emergencyHold(const std::string& reason) {
    {
        std::lock_guard lock(m_emergencyMutex);
        m_emergencyReason = reason.empty() ? std::string("operator") : reason;
        // Counted before the send, so that hold() on the worker never misses its ack.
        m_emergencyHoldsSent.fetch_add(1, std::memory_order_acq_rel);
        std::string error;
        if (!m_link->send(HoldMsg{reason.substr(0, 512)}, error))
            m_emergencyHoldsSent.fetch_sub(1, std::memory_order_acq_rel);
        m_emergency.store(true, std::memory_order_release);
    }
    m_link->interrupt();
}

void TcpControl::takeEmergencyAcks(int count) {
    // The emergency Hold frames were sent out of band; what arrives before their
    // acknowledgements (a measurement or commit ack that crossed them, an error such as
    // "holding") belongs to the interrupted step, which is retried after resume.
    const auto deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration<double>(std::min(m_opt.stepDeadline, 2.0));
    while (count > 0) {
        const double left =
            std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
        std::string error;
        const auto m = left > 0.0 ? m_link->receive(left, error) : std::nullopt;
        if (!m) {
            linkFault("no acknowledgement of the emergency hold" +
                      (error.empty() ? std::string() : ": " + error));
            return;
        }
        if (const auto* a = std::get_if<AckMsg>(&*m); a && a->acked == MessageType::Hold)
            --count;
    }
}

void TcpControl::hold(const std::string& reason) {
    m_commitSent = false;
    m_holding = true;
    m_holdReason = reason;
    m_awaitingMeasurement = false;
    if (!m_link->isOpen())
        return;
    m_link->clearInterrupt();
    if (const int sent = m_emergencyHoldsSent.exchange(0, std::memory_order_acq_rel); sent > 0) {
        takeEmergencyAcks(sent);
        return;
    }
    std::string error;
    if (!m_link->send(HoldMsg{reason}, error) ||
        !await(MessageType::Hold, std::min(m_opt.stepDeadline, 2.0)).ok)
        linkFault("no acknowledgement of the hold");
}

void TcpControl::resume() {
    {
        std::lock_guard lock(m_emergencyMutex);
        m_emergency.store(false, std::memory_order_release);
        m_emergencyReason.clear();
    }
    m_link->clearInterrupt();
    if (const int sent = m_emergencyHoldsSent.exchange(0, std::memory_order_acq_rel);
        sent > 0 && m_link->isOpen())
        takeEmergencyAcks(sent);
    m_holding = false;
    m_holdReason.clear();
    if (!m_link->isOpen() && !reconnect().ok)
        return; // setTarget reports the link as down; the test holds again
    const auto acknowledged = [this] {
        std::string error;
        return m_link->send(ResumeMsg{}, error) && await(MessageType::Resume, m_opt.stepDeadline).ok;
    };
    if (acknowledged())
        return;
    // The link closed while the test was held before this side saw it (e.g. the controller
    // replaced the session): reconnect once and resume there (a refusal keeps the link open).
    if (!emergency() && !m_link->isOpen() && reconnect().ok && acknowledged())
        return;
    linkFault("no acknowledgement of the resume");
}

} // namespace hsmu::comms
