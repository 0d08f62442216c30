#include "comms/controller/ControllerApp.h"

#include "comms/controller/ControllerSettings.h"
#include "core/config/ConfigLoader.h"
#include "core/config/RthsConfig.h"
#include "core/rths/RthsReport.h"
#include "core/util/SecretFile.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace hsmu::comms {

ControllerApp::ControllerApp(ControllerCommandLine commandLine) : m_cmd(std::move(commandLine)) {}

ControllerApp::~ControllerApp() = default;

namespace {

/// The token (linkToken: --token-file, else HSMU_CONTROLLER_TOKEN, else none).
bool readToken(const std::string& tokenFile, std::string& token, std::string& error) {
    const auto secret = linkToken(tokenFile, error);
    if (!secret) {
        error += " (--token-file)";
        return false;
    }
    token = *secret;
    return true;
}

} // namespace

bool ControllerApp::startRths(const std::string& token, std::string& error) {
    if (!ControllerCommandLine::isLoopback(m_cmd.bind) && !m_cmd.insecurePlaintext) {
        m_usageRefused = true;
        error = "--bind " + m_cmd.bind +
                " is not a loopback address, and the native protocol is plaintext: keep --bind "
                "127.0.0.1 and tunnel the port (docs/security.md), or pass --insecure-plaintext";
        return false;
    }
    RthsJob job;
    try {
        const RthsConfig cfg = loadRthsConfig(m_cmd.rths);
        job.name = cfg.name;
        job.settings = cfg.settings;
        rths::fitToNominalLoop(job.settings);
        job.partition = cfg.partition();
        job.groundMotion = loadRthsGroundMotion(cfg, "", cfg.groundMotionScale);
        job.holdAfterMisses = cfg.holdAfterMisses;
        job.identification = cfg.identification;
        job.configuration = cfg.raw.dump();
        const rths::Preflight pre = rths::preflight(job.partition, job.settings);
        std::fprintf(stderr, "hsmu-controller: pre-flight: %s\n", pre.message.c_str());
        if (pre.refused) {
            error = "refused in pre-flight: " + pre.message;
            return false;
        }
    } catch (const std::exception& e) { // ConfigError, ground-motion errors
        error = e.what();
        return false;
    }
    RthsServerOptions o;
    o.bind = m_cmd.bind;
    o.port = m_cmd.port;
    o.token = token;
    o.realTime = !m_cmd.fast;
    o.realTimePriority = m_cmd.realTimePriority;
    o.spinMicros = m_cmd.spinMicros;
    o.quiet = m_cmd.quiet;
    o.holdOnMonitorLoss = m_cmd.monitorLossHolds;
    o.recordDirectory = m_cmd.record;
    m_rthsServer = std::make_unique<RthsServer>(o, std::move(job));
    if (!m_rthsServer->listen(error))
        return false;
    std::printf("hsmu-controller: listening on %s:%u (%s, %s pace)\n", m_cmd.bind.c_str(),
                unsigned(port()), m_rthsServer->describe().c_str(),
                m_cmd.fast ? "fast" : "real-time");
    std::fflush(stdout);
    return true;
}

