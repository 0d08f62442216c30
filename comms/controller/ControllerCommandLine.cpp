#include "comms/controller/ControllerCommandLine.h"

#include "comms/LinkAddress.h"
#include "core/config/PresetCatalog.h"

#include <boost/asio/ip/address.hpp>

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace hsmu::comms {

const char* ControllerCommandLine::usage() {
    return "usage: hsmu-controller --config FILE --port PORT [--bind ADDR [--insecure-plaintext]] "
           "[--pace realtime|fast] [--token-file F] [--state-file FILE | --no-state-file] "
           "[--quiet]\n"
           "                       [--tls-certificate F --tls-key F (--tls-ca F | --tls-pins F) "
           "[--tls-revoked F] [--tls-crl F]]\n"
           "                       [--protocol native|simapp|generictcp] [--data-size N] "
           "[--simapp-site] [--realtime-priority P] [--reply-delay MS]\n"
           "       hsmu-controller --rths FILE|PRESET --port PORT [--bind ADDR] [--pace realtime|fast]\n"
           "                       [--token-file F] [--realtime-priority P] [--spin-us N] [--monitor-loss hold|continue]\n"
           "                       [--record DIR]\n"
           "  --rths FILE     run the whole RTHS loop of this RTHS configuration (or\n"
           "                  rths-benchmark-case-1 .. -4) on the controller; a console\n"
           "                  monitors it (`hsmu rths --controller`; docs/rths.md)\n"
           "  --spin-us N     RTHS, real-time pace: busy-wait the last N microseconds before\n"
           "                  each tick's release instead of sleeping (0: sleep only; default a\n"
           "                  quarter of the period, at most 100)\n"
           "  --monitor-loss P\n"
           "                  RTHS: when the monitor's link is lost during a run, hold the\n"
           "                  loop (hold, default) or let it run on (continue)\n"
           "  --record DIR    RTHS: write each run's every tick to DIR/record.h5 (the second\n"
           "                  run's to DIR/record-2.h5, ...) on this machine, as `hsmu rths`\n"
           "  --config FILE   the console's test configuration (JSON) or a preset name\n"
           "                  (e.g. paper-condition-3); its experimental\n"
           "                  elements' specimen sections and the optional controller section\n"
           "  --port PORT     TCP port, 0 = any free port (printed on stdout)\n"
           "  --bind ADDR     address to listen on (default 127.0.0.1); without TLS the\n"
           "                  native protocol is plaintext: a non-loopback address is refused\n"
           "                  unless --tls-certificate or --insecure-plaintext\n"
           "  --insecure-plaintext\n"
           "                  accept a non-loopback --bind for the plaintext native\n"
           "                  protocol (the token and commands cross the network in clear)\n"
           "  --tls-certificate F, --tls-key F\n"
           "                  native protocol in TLS 1.3 (tls://): this controller's\n"
           "                  certificate and key (PEM; the key readable by its owner only)\n"
           "  --tls-ca F      clients must show a certificate this CA signed ...\n"
           "  --tls-pins F    ... or one whose SHA-256 fingerprint F lists (one a line)\n"
           "  --tls-revoked F fingerprints refused even under the CA (one a line)\n"
           "  --tls-crl F     the CA's revocation list (PEM; scripts/hsmu-certs.sh revoke):\n"
           "                  certificates it lists are refused. SIGHUP re-reads every\n"
           "                  TLS file (docs/security.md)\n"
           "  --pace P        realtime (wall clock, default) or fast (simulated clock)\n"
           "  --token-file F  file holding the shared secret the console's hello must carry\n"
           "                  (or the environment variable HSMU_CONTROLLER_TOKEN; never an\n"
           "                  argument: arguments show in ps)\n"
           "  --state-file FILE\n"
           "                  journal of committed steps: a restart continues the specimen\n"
           "                  (--state FILE is the same); default\n"
           "                  $XDG_STATE_HOME/hsmu/controller/CONFIG-PORT.state\n"
           "                  ($XDG_STATE_HOME: ~/.local/state when unset) for a fixed\n"
           "                  port; none with --port 0\n"
           "  --no-state-file keep no journal (a restarted controller starts afresh)\n"
           "  --quiet         no session log on stderr\n"
           "  --protocol P    native (default), simapp (OpenFresco SimApp element server) or\n"
           "                  generictcp (a server for OpenFresco's expControl GenericTCP);\n"
           "                  default: the configuration's controller.protocol\n"
           "  --data-size N   OpenFresco doubles per frame (default: controller.dataSize, 256)\n"
           "  --simapp-site   SimApp: answer as a site server (no replies to actions 12-15)\n"
           "  --realtime-priority P\n"
           "                  native protocol, real-time pace: run the 1024 Hz loop under\n"
           "                  SCHED_FIFO priority P (1..99; needs root or CAP_SYS_NICE)\n"
           "  --reply-delay MS\n"
           "                  native protocol: send every measurement MS milliseconds\n"
           "                  (0..1000) after its target arrived, like a distant lab (tests\n"
           "                  and benchmarks of sites; never for a real specimen)\n";
}

std::optional<ControllerCommandLine> ControllerCommandLine::parse(int argc, const char* const* argv,
                                                                  std::string& error) {
    ControllerCommandLine c;
    bool havePort = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&](std::string& out) {
            if (i + 1 >= argc) {
                error = a + " needs a value";
                return false;
            }
            out = argv[++i];
            return true;
        };
        std::string v;
        if (a == "--help" || a == "-h") {
            c.help = true;
        } else if (a == "--quiet") {
            c.quiet = true;
        } else if (a == "--simapp-site") {
            c.siteServer = true;
        } else if (a == "--protocol") {
            if (!value(c.protocol))
                return std::nullopt;
            if (c.protocol != "native" && c.protocol != "simapp" && c.protocol != "generictcp") {
                error =
                    "--protocol: expected native, simapp or generictcp, found '" + c.protocol + "'";
                return std::nullopt;
            }
        } else if (a == "--data-size") {
            if (!value(v))
                return std::nullopt;
            char* end = nullptr;
            const long n = std::strtol(v.c_str(), &end, 10);
            if (v.empty() || *end != '\0' || n < 1 || n > (1L << 20)) {
                error = "--data-size: expected 1..1048576 doubles, found '" + v + "'";
                return std::nullopt;
            }
            c.dataSize = static_cast<int>(n);
        } else if (a == "--realtime-priority") {
            if (!value(v))
                return std::nullopt;
            char* end = nullptr;
            const long p = std::strtol(v.c_str(), &end, 10);
            if (v.empty() || *end != '\0' || p < 1 || p > 99) {
                error = "--realtime-priority: expected 1..99, found '" + v + "'";
                return std::nullopt;
            }
            c.realTimePriority = static_cast<int>(p);
        } else if (a == "--spin-us") {
            if (!value(v))
                return std::nullopt;
            char* end = nullptr;
            const double us = std::strtod(v.c_str(), &end);
            if (v.empty() || *end != '\0' || !(us >= 0.0 && us <= 1e6)) {
                error = "--spin-us: expected 0..1000000 microseconds, found '" + v + "'";
                return std::nullopt;
            }
            c.spinMicros = us;
        } else if (a == "--reply-delay") {
            if (!value(v))
                return std::nullopt;
            char* end = nullptr;
            const double ms = std::strtod(v.c_str(), &end);
            if (v.empty() || *end != '\0' || !(ms >= 0.0 && ms <= 1000.0)) {
                error = "--reply-delay: expected 0..1000 milliseconds, found '" + v + "'";
                return std::nullopt;
            }
            c.replyDelay = ms * 1e-3;
        } else if (a == "--rths") {
            if (!value(c.rths))
                return std::nullopt;
        } else if (a == "--record") {
            if (!value(c.record))
                return std::nullopt;
            if (c.record.empty()) {
                error = "--record: expected a folder";
                return std::nullopt;
            }
        } else if (a == "--monitor-loss") {
            if (!value(v))
                return std::nullopt;
            if (v != "hold" && v != "continue") {
                error = "--monitor-loss: expected hold or continue, found '" + v + "'";
                return std::nullopt;
            }
            c.monitorLossHolds = v == "hold";
        } else if (a == "--config") {
            if (!value(c.config))
                return std::nullopt;
        } else if (a == "--bind") {
            if (!value(c.bind))
                return std::nullopt;
        } else if (a == "--tls-certificate" || a == "--tls-key" || a == "--tls-ca" ||
                   a == "--tls-pins" || a == "--tls-revoked" || a == "--tls-crl") {
            if (!c.tls)
                c.tls.emplace();
            std::string& field = a == "--tls-certificate" ? c.tls->certificate
                                 : a == "--tls-key"       ? c.tls->key
                                 : a == "--tls-ca"        ? c.tls->ca
                                 : a == "--tls-pins"      ? c.tls->pinsFile
                                 : a == "--tls-crl"       ? c.tls->crl
                                                          : c.tls->revokedFile;
            if (!value(field))
                return std::nullopt;
        } else if (a == "--insecure-plaintext") {
            c.insecurePlaintext = true;
        } else if (a == "--token") {
            error = "--token is not accepted: arguments show in ps; put the token in a file "
                    "(--token-file FILE) or in the environment variable HSMU_CONTROLLER_TOKEN";
            return std::nullopt;
        } else if (a == "--token-file") {
            if (!value(c.tokenFile))
                return std::nullopt;
        } else if (a == "--state" || a == "--state-file") {
            if (!value(c.state))
                return std::nullopt;
        } else if (a == "--no-state-file") {
            c.noStateFile = true;
        } else if (a == "--port") {
            if (!value(v))
                return std::nullopt;
            char* end = nullptr;
            const long p = std::strtol(v.c_str(), &end, 10);
            if (v.empty() || *end != '\0' || p < 0 || p > 65535) {
                error = "--port: expected 0..65535, found '" + v + "'";
                return std::nullopt;
            }
            c.port = static_cast<std::uint16_t>(p);
            havePort = true;
        } else if (a == "--pace") {
            if (!value(v))
                return std::nullopt;
            if (v != "realtime" && v != "fast") {
                error = "--pace: expected realtime or fast, found '" + v + "'";
                return std::nullopt;
            }
            c.fast = v == "fast";
        } else {
            error = "unknown argument '" + a + "'";
            return std::nullopt;
        }
    }
    if (c.help)
        return c;
    if (!c.rths.empty() && !c.config.empty()) {
        error = "--rths and --config exclude each other (an RTHS loop or specimens)";
        return std::nullopt;
    }
    if (!c.record.empty() && c.rths.empty()) {
        error = "--record DIR applies to --rths (a specimen's record is the console's)";
        return std::nullopt;
    }
    if (c.config.empty() && c.rths.empty()) {
        error = "--config FILE (or --rths FILE) is required";
        return std::nullopt;
    }
    if (!havePort) {
        error = "--port PORT is required (0 = any free port)";
        return std::nullopt;
    }
    if (c.noStateFile && !c.state.empty()) {
        error = "--no-state-file and --state-file " + c.state + " contradict each other";
        return std::nullopt;
    }
    if (!c.config.empty())
        c.config = resolveConfig(c.config);
    return c;
}

