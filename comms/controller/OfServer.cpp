#include "comms/controller/OfServer.h"

#include "comms/LogText.h"

#include "comms/openfresco/OfFrame.h"
#include "comms/openfresco/OfSocket.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <limits>
#include <thread>

namespace hsmu::comms {

using namespace of;

namespace {

constexpr long kLoggedInitLines = 16; // GenericTCP init lines logged per session

volatile std::sig_atomic_t g_signalled = 0;

extern "C" void onSignal(int) {
    g_signalled = 1;
}

std::string reasonOf(const Message& m) {
    if (const auto* e = std::get_if<ErrorMsg>(&m))
        return e->reason;
    return std::string("unexpected ") + messageTypeName(messageTypeOf(m));
}

} // namespace

OfServer::OfServer(const OfServerOptions& options,
                   std::vector<std::unique_ptr<SpecimenStation>> stations)
    : m_opt(options), m_stations(std::move(stations)), m_listener(std::make_unique<OfListener>()),
      m_measured(m_stations.size()), m_commanded(m_stations.size(), 0.0) {
    if (m_opt.dofs.specimens() != static_cast<int>(m_stations.size()))
        m_opt.dofs = OfDofMap(static_cast<int>(m_stations.size()));
    m_listener->setCancel([this] { return m_stop.load() || g_signalled != 0; });
}

OfServer::~OfServer() = default;

std::string OfServer::describe() const {
    std::string role = m_opt.protocol == OfProtocol::GenericTcp ? "generictcp server"
                       : m_opt.siteServer                       ? "simapp site server"
                                                                : "simapp element server";
    const ChannelRig* rig = channelRig();
    return role + ", dataSize " + std::to_string(m_opt.dataSize) + ", " +
           (rig ? std::to_string(rig->channels()) + " actuator channels of '" +
                      m_stations[0]->name() + "'"
                : m_opt.dofs.describe());
}

void OfServer::log(const std::string& line) const {
    if (!m_opt.quiet)
        std::fprintf(stderr, "hsmu-controller: %s\n", line.c_str());
}

bool OfServer::listen(std::string& error) {
    if (!m_listener->listen(m_opt.bind, m_opt.port, error)) {
        error = "--bind/--port: " + error;
        return false;
    }
    // Before anyone is told the port: no TLS files to reload here, so SIGHUP is ignored (its
    // default action would end the process).
    std::signal(SIGHUP, SIG_IGN);
    return true;
}

std::uint16_t OfServer::port() const {
    return m_listener->port();
}

void OfServer::stop() {
    m_stop = true;
}

void OfServer::run() {
    std::signal(SIGINT, onSignal);
    std::signal(SIGTERM, onSignal);
    while (!m_stop && g_signalled == 0) {
        OfSocket socket;
        socket.setCancel([this] { return cancelled(); });
        std::string error;
        if (!m_listener->accept(socket, 0.0, error)) {
            if (!error.empty())
                log(error);
            continue;
        }
        ++m_stats.sessionsAdmitted;
        m_lastFrame = std::chrono::steady_clock::now();
        m_replaced = false;
        log("session " + socket.peer() + " (" + describe() + ")");
        serve(socket);
        socket.close();
    }
    m_listener->close();
}

bool OfServer::cancelled() {
    if (m_stop.load() || g_signalled != 0)
        return true;
    const auto idle = std::chrono::steady_clock::now() - m_lastFrame;
    if (idle < std::chrono::duration<double>(m_opt.idleTimeout) || !m_listener->pending())
        return false;
    m_replaced = true;
    return true;
}

std::string OfServer::idleText() const {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", m_opt.idleTimeout);
    return std::string("idle for ") + buf + " s while another client waits";
}

void OfServer::serve(OfSocket& socket) {
    std::string why;
    const std::string peer = socket.peer(); // "" once the socket is closed
    if (!acceptHeader(socket, why)) {
        ++m_stats.sessionsRefused;
        log("refused " + peer + ": " + why);
        refuse(socket);
        return;
    }
    log("sizes " + m_sizes.describe());
    // A fresh specimen per session, configured with the test's dt.
    for (auto& st : m_stations) {
        if (st->committedSteps() > 0 || st->holding())
            st->reset();
        ConfigureMsg c;
        c.dt = m_opt.dt;
        if (const Message m = st->configure(c); std::holds_alternative<ErrorMsg>(m)) {
            log("cannot configure specimen '" + st->name() + "': " + reasonOf(m));
            return;
        }
    }
    m_haveTrial = false;
    for (auto& m : m_measured)
        m = MeasurementMsg{};
    std::fill(m_commanded.begin(), m_commanded.end(), 0.0);
    m_ctrl.assign(static_cast<std::size_t>(dofCount()), 0.0);
    m_measuredN = MeasurementsMsg{};

    const std::size_t frameBytes = static_cast<std::size_t>(m_sizes.dataSize) * sizeof(double);
    std::vector<std::uint8_t> buffer(std::max(frameBytes, kInitLineBytes));
    std::vector<double> frame, reply;
    std::vector<std::uint8_t> out;
    const bool generic = m_opt.protocol == OfProtocol::GenericTcp;
    // Whatever ends the session other than 99 leaves every actuator holding (OfServer.h).
    bool terminated = false;
    struct HoldOnExit {
        OfServer* server;
        const bool& terminated;
        ~HoldOnExit() {
            if (!terminated)
                server->holdAfterSession("the OpenFresco session ended without 99");
        }
    } holdOnExit{this, terminated};
    bool framesStarted = false;
    bool trialSeen = false; // until the first trial, a getDaqResponse is the console's probe
    long initLines = 0;
    const auto countInitLines = [&] {
        if (initLines > kLoggedInitLines)
            log(std::to_string(initLines) + " init lines in this session");
    };
    for (;;) {
        // Sessions may idle between steps for as long as the client computes; a vanished
        // peer is a closed socket (or TCP keep-alive), a stop request cancels the read.
        if (generic && !framesStarted) {
            if (!socket.read(buffer.data(), 8, 0.0, why))
                break;
            const bool isFrame = startsWithCode(buffer.data()); // an unknown code too
            const std::size_t total = isFrame ? frameBytes : kInitLineBytes;
            if (total > 8 && !socket.read(buffer.data() + 8, total - 8, 0.0, why))
                break;
            if (!isFrame) {
                // The client's text, escaped and cut, and only the first lines (issue 26, D2).
                if (++initLines <= kLoggedInitLines)
                    log("init line: " + logText(decodeInitLine(buffer.data())));
                else if (initLines == kLoggedInitLines + 1)
                    log("further init lines not logged (their count is, at the session's end)");
                continue;
            }
            framesStarted = true;
        } else if (!socket.read(buffer.data(), frameBytes, 0.0, why)) {
            break;
        }
        m_lastFrame = std::chrono::steady_clock::now();
        decodeFrame(buffer.data(), m_sizes.dataSize, frame);
        const auto action = actionOf(frame[0]);
        if (!action) {
            char code[32];
            std::snprintf(code, sizeof code, "%g", frame[0]);
            countInitLines();
            log(std::string("unknown action code ") + code + "; session closed");
            return;
        }
        reply.clear();
        bool answer = false;
        switch (*action) {
        case Action::SetTrialResponse:
            trialSeen = true;
            if (!trial(frame, why)) {
                log(why + "; session closed");
                return;
            }
            break;
        case Action::CommitState:
            if (!commitAll(why)) {
                log(why + "; session closed");
                return;
            }
            break;
        case Action::GetDaqResponse:
            reply = daqReply(0, 5);
            answer = true;
            if (!trialSeen && reply.size() < static_cast<std::size_t>(m_sizes.dataSize)) {
                // The console's connect probe: say which server answers (OfFrame.h).
                reply.resize(static_cast<std::size_t>(m_sizes.dataSize), 0.0);
                reply.back() = generic ? kMarkGenericTcpServer : kMarkSimAppServer;
            }
            break;
        case Action::GetDisp:
        case Action::GetVel:
        case Action::GetAccel:
        case Action::GetForce:
        case Action::GetTime: {
            const int k = static_cast<int>(*action) - static_cast<int>(Action::GetDisp);
            reply = daqReply(k, k + 1);
            answer = true;
            break;
        }
        case Action::GetInitialStiff:
        case Action::GetTangentStiff:
        case Action::GetDamp:
        case Action::GetMass:
            answer = m_opt.protocol == OfProtocol::SimApp && !m_opt.siteServer;
            if (answer)
                reply = matrix(static_cast<int>(*action));
            break;
        case Action::Terminate:
            log("session " + socket.peer() + " terminated by the client (99)");
            terminated = true;
            return;
        case Action::Open:
        case Action::Setup:
        case Action::Execute:
            break;
        }
        if (answer) {
            std::string error;
            if (!encodeFrame(reply, m_sizes.dataSize, out, error) ||
                !socket.write(out.data(), out.size(), kWriteTimeout, error)) {
                log("reply not sent: " + error + "; session closed");
                return;
            }
        }
    }
    countInitLines();
    if (m_replaced)
        why = peer + " " + idleText();
    log(socket.closedByPeer() ? "session ended: " + why : "session closed: " + why);
}

bool OfServer::trial(const std::vector<double>& frame, std::string& why) {
    const std::size_t n = m_stations.size();
    if (m_opt.protocol == OfProtocol::GenericTcp && m_haveTrial && !commitAll(why))
        return false;
    if (channelRig())
        return trialChannels(frame, why);
    const auto first = static_cast<std::size_t>(m_sizes.ctrlIndex(Resp::Disp));
    for (std::size_t i = 0; i < m_ctrl.size(); ++i) {
        m_ctrl[i] = frame[first + i];
        if (!std::isfinite(m_ctrl[i])) {
            why = "the trial of DOF " + std::to_string(i + 1) + " is not finite";
            return false;
        }
    }
    m_commanded = m_opt.dofs.deformations(m_ctrl);
    std::vector<std::optional<Message>> result(n);
    for (std::size_t i = 0; i < n; ++i)
        result[i] =
            m_stations[i]->target(TargetMsg{m_stations[i]->committedSteps() + 1, m_commanded[i]});
    if (!tickUntilMeasured(result, why))
        return false;
    for (std::size_t i = 0; i < n; ++i) {
        const auto* mm = result[i] ? std::get_if<MeasurementMsg>(&*result[i]) : nullptr;
        if (!mm) {
            why = result[i] ? reasonOf(*result[i])
                            : "specimen '" + m_stations[i]->name() + "' gave no measurement";
            return false;
        }
        m_measured[i] = *mm;
    }
    m_haveTrial = true;
    return true;
}

bool OfServer::tickUntilMeasured(std::vector<std::optional<Message>>& result, std::string& why) {
    const std::size_t n = result.size();
    const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(1.0 / m_opt.rate));
    auto next = std::chrono::steady_clock::now();
    for (long guard = 0;; ++guard) {
        bool waiting = false;
        for (std::size_t i = 0; i < n; ++i)
            if (!result[i] && m_stations[i]->needsTicks())
                waiting = true;
        if (!waiting)
            break;
        if (guard > 10'000'000) {
            why = "a step did not finish";
            return false;
        }
        next += period;
        std::this_thread::sleep_until(next);
        const double late =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - next).count();
        if (late > 1.0 / m_opt.rate)
            ++m_stats.deadlineMisses;
        m_stats.maxLateness = std::max(m_stats.maxLateness, late);
        ++m_stats.ticks;
        for (std::size_t i = 0; i < n; ++i)
            if (!result[i])
                result[i] = m_stations[i]->tick();
    }
    return true;
}

