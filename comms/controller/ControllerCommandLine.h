#pragma once
// ControllerCommandLine: the arguments of hsmu-controller.
//
//   hsmu-controller --config FILE|PRESET --port PORT [--bind ADDR] [--pace realtime|fast]
//                   [--token-file F] [--state-file FILE | --no-state-file] [--quiet]
//                   [--protocol native|simapp|generictcp] [--data-size N] [--simapp-site]
//                   [--realtime-priority P] [--tls-certificate F --tls-key F --tls-ca F
//                   --tls-pins F --tls-revoked F]
//   hsmu-controller --rths FILE|PRESET --port PORT [--bind ADDR] [--pace realtime|fast]
//                   [--token-file F] [--realtime-priority P] [--monitor-loss hold|continue]
//                   [--record DIR]
//
// --rths runs the whole RTHS loop on the controller (RthsServer; docs/rths.md) instead of
// serving specimens; --config is then not needed and there is no state file. --record DIR
// (only with --rths) writes each run's every tick to DIR/record.h5 (run N >= 2: record-N.h5).

// --port 0 picks a free port; the chosen one is printed on stdout ("listening on ADDR:PORT").
// --bind defaults to 127.0.0.1: exposing the controller is an explicit choice. The --tls-*
// options (the names of the console's "tls" block, core/config/TlsConfig.h) make the native
// protocol TLS 1.3 with client certificates. Without them it is plaintext: on a non-loopback
// address it is refused (ControllerApp, exit 2) unless --insecure-plaintext takes the risk;
// the OpenFresco protocols warn there (docs/security.md).
// The token comes from --token-file (its first line) or HSMU_CONTROLLER_TOKEN, never from an
// argument (ps shows arguments to every user); --token is refused with that sentence.
// The state file (StateJournal: a restarted controller continues every specimen) is kept by
// default: --state-file FILE (or --state FILE) names it, --no-state-file turns it off, and
// otherwise, on a fixed port, it is defaultStateFile():
// $XDG_STATE_HOME/hsmu/controller/<config>-<port>.state ($XDG_STATE_HOME defaults to
// ~/.local/state; docs/cli.md). --port 0 has no default (a restart would listen elsewhere).

#include "core/config/TlsConfig.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hsmu::comms {

struct ControllerCommandLine {
    std::string config;
    std::string bind = "127.0.0.1";
    std::uint16_t port = 0;
    bool fast = false; ///< --pace fast: simulated clock (as fast as possible)
    std::string tokenFile; ///< --token-file: the token is its first line
    bool insecurePlaintext = false; ///< native protocol in clear on a non-loopback address
    std::optional<TlsSpec> tls;     ///< any --tls-* option given: the native protocol in TLS
    std::string state;        ///< --state-file (or --state): the journal; "" = default or none
    bool noStateFile = false; ///< --no-state-file: no journal at all
    bool quiet = false;
    bool help = false;
    std::string protocol;    ///< "" = the configuration's controller.protocol (native by default)
    int dataSize = 0;        ///< OpenFresco doubles per frame; 0 = controller.dataSize (256)
    bool siteServer = false; ///< SimApp: behave as a site server (no replies to 12-15)
    int realTimePriority = 0; ///< native, real-time pace: SCHED_FIFO priority 1..99; 0 = normal
    double spinMicros = -1.0; ///< RTHS, real-time pace: busy-wait before each release [us]; < 0: default
    double replyDelay = 0.0;  ///< --reply-delay MS, in seconds (native; tests and benchmarks)
    std::string rths;         ///< --rths FILE|PRESET: the RTHS loop's configuration
    bool monitorLossHolds = true; ///< --monitor-loss hold (default) | continue (RTHS)
    std::string record;       ///< --record DIR: the RTHS runs' records (RTHS); "" = none

    /// nullopt with a sentence in error when the arguments are wrong.
    static std::optional<ControllerCommandLine> parse(int argc, const char* const* argv,
                                                      std::string& error);
    static const char* usage();
    /// Whether address is a loopback address (127.0.0.0/8, ::1, ::ffff:127.x); false for a
    /// text that is not an IP address.
    static bool isLoopback(const std::string& address);
    /// A preset name (no '/', no such file) -> PREFIX/share/hsmu/presets/NAME.json next to
    /// the installed program, else the source tree's resources/presets/NAME.json; otherwise
    /// returned unchanged. parse() applies it to --config.
    static std::string resolveConfig(const std::string& configOrPreset);
    /// The default state file for this configuration file and port:
    /// STATE/hsmu/controller/<config file stem>-<port>.state with STATE = $XDG_STATE_HOME if
    /// set and absolute, else $HOME/.local/state; "" if neither is known (no default).
    static std::string defaultStateFile(const std::string& config, std::uint16_t port);
    /// The journal to keep: state, else (unless noStateFile or port 0)
    /// defaultStateFile(config, port).
    std::string stateFile() const;
};

} // namespace hsmu::comms