std::string ControllerCommandLine::defaultStateFile(const std::string& config, std::uint16_t port) {
    namespace fs = std::filesystem;
    fs::path base;
    const char* xdg = std::getenv("XDG_STATE_HOME");
    const char* home = std::getenv("HOME");
    if (xdg && *xdg && fs::path(xdg).is_absolute()) // the spec: relative values are ignored
        base = xdg;
    else if (home && *home)
        base = fs::path(home) / ".local" / "state";
    else
        return {};
    std::string stem = fs::path(config).stem().string();
    if (stem.empty())
        stem = "controller";
    return (base / "hsmu" / "controller" / (stem + "-" + std::to_string(port) + ".state")).string();
}

std::string ControllerCommandLine::stateFile() const {
    if (!state.empty() || noStateFile || port == 0) // port 0: a restart listens elsewhere
        return state;
    return defaultStateFile(config, port);
}

std::string ControllerCommandLine::resolveConfig(const std::string& configOrPreset) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::exists(configOrPreset, ec) || configOrPreset.find('/') != std::string::npos)
        return configOrPreset;
    std::vector<std::string> dirs;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) // installed: PREFIX/bin/hsmu-controller -> PREFIX/share/hsmu/presets
        dirs.push_back((exe.parent_path().parent_path() / "share" / "hsmu" / "presets").string());
#ifdef HSMU_PRESET_SOURCE_DIR
    dirs.emplace_back(HSMU_PRESET_SOURCE_DIR); // a build tree
#endif
    if (auto file = presetFile(configOrPreset, dirs))
        return *file;
    return configOrPreset; // the loader's error names it
}

bool ControllerCommandLine::isLoopback(const std::string& address) {
    return isLoopbackAddress(address);
}

} // namespace hsmu::comms
