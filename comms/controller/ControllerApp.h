#pragma once
// ControllerApp: hsmu-controller assembled from its command line: reads the configuration
// (core's ConfigLoader), makes one SpecimenStation per experimental element (in the order of
// the configuration), opens the state journal and replays it, and serves.
// Serves the native protocol (ControllerServer) or, with --protocol / controller.protocol
// simapp or generictcp, an OpenFresco one (OfServer).
// Output: one line on stdout once listening,
//   "hsmu-controller: listening on 127.0.0.1:PORT (fast pace, 1 specimen: Element 1)"
//   "hsmu-controller: listening on 127.0.0.1:PORT (simapp element server, dataSize 256, fast
//    pace, 1 specimen: Element 1)"
// and the loop statistics on stdout when stopped; errors on stderr. With --rths, the RTHS loop
// on the controller (RthsServer):
//   "hsmu-controller: listening on 127.0.0.1:PORT (RTHS loop 'NAME', 1024 Hz, 3 s record,
//    fast pace)")

#include "comms/controller/ControllerCommandLine.h"
#include "comms/controller/ControllerServer.h"
#include "comms/controller/OfServer.h"
#include "comms/controller/RthsServer.h"

#include <memory>
#include <string>

namespace hsmu::comms {

class ControllerApp {
public:
    explicit ControllerApp(ControllerCommandLine commandLine);
    ~ControllerApp();

    /// Build everything and listen; false with a sentence in error.
    bool start(std::string& error);
    /// Serve until SIGINT / SIGTERM; returns the process exit code.
    int run();
    std::uint16_t port() const;
    /// After a failed start(): whether it was the command line's fault (exit code 2), e.g. a
    /// non-loopback --bind for the plaintext native protocol without --insecure-plaintext.
    bool usageRefused() const { return m_usageRefused; }

private:
    bool startRths(const std::string& token, std::string& error);
    bool m_usageRefused = false;
    std::unique_ptr<RthsServer> m_rthsServer;
    ControllerCommandLine m_cmd;
    std::unique_ptr<StateJournal> m_journal;
    std::unique_ptr<ControllerServer> m_server;
    std::unique_ptr<OfServer> m_ofServer;
    std::string m_names;
};

} // namespace hsmu::comms