bool OfServer::commitAll(std::string& why) {
    if (!m_haveTrial)
        return true; // a commit without a trial (e.g. a repeated 5) changes nothing
    for (auto& st : m_stations) {
        const Message m = st->commit(CommitMsg{st->committedSteps() + 1});
        if (!std::holds_alternative<AckMsg>(m)) {
            why = reasonOf(m);
            return false;
        }
    }
    m_haveTrial = false;
    return true;
}

std::vector<double> OfServer::daqReply(int first, int last) const {
    // [disp..., vel..., accel..., force..., time], each part as long as its daq size (6), or
    // n values (1 for time) when asked for alone (7-11); n = the client's DOFs.
    const std::size_t n = static_cast<std::size_t>(dofCount());
    const bool whole = last - first > 1;
    std::vector<double> disp, force;
    measuredDofs(disp, force);
    std::vector<double> v;
    for (int k = first; k < last; ++k) {
        const Resp r = static_cast<Resp>(k);
        const std::size_t count =
            whole ? static_cast<std::size_t>(m_sizes.daqSize(r)) : (r == Resp::Time ? 1 : n);
        for (std::size_t i = 0; i < count; ++i) {
            double x = 0.0;
            if (r == Resp::Disp)
                x = disp[i];
            else if (r == Resp::Force)
                x = force[i];
            else if (r == Resp::Time)
                x = static_cast<double>(m_stations[0]->committedSteps() + (m_haveTrial ? 1 : 0)) *
                    m_opt.dt;
            v.push_back(x);
        }
    }
    return v;
}

std::vector<double> OfServer::matrix(int action) const {
    const std::size_t n = static_cast<std::size_t>(dofCount());
    const bool initial = action == static_cast<int>(Action::GetInitialStiff);
    if (!initial && action != static_cast<int>(Action::GetTangentStiff))
        return std::vector<double>(n * n, 0.0); // damping, mass
    if (const ChannelRig* rig = channelRig()) { // diag of the actuators' tangents
        std::vector<double> K(n * n, 0.0);
        for (std::size_t i = 0; i < n; ++i) {
            K[i * n + i] = rig->lab().channelStiffness(static_cast<int>(i), initial);
        }
        return K;
    }
    std::vector<double> k(m_stations.size());
    for (std::size_t s = 0; s < m_stations.size(); ++s)
        k[s] = initial ? m_stations[s]->initialStiffness() : m_stations[s]->tangentStiffness();
    return m_opt.dofs.stiffness(k); // column-major
}

} // namespace hsmu::comms
