#pragma once
// LinkClient: the console's end of one native-protocol TCP connection, with blocking calls
// that all take a deadline. An Asio io_context runs on a thread of its own (ARCHITECTURE.md
// "Threads"): it reads and decodes frames into an inbox, writes queued frames in order,
// sends a Heartbeat whenever nothing was sent for heartbeatInterval, swallows the
// controller's heartbeats, and declares the link lost after silenceTimeout without any frame.
// TCP_NODELAY is on. Sequence numbers are assigned here (1, 2, ... per connection) and checked
// on what arrives. With options.tls the connection is TLS 1.3 (docs/security.md): connect()
// also completes the handshake (the controller's certificate verified against the CA or the
// pins, and against host); the frames and timeouts are the same.
//
// Thread rules: connect / close / receive from one thread at a time (the test worker);
// send() and interrupt() from any thread (they only lock a mutex and post to the io thread:
// an emergency hold is queued behind nothing but frames already posted). The io thread is
// private. No call blocks longer than its timeout.

#include "comms/protocol/Messages.h"
#include "core/config/TlsConfig.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hsmu::comms {

struct LinkClientOptions {
    double heartbeatInterval = 0.25; ///< [s]
    double silenceTimeout = 5.0;     ///< [s] without any frame: the link is lost
    /// Certificates for a TLS link (tls://); nullopt: plain TCP.
    std::optional<TlsSpec> tls;
};

class LinkClient {
public:
    explicit LinkClient(const LinkClientOptions& options = {});
    ~LinkClient();
    LinkClient(const LinkClient&) = delete;
    LinkClient& operator=(const LinkClient&) = delete;

    /// Close any previous connection, then connect to host:port within timeout [s].
    bool connect(const std::string& host, std::uint16_t port, double timeout, std::string& error);
    /// Close now; a receive() in progress returns. Safe to call when closed.
    void close();
    bool isOpen() const;
    /// Why the link closed ("" while open or before the first connect).
    std::string closeReason() const;

    /// Queue a message (false when the link is closed).
    bool send(const Message& m, std::string& error);
    /// Queue raw bytes as they are (tests: malformed frames). False when closed.
    bool sendRaw(std::vector<std::uint8_t> bytes, std::string& error);
    /// The next message other than Heartbeat, waiting at most timeout [s]. Messages that
    /// arrived before the link closed are still delivered. nullopt with error set on timeout
    /// A receive() in progress returns at once (nullopt, error "interrupted"); without one,
    /// the next receive() does. The link stays open. Any thread.
    void interrupt();
    /// Forget an interrupt() that no receive() has taken yet.
    void clearInterrupt();
    /// ("no reply within ...") or a closed link (its reason). arrived (optional): when the io
    /// thread decoded it (steady clock), for round-trip times that do not count the wait
    /// before the caller asked.
    std::optional<Message> receive(double timeout, std::string& error,
                                   std::chrono::steady_clock::time_point* arrived = nullptr);

private:
    struct Impl;
    std::unique_ptr<Impl> d;
};

} // namespace hsmu::comms
