#pragma once
// ControllerSession: one console connection to hsmu-controller (internal to the controller:
// this header includes Asio and is not part of any public API).
//
// Life: accepted -> (TLS listener: the TLS 1.3 handshake, the client's certificate verified;
// a client whose first bytes are not a TLS handshake gets a plaintext Error frame saying the
// port speaks TLS; plaintext listener: a client whose first bytes are a TLS handshake is
// closed with a log line) -> Hello within 5 s (else Error(Timeout), close) -> admitted by the host
// (token, version, element, one console session at a time) -> frames are handed to the host
// and its replies sent back; Heartbeat is echoed here; silence past the idle timeout, a
// malformed frame or Bye closes it. A frame that must close the connection (Error with a
// closing code) is written before the socket is shut down, if the peer takes it within 2 s
// (a peer that does not read is closed without it).
// Bounded: replies wait in a send queue of at most kMaxQueuedBytes; a client that does not
// read its replies is dropped when its queue would grow past the cap or when a reply has
// waited the idle timeout to be written, whichever comes first, so it can neither grow the
// controller's memory nor hold the session (docs/protocol.md, "Resource limits").
// Thread rules: the controller's single io thread.

#include "comms/protocol/FrameDecoder.h"
#include "comms/tls/ByteStream.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include <array>
#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace hsmu::comms {

class ControllerSession;

/// What a session needs from the server.
class SessionHost {
public:
    virtual ~SessionHost() = default;
    /// Admit a hello: fill ack, or return the refusal (the session sends it and closes).
    /// delay [s]: how long the session waits before it sends the refusal (0: at once).
    virtual std::optional<ErrorMsg> admit(ControllerSession& s, const HelloMsg& hello,
                                          HelloAckMsg& ack, double& delay) = 0;
    /// A frame of an admitted session (not Hello, Heartbeat or Bye); the reply, if any.
    virtual std::optional<Message> handle(ControllerSession& s, const Message& m) = 0;
    /// The connection is gone (called once).
    virtual void closed(ControllerSession& s) = 0;
    virtual double idleTimeout() const = 0;
    /// The session is about to be closed for misbehaving (a log line; closed() follows).
    virtual void dropped(ControllerSession& s, const std::string& why) = 0;
};

class ControllerSession : public std::enable_shared_from_this<ControllerSession> {
public:
    /// [bytes] the send queue's cap (a few thousand frames: far more than any console lags).
    static constexpr std::size_t kMaxQueuedBytes = 256 * 1024;

    /// stream: plain TCP, or TLS whose handshake start() performs (under the hello timeout).
    ControllerSession(std::unique_ptr<ByteStream> stream, SessionHost& host);
    void start();
    void send(const Message& m);
    /// Send a final error frame, then close.
    void refuse(const ErrorMsg& e);
    /// The same after delay [s]; the input is drained, not decoded, meanwhile.
    void refuseLater(const ErrorMsg& e, double delay);
    /// Close now (pending writes are dropped).
    void close();

    bool admitted() const { return m_admitted; }
    /// [bytes] written by send() and not yet on the socket.
    std::size_t queuedBytes() const { return m_queuedBytes; }
    std::uint64_t sessionId() const { return m_sessionId; }
    int station() const { return m_station; }
    void setStation(int index) { m_station = index; }
    const std::string& peer() const { return m_peer; }
    /// TLS: the SHA-256 fingerprint of the client's certificate ("" before the handshake or
    /// in plaintext).
    const std::string& peerFingerprint() const { return m_fingerprint; }

private:
    void handshake();
    void refusePlaintextOnTls();
    void read();
    void onFrame(const Frame& f);
    void write();
    void finish();
    void armIdle(double seconds);
    void waitIdle();

    std::unique_ptr<ByteStream> m_stream;
    boost::asio::steady_timer m_idle;
    SessionHost& m_host;
    FrameDecoder m_decoder;
    std::array<std::uint8_t, 8192> m_readBuffer{};
    std::deque<std::vector<std::uint8_t>> m_writes;
    std::size_t m_queuedBytes = 0;
    bool m_writing = false;
    bool m_closeAfterWrite = false;
    bool m_closed = false;
    bool m_admitted = false;
    std::uint32_t m_sequence = 1;
    std::uint64_t m_sessionId = 0;
    int m_station = -1;
    std::string m_peer;
    std::string m_fingerprint;
    bool m_received = false; ///< any byte decoded yet (plaintext: the TLS check)
    bool m_secured = false;  ///< TLS: the handshake is done (frames may be written)
    std::chrono::steady_clock::time_point m_lastActivity; ///< last frame received
    std::chrono::steady_clock::time_point m_writeStarted; ///< the pending write's start
    double m_idleSeconds = 5.0;
};

} // namespace hsmu::comms