bool ControllerApp::start(std::string& error) {
    std::vector<std::unique_ptr<SpecimenStation>> stations;
    std::string token;
    if (!readToken(m_cmd.tokenFile, token, error))
        return false;
    if (!m_cmd.rths.empty())
        return startRths(token, error);
    ControllerSettings settings;
    std::string protocol = m_cmd.protocol;
    int dataSize = m_cmd.dataSize;
    double dt = 0.0;
    OfDofMap dofs;
    try {
        const TestConfig cfg = loadConfigFile(m_cmd.config);
        settings = parseControllerSettings(cfg);
        if (protocol.empty())
            protocol = cfg.link.protocol;
        if (dataSize == 0)
            dataSize = cfg.link.dataSize;
        dt = cfg.analysis.dt;
        m_cmd.state = m_cmd.stateFile(); // --state-file, the default one, or none
        if (!m_cmd.state.empty()) {
            m_journal = std::make_unique<StateJournal>();
            std::error_code ec; // the default folder may not exist yet
            std::filesystem::create_directories(std::filesystem::path(m_cmd.state).parent_path(),
                                                ec);
            if (!m_cmd.quiet)
                std::fprintf(stderr, "hsmu-controller: state file %s\n", m_cmd.state.c_str());
        }
        std::vector<JournalElement> identities;
        const auto pace =
            m_cmd.fast ? SpecimenStation::Pace::Fast : SpecimenStation::Pace::RealTime;
        const auto& rawElements = cfg.raw.at("structure").at("elements");
        std::string linkOverOpenFresco; // a link2d specimen served over an OpenFresco protocol
        for (std::size_t i = 0; i < cfg.elements.size(); ++i) {
            const ElementSpec& e = cfg.elements[i];
            if (!e.experimental)
                continue;
            if (e.link2d && protocol != "native" && !protocol.empty())
                linkOverOpenFresco = e.name;
            const int index = static_cast<int>(stations.size());
            stations.push_back(
                std::make_unique<SpecimenStation>(index, e, settings, pace, m_journal.get()));
            const auto& raw = rawElements.at(i);
            identities.push_back(
                {e.name, StateJournal::fingerprint(
                             e.name + "\n" + (e.link2d ? raw : raw.at("specimen")).dump())});
            m_names += (m_names.empty() ? "" : ", ") + e.name;
        }
        if (stations.empty()) {
            error = m_cmd.config + ": no experimental element (\"experimental\": true) to emulate";
            return false;
        }
        // An OpenFresco server gives a link2d specimen's channels to its client as its DOFs
        // (OfServer.h): that specimen alone, without controller.serverDofs.
        const bool serverDofs = cfg.raw.contains("controller") &&
                                cfg.raw.at("controller").is_object() &&
                                cfg.raw.at("controller").contains("serverDofs");
        if (!linkOverOpenFresco.empty() && (stations.size() > 1 || serverDofs)) {
            error = m_cmd.config + ": element '" + linkOverOpenFresco +
                    "': a link2d specimen (several actuator channels) is served over --protocol " +
                    protocol + " alone, its channels the client's DOFs: " +
                    (serverDofs ? std::string("remove controller.serverDofs")
                                : "serve the other experimental elements by another "
                                  "hsmu-controller, or use the native protocol") +
                    " (docs/setups.md, \"hsmu-controller\")";
            return false;
        }
        std::vector<std::string> names;
        for (const auto& st : stations)
            names.push_back(st->name());
        dofs = OfDofMap::parse(cfg.raw.contains("controller") ? cfg.raw.at("controller")
                                                              : nlohmann::json(),
                               names, m_cmd.config);
        if (m_journal) {
            std::vector<JournalRecord> records;
            if (!m_journal->open(m_cmd.state, identities, records, error))
                return false;
            for (const JournalRecord& r : records)
                if (!stations[static_cast<std::size_t>(r.element)]->replay(r, error)) {
                    error = m_cmd.state + ": " + error;
                    return false;
                }
        }
    } catch (const std::exception& e) { // ConfigError, json errors
        error = e.what();
        return false;
    }
    for (const auto& st : stations)
        if (st->committedSteps() > 0)
            std::fprintf(stderr,
                         "hsmu-controller: specimen '%s' continues after step %llu (state file "
                         "%s; --no-state-file, or delete it, for a fresh specimen)\n",
                         st->name().c_str(), static_cast<unsigned long long>(st->committedSteps()),
                         m_cmd.state.c_str());
    const bool exposed = !ControllerCommandLine::isLoopback(m_cmd.bind);
    if (m_cmd.tls && protocol != "native") {
        m_usageRefused = true;
        error = "--tls-* options apply to the native protocol only (the OpenFresco protocols "
                "carry no security: tunnel them, docs/security.md)";
        return false;
    }
    if (m_cmd.tls && m_cmd.insecurePlaintext) {
        m_usageRefused = true;
        error = "--insecure-plaintext contradicts the --tls-* options: choose one";
        return false;
    }
    if (m_cmd.tls && !checkTlsSpec(*m_cmd.tls, error)) {
        m_usageRefused = true;
        error = "--tls-*: " + error;
        return false;
    }
    if (exposed && protocol == "native" && !m_cmd.tls && !m_cmd.insecurePlaintext) {
        m_usageRefused = true;
        error = "--bind " + m_cmd.bind +
                " is not a loopback address, and without TLS the native protocol is plaintext: "
                "the token and every command would cross the network in clear, readable and "
                "forgeable on the path. Use TLS (--tls-certificate F --tls-key F --tls-ca F; "
                "scripts/hsmu-certs.sh makes them; docs/security.md), or keep --bind 127.0.0.1 "
                "and tunnel the port, or pass --insecure-plaintext to take that risk on a "
                "network you trust";
        return false;
    }
    if (exposed && protocol == "native" && !m_cmd.tls)
        std::fprintf(stderr,
                     "hsmu-controller: --insecure-plaintext: the native protocol runs in clear "
                     "on %s (token and commands readable and forgeable on the path)%s\n",
                     m_cmd.bind.c_str(),
                     token.empty() ? "; and no token: anyone who reaches the port can command "
                                     "the specimen"
                                   : "");
    if (exposed && protocol != "native")
        std::fprintf(stderr,
                     "hsmu-controller: warning: the OpenFresco protocols carry no security at "
                     "all (no token, no encryption) and %s is not a loopback address: anyone "
                     "who reaches the port can command the specimen; listen on 127.0.0.1 and "
                     "tunnel it (docs/security.md)\n",
                     m_cmd.bind.c_str());
    const std::size_t count = stations.size();
    std::string what;
    if (protocol != "native") {
        OfServerOptions o;
        o.bind = m_cmd.bind;
        o.port = m_cmd.port;
        o.protocol = protocol == "simapp" ? of::OfProtocol::SimApp : of::OfProtocol::GenericTcp;
        o.siteServer = m_cmd.siteServer;
        o.dataSize = dataSize;
        o.dt = dt;
        o.realTime = !m_cmd.fast;
        o.rate = settings.rate;
        o.quiet = m_cmd.quiet;
        o.idleTimeout = settings.idleTimeout;
        o.dofs = dofs;
        if (!token.empty())
            std::fprintf(stderr, "hsmu-controller: the token is ignored: the OpenFresco "
                                 "protocols carry no token\n");
        if (m_cmd.realTimePriority > 0)
            std::fprintf(stderr, "hsmu-controller: --realtime-priority applies to the native "
                                 "protocol only; ignored\n");
        if (m_cmd.replyDelay > 0.0)
            std::fprintf(stderr, "hsmu-controller: --reply-delay applies to the native "
                                 "protocol only; ignored\n");
        m_ofServer = std::make_unique<OfServer>(o, std::move(stations));
        if (!m_ofServer->listen(error))
            return false;
        what = m_ofServer->describe() + ", ";
    } else {
        ControllerServerOptions o;
        o.bind = m_cmd.bind;
        o.port = m_cmd.port;
        o.token = token;
        o.tls = m_cmd.tls;
        o.idleTimeout = settings.idleTimeout;
        o.rate = settings.rate;
        o.realTime = !m_cmd.fast;
        o.realTimePriority = m_cmd.realTimePriority;
        o.quiet = m_cmd.quiet;
        o.replyDelay = m_cmd.replyDelay;
        m_server = std::make_unique<ControllerServer>(o, std::move(stations));
        if (!m_server->listen(error))
            return false;
        if (m_cmd.tls)
            what = std::string("TLS 1.3, client certificates from ") +
                   (m_cmd.tls->ca.empty() ? "the pins" : m_cmd.tls->ca) +
                   (token.empty() ? "" : " and the token") + ", ";
    }
    std::printf("hsmu-controller: listening on %s:%u (%s%s pace, %zu specimen%s: %s)\n",
                m_cmd.bind.c_str(), unsigned(port()), what.c_str(),
                m_cmd.fast ? "fast" : "real-time", count, count == 1 ? "" : "s", m_names.c_str());
    std::fflush(stdout);
    return true;
}

std::uint16_t ControllerApp::port() const {
    return m_server       ? m_server->port()
           : m_ofServer   ? m_ofServer->port()
           : m_rthsServer ? m_rthsServer->port()
                          : 0;
}

int ControllerApp::run() {
    if (m_rthsServer) {
        m_rthsServer->run();
        std::printf("hsmu-controller: stopped\n");
        std::fflush(stdout);
        return 0;
    }
    if (m_ofServer)
        m_ofServer->run();
    else
        m_server->run();
    const ControllerStatistics s = m_ofServer ? m_ofServer->statistics() : m_server->statistics();
    std::printf(
        "hsmu-controller: stopped; %lld ticks, %lld deadline misses (max lateness %.3f ms), "
        "%lld sessions admitted, %lld refused\n",
        s.ticks, s.deadlineMisses, s.maxLateness * 1e3, s.sessionsAdmitted, s.sessionsRefused);
    std::fflush(stdout);
    return 0;
}

} // namespace hsmu::comms
