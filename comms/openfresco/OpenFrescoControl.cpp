#include "comms/openfresco/OpenFrescoControl.h"

#include "comms/openfresco/OfFrame.h"
#include "comms/openfresco/OfSocket.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>
#include <utility>

namespace hsmu::comms::of {

const char* ofProtocolName(OfProtocol p) {
    return p == OfProtocol::SimApp ? "simapp" : p == OfProtocol::Adapter ? "adapter" : "generictcp";
}

OpenFrescoControl::OpenFrescoControl(OfProtocol protocol, std::string host, std::uint16_t port,
                                     std::string element, OfControlOptions options)
    : m_protocol(protocol), m_socket(std::make_unique<OfSocket>()), m_host(std::move(host)),
      m_port(port), m_element(std::move(element)), m_opt(std::move(options)) {}

OpenFrescoControl::~OpenFrescoControl() {
    if (m_socket->isOpen() && sendRequest(static_cast<int>(Action::Terminate), {}).ok)
        m_socket->closeAfterPeer(2.0); // the server's port is not left in TIME_WAIT
    m_socket->close();
}

std::string OpenFrescoControl::where() const {
    const bool v6 = m_host.find(':') != std::string::npos;
    return std::string(ofProtocolName(m_protocol)) + "://" + (v6 ? "[" + m_host + "]" : m_host) +
           ":" + std::to_string(m_port);
}

std::string OpenFrescoControl::description() const {
    return std::string(m_protocol == OfProtocol::SimApp    ? "OpenFresco SimApp"
                       : m_protocol == OfProtocol::Adapter ? "OpenSees adapter element"
                                                           : "OpenFresco GenericTCP") +
           " link " + where() + " for specimen '" + m_element + "' (" + m_opt.sizes.describe() +
           ")";
}

bool OpenFrescoControl::linkUp() const {
    return m_socket->isOpen();
}

ControlResult OpenFrescoControl::linkFault(const std::string& what) {
    m_socket->close();
    m_linkError = what;
    m_awaitingMeasurement = false;
    if (m_emergency.load(std::memory_order_acquire))
        m_linkError = emergencyText() + " (connection closed)";
    return ControlResult::fault("link to " + where() + ": " + m_linkError);
}

std::string OpenFrescoControl::emergencyText() const {
    std::lock_guard lock(m_emergencyMutex);
    return "emergency hold: " + m_emergencyReason;
}

void OpenFrescoControl::emergencyHold(const std::string& reason) {
    {
        std::lock_guard lock(m_emergencyMutex);
        m_emergencyReason = reason.empty() ? std::string("operator") : reason;
    }
    m_emergency.store(true, std::memory_order_release);
    m_socket->interrupt();
}

std::optional<ActuatorChannels> OpenFrescoControl::actuatorChannels() const {
    return m_channels;
}

ControlResult OpenFrescoControl::sendRequest(int action, const std::vector<double>& values) {
    std::string error;
    if (!encodeRequest(static_cast<Action>(action), values, m_opt.sizes.dataSize, m_buffer, error))
        return ControlResult::fault("link to " + where() + ": " + error);
    if (!m_socket->write(m_buffer.data(), m_buffer.size(), m_opt.stepDeadline, error))
        return linkFault(error);
    return ControlResult::success();
}

ControlResult OpenFrescoControl::connectOnce() {
    std::string error;
    m_connectFailed = false;
    if (!m_socket->connect(m_host, m_port, m_opt.connectTimeout, error)) {
        m_connectFailed = true;
        m_linkError = error;
        return ControlResult::fault("link to " + where() + ": " + error);
    }
    const auto header = encodeSizes(m_opt.sizes);
    if (!m_socket->write(header.data(), header.size(), m_opt.stepDeadline, error))
        return linkFault("sending the sizes header: " + error);
    if (m_protocol == OfProtocol::GenericTcp)
        for (const std::string& line : m_opt.initLines) {
            std::vector<std::uint8_t> bytes;
            if (!encodeInitLine(line, bytes, error))
                return linkFault(error);
            if (!m_socket->write(bytes.data(), bytes.size(), m_opt.stepDeadline, error))
                return linkFault("sending the init lines: " + error);
        }
    if (m_protocol == OfProtocol::Adapter) {
        // No probe: the adapter takes only 3 (then 10) and 99; anything else ends OpenSees.
        if (m_opt.logConnect)
            std::fprintf(stderr, "hsmu: %s connected, specimen '%s': %s\n", where().c_str(),
                         m_element.c_str(), m_opt.sizes.describe().c_str());
        m_linkError.clear();
        return ControlResult::success();
    }
    // The probe: a whole reply of dataSize doubles proves the server took the header.
    if (ControlResult r = sendRequest(static_cast<int>(Action::GetDaqResponse), {}); !r.ok)
        return r;
    m_buffer.resize(static_cast<std::size_t>(m_opt.sizes.dataSize) * sizeof(double));
    if (!m_socket->read(m_buffer.data(), m_buffer.size(), m_opt.stepDeadline, error)) {
        // A closed or reset connection: the server refused the header (an OpenFresco element
        // server exits when the sizes do not fit its element).
        const bool refused = m_socket->closedByPeer() || error.find("reset") != std::string::npos;
        const std::string n = std::to_string(m_opt.sizes.ctrlSize(Resp::Disp));
        return linkFault(
            refused ? "the server closed the connection after the sizes header (" +
                          m_opt.sizes.describe() +
                          "): it does not accept these sizes. This console sends ctrl disp " + n +
                          " (one DOF); an OpenFresco element server needs ctrl disp, daq disp "
                          "and daq force equal to its element's DOF count (a twoNodeLink on 2 "
                          "nodes has 2: its log says \"want: 2 but got: " +
                          n +
                          "\"; serve such a specimen by a site server, startSimAppSiteServer, "
                          "or a one-node expElement generic), a site server its setup's sizes; "
                          "make controller.dataSize, controller.ctrlSizes and "
                          "controller.daqSizes match the server's"
                    : "no answer to the first getDaqResponse (" + m_opt.sizes.describe() +
                          "): " + error + "; a server with another dataSize waits for more bytes");
    }
    decodeFrame(m_buffer.data(), m_opt.sizes.dataSize, m_values);
    if (std::any_of(m_values.begin(), m_values.end(), [](double x) { return std::isnan(x); }))
        return linkFault("the server refused the sizes header (" + m_opt.sizes.describe() +
                         "): it answers NaN (hsmu-controller's polite refusal; its log names "
                         "the reason); make controller.dataSize and the sizes match the "
                         "server's");
    if (m_protocol == OfProtocol::GenericTcp) {
        // hsmu-controller marks its probe reply (OfFrame.h): a SimApp server of ours is refused
        // outright, a GenericTCP server of ours commits on its own; anything else is warned.
        const double mark = m_values.empty() ? 0.0 : m_values.back();
        if (mark == kMarkSimAppServer) {
            const std::string simapp = "simapp" + where().substr(where().find("://"));
            if (sendRequest(static_cast<int>(Action::Terminate), {}).ok)
                m_socket->closeAfterPeer(2.0);
            return linkFault(
                "refused: this server is hsmu-controller serving SimApp (--protocol simapp), "
                "which needs a commit after every step; GenericTCP sends none, so its "
                "specimens would never be committed and every force would be wrong. Connect "
                "with " + simapp + " (or start hsmu-controller with --protocol generictcp)");
        }
        if (mark != kMarkGenericTcpServer) {
            m_pairingWarning =
                where() +
                ": GenericTCP has no commit; the server must take each trial as final when the "
                "next one arrives (as hsmu-controller --protocol generictcp and lab GenericTCP "
                "controllers do). An OpenFresco SimApp site or element server "
                "(startSimAppSiteServer / startSimAppElemServer) never commits its specimen over "
                "GenericTCP and every force is silently wrong: use simapp:// for it.";
            if (m_opt.warnNoCommit)
                std::fprintf(stderr, "hsmu: WARNING %s\n", m_pairingWarning.c_str());
            m_notice = m_notice.empty() ? m_pairingWarning : m_notice + "; " + m_pairingWarning;
        }
    }
    if (m_opt.logConnect)
        std::fprintf(stderr, "hsmu: %s connected, specimen '%s': %s\n", where().c_str(),
                     m_element.c_str(), m_opt.sizes.describe().c_str());
    m_linkError.clear();
    return ControlResult::success();
}

ControlResult OpenFrescoControl::prepare(double dt) {
    if (!(dt > 0.0))
        return ControlResult::fault(where() + ": dt must be > 0");
    if (auto why = m_opt.sizes.problem())
        return ControlResult::fault(where() + ": " + *why);
    if (m_opt.sizes.ctrlSize(Resp::Disp) < 1 || m_opt.sizes.daqSize(Resp::Disp) < 1 ||
        m_opt.sizes.daqSize(Resp::Force) < 1)
        return ControlResult::fault(where() +
                                    ": the sizes need ctrl disp, daq disp and daq "
                                    "force of at least 1 (" +
                                    m_opt.sizes.describe() + ")");
    if (auto why = channelProblem())
        return ControlResult::fault(where() + ": specimen '" + m_element + "': " + *why);
    if (m_protocol == OfProtocol::Adapter &&
        (m_opt.sizes.daqSize(Resp::Vel) != 0 || m_opt.sizes.daqSize(Resp::Accel) != 0 ||
         m_opt.sizes.daqSize(Resp::Time) != 0 || m_opt.sizes.ctrlSize(Resp::Disp) != 1 ||
         m_opt.sizes.daqSize(Resp::Disp) != 1 || m_opt.sizes.daqSize(Resp::Force) != 1))
        return ControlResult::fault(where() +
                                    ": OpenSees' adapter element answers [daq disp, daq force] "
                                    "only; use controller.ctrlSizes {disp 1} and "
                                    "controller.daqSizes {disp 1, force 1} (" +
                                    m_opt.sizes.describe() + ")");
    m_dt = dt;
    ControlResult r;
    for (int i = 0; i < std::max(1, m_opt.connectAttempts); ++i) {
        if (i > 0)
            std::this_thread::sleep_for(std::chrono::duration<double>(m_opt.retryDelay));
        r = connectOnce();
        if (r.ok || !m_connectFailed)
            break;
    }
    return r;
}

ControlResult OpenFrescoControl::trialAllowed() {
    if (m_emergency.load(std::memory_order_acquire))
        return ControlResult::fault(where() + ": " + emergencyText());
    if (m_holding)
        return ControlResult::fault(where() + " is holding: " + m_holdReason);
    if (!m_socket->isOpen())
        return ControlResult::fault(
            "link to " + where() + " is down (" + m_linkError +
            "); OpenFresco protocols cannot resume a lost session: restart the test");
    if (m_protocol != OfProtocol::SimApp && m_measuredUncommitted)
        return ControlResult::fault(where() + ": " + ofProtocolName(m_protocol) +
                                    " has no commit, so a measured step cannot be "
                                    "repeated; restart the test");
    return ControlResult::success();
}

ControlResult OpenFrescoControl::sendTrial(std::vector<double>& ctrl) {
    const OfSizes& s = m_opt.sizes;
    if (s.ctrlSize(Resp::Time) > 0)
        ctrl[static_cast<std::size_t>(s.ctrlIndex(Resp::Time) - 1)] =
            static_cast<double>(m_committed + 1) * m_dt;
    if (ControlResult r = sendRequest(static_cast<int>(Action::SetTrialResponse), ctrl); !r.ok)
        return r;
    // The response is asked for at once (the same frames, in the same order, as asking in
    // measure()), so that with several sites every site works while the others are asked:
    // measure() only reads the reply (docs/configuration.md "Sites").
    const Action ask =
        m_protocol == OfProtocol::Adapter ? Action::GetForce : Action::GetDaqResponse;
    if (ControlResult r = sendRequest(static_cast<int>(ask), {}); !r.ok)
        return r;
    m_awaitingMeasurement = true;
    return ControlResult::success();
}

ControlResult OpenFrescoControl::setTarget(double d) {
    if (ControlResult r = trialAllowed(); !r.ok)
        return r;
    const OfSizes& s = m_opt.sizes;
    std::vector<double> ctrl(static_cast<std::size_t>(s.ctrlTotal()), 0.0);
    ctrl[static_cast<std::size_t>(s.ctrlIndex(Resp::Disp) - 1)] = d;
    if (ControlResult r = sendTrial(ctrl); !r.ok)
        return r;
    m_target = d;
    return ControlResult::success();
}

ControlResult OpenFrescoControl::readReply() {
    if (!m_awaitingMeasurement)
        return ControlResult::fault(where() + ": measure() without a target");
    m_awaitingMeasurement = false;
    std::string error;
    m_buffer.resize(static_cast<std::size_t>(m_opt.sizes.dataSize) * sizeof(double));
    if (!m_socket->read(m_buffer.data(), m_buffer.size(), m_opt.stepDeadline, error))
        return linkFault("no measurement for step " + std::to_string(m_committed + 1) + ": " +
                         error);
    decodeFrame(m_buffer.data(), m_opt.sizes.dataSize, m_values);
    return ControlResult::success();
}

ControlResult OpenFrescoControl::measure(ControlMeasurement& out) {
    if (ControlResult r = readReply(); !r.ok)
        return r;
    const double d = m_values[static_cast<std::size_t>(m_opt.sizes.daqIndex(Resp::Disp))];
    const double f = m_values[static_cast<std::size_t>(m_opt.sizes.daqIndex(Resp::Force))];
    if (!std::isfinite(d) || !std::isfinite(f))
        return linkFault("the measured response of step " + std::to_string(m_committed + 1) +
                         " is not finite");
    if (d == 0.0 && m_target != 0.0 && !m_zeroDisp) {
        m_zeroDisp = true;
        m_notice = "the daq displacement of " + where() + " reads exactly 0 while the target is " +
                   std::to_string(m_target) +
                   " (an OpenFresco element server always answers 0): the commanded "
                   "deformation is used instead wherever it reads 0 (identification, limits, "
                   "record)";
        std::fprintf(stderr, "hsmu: WARNING specimen '%s': %s\n", m_element.c_str(),
                     m_notice.c_str());
    }
    ActuatorChannels c;
    c.commanded = m_target;
    c.measured = d;
    m_channels = c;
    out.deformation = m_zeroDisp && d == 0.0 ? m_target : d;
    out.force = f;
    m_measuredUncommitted = true;
    return ControlResult::success();
}

ControlResult OpenFrescoControl::commit() {
    if (!m_measuredUncommitted)
        return ControlResult::fault(where() + ": commit() without a measured step");
    if (m_protocol == OfProtocol::SimApp)
        if (ControlResult r = sendRequest(static_cast<int>(Action::CommitState), {}); !r.ok)
            return r;
    m_measuredUncommitted = false;
    ++m_committed;
    return ControlResult::success();
}

std::string OpenFrescoControl::takeNotice() {
    return std::exchange(m_notice, std::string());
}

void OpenFrescoControl::hold(const std::string& reason) {
    // OpenFresco has no hold message: no new trial is sent, which keeps the specimen where it is.
    m_holding = true;
    m_holdReason = reason;
    m_awaitingMeasurement = false;
}

void OpenFrescoControl::resume() {
    if (m_emergency.exchange(false, std::memory_order_acq_rel) && m_socket->isOpen()) {
        m_socket->close(); // shut down by the emergency hold: no session to resume
        m_linkError = "closed by an emergency hold";
    }
    m_holding = false;
    m_holdReason.clear();
}

} // namespace hsmu::comms::of
