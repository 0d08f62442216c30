#pragma once
// ControllerServer: the network side of hsmu-controller. Listens (127.0.0.1 by default),
// admits one console session at a time (a session may hold one connection per specimen; its
// reconnects, identified by the hello's session id, replace the old connection; anyone else
// gets Error(Busy)), checks the optional token, routes specimen messages to the
// SpecimenStations and, in real-time pace, runs their loop at the settings' rate from a
// steady-clock timer that wakes 100 us before each tick and spins to it (ticks that come due
// while the thread was busy are run at once; each tick run more than one period late counts
// as a deadline miss), optionally under SCHED_FIFO (realTimePriority).
// With options.tls the port speaks TLS 1.3 only, with mutual authentication: every client must
// show a certificate its CA signed or whose fingerprint is pinned, not revoked
// (comms/tls/PeerPolicy.h); the token is then a second factor. SIGHUP re-reads the TLS files
// (certificate, key, CA, pins, revoked list): connections from then on use them, and admitted
// sessions whose certificate is now revoked are closed; a reload that fails keeps the old
// ones and says why (docs/security.md, "Rotation and revocation").
// Thread rules: construct, listen() and run() on one thread; stop() from any thread.

#include "comms/controller/SpecimenStation.h"
#include "core/config/TlsConfig.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hsmu::comms {

struct ControllerServerOptions {
    std::string bind = "127.0.0.1";
    std::uint16_t port = 0; ///< 0: any free port (see port() after listen())
    std::string token;      ///< "" accepts any hello
    std::optional<TlsSpec> tls; ///< TLS 1.3 with client certificates; nullopt: plaintext
    double idleTimeout = 10.0;
    double rate = 1024.0; ///< loop rate [Hz] (real-time pace)
    bool realTime = true;
    /// Real-time pace: run()'s thread under SCHED_FIFO at this priority (1-99) so that other
    /// processes cannot preempt the loop; 0 (default): normal scheduling. Needs CAP_SYS_NICE
    /// (or an rtprio limit); if refused, a log line and normal scheduling.
    int realTimePriority = 0;
    bool quiet = false; ///< no session log lines on stderr
    /// Test and benchmark setting (hsmu-controller --reply-delay): every measurement is sent
    /// this many seconds after its target arrived (an asio timer: the loop keeps running), as
    /// a remote lab's latency would delay it. 0 (default): at once.
    double replyDelay = 0.0;
};

struct ControllerStatistics {
    long long ticks = 0;
    long long deadlineMisses = 0; ///< ticks run more than one period after they were due
    double maxLateness = 0.0;     ///< [s]
    long long sessionsAdmitted = 0;
    long long sessionsRefused = 0;
};

class ControllerServer {
public:
    ControllerServer(const ControllerServerOptions& options,
                     std::vector<std::unique_ptr<SpecimenStation>> stations);
    ~ControllerServer();
    ControllerServer(const ControllerServer&) = delete;
    ControllerServer& operator=(const ControllerServer&) = delete;

    /// Bind and listen; false with a sentence in error.
    bool listen(std::string& error);
    std::uint16_t port() const;
    /// Re-read the TLS files now (what SIGHUP does); false with the reason in error (the old
    /// ones stay). True without TLS.
    bool reloadTls(std::string& error);
    /// Serve until stop(), SIGINT or SIGTERM.
    void run();
    void stop();
    ControllerStatistics statistics() const;

private:
    struct Impl;
    std::unique_ptr<Impl> d;
};

} // namespace hsmu::comms
