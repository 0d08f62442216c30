#include "comms/controller/ControllerSession.h"

#include <boost/asio/write.hpp>

#include <openssl/ssl.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace hsmu::comms {

namespace asio = boost::asio;

namespace {
constexpr double kHelloTimeout = 5.0; // [s]
/// How long a refusal's final frame may wait to be written, and (finish()) how long the peer
/// then has to close its side, before the connection is closed regardless.
constexpr auto kRefusalGrace = std::chrono::seconds(2);
}

ControllerSession::ControllerSession(std::unique_ptr<ByteStream> stream, SessionHost& host)
    : m_stream(std::move(stream)), m_idle(m_stream->socket().get_executor()), m_host(host) {
    boost::system::error_code ec;
    m_stream->socket().set_option(asio::ip::tcp::no_delay(true), ec);
    const auto ep = m_stream->socket().remote_endpoint(ec);
    m_peer = ec ? std::string("?") : ep.address().to_string() + ":" + std::to_string(ep.port());
}

void ControllerSession::start() {
    m_lastActivity = std::chrono::steady_clock::now();
    armIdle(kHelloTimeout); // the TLS handshake counts against the hello's time
    if (!m_stream->tls()) {
        read();
        return;
    }
    // Look at the first bytes before TLS takes them: a plaintext client is told in its own
    // framing that this port speaks TLS.
    m_stream->socket().async_wait(
        asio::ip::tcp::socket::wait_read,
        [self = shared_from_this()](const boost::system::error_code& ec) {
            if (self->m_closed)
                return;
            if (ec) {
                self->close();
                return;
            }
            std::array<std::uint8_t, 3> head{};
            boost::system::error_code e;
            const std::size_t n = self->m_stream->socket().receive(
                asio::buffer(head), asio::ip::tcp::socket::message_peek, e);
            if (!e && n > 0 && head[0] != 0x16)
                self->refusePlaintextOnTls();
            else if (!e && n > 0)
                self->handshake();
            else
                self->close();
        });
}

void ControllerSession::handshake() {
    auto self = shared_from_this();
    m_stream->asyncHandshake(true, [self](const boost::system::error_code& ec) {
        if (self->m_closed)
            return;
        if (ec) {
            const std::string& v = self->m_stream->verifyFailure();
            self->m_host.dropped(*self,
                                 "TLS handshake failed: " +
                                     tlsFailureText(ec, v.empty() ? "" : "its certificate: " + v));
            self->close();
            return;
        }
        self->m_secured = true;
        if (X509* cert = SSL_get1_peer_certificate(self->m_stream->nativeHandle())) {
            self->m_fingerprint = certificateFingerprint(cert);
            X509_free(cert);
        }
        self->read();
    });
}

void ControllerSession::refusePlaintextOnTls() {
    // The Error frame goes out on the TCP socket itself, in the client's plaintext framing.
    const std::string why = "this controller speaks TLS on this port: connect with "
                            "tls://HOST:PORT and a client certificate (docs/security.md)";
    m_host.dropped(*this, "a plaintext client on the TLS port (told to use tls://)");
    auto bytes = std::make_shared<std::vector<std::uint8_t>>();
    encodeFrame(ErrorMsg{ErrorCode::Unauthorized, why}, m_sequence++, *bytes);
    m_closeAfterWrite = true;
    m_idle.expires_after(kRefusalGrace);
    m_idle.async_wait([self = shared_from_this()](const boost::system::error_code& ec) {
        if (!ec)
            self->close();
    });
    asio::async_write(m_stream->socket(), asio::buffer(*bytes),
                      [self = shared_from_this(), bytes](const boost::system::error_code& ec,
                                                         std::size_t) {
                          if (self->m_closed)
                              return;
                          if (ec) {
                              self->close();
                              return;
                          }
                          self->m_stream->shutdownSend();
                      });
}

void ControllerSession::armIdle(double seconds) {
    m_idleSeconds = seconds;
    waitIdle();
}

void ControllerSession::waitIdle() {
    // One timer wait per timeout period, not per frame: on expiry the wait is renewed for what
    // is left. Two clocks run against the same timeout: the silence since the last frame
    // received, and how long the oldest reply has been waiting to be written (a client that
    // sends but does not read: its replies stop moving long before its queue reaches the cap).
    using namespace std::chrono;
    const auto limit = duration_cast<steady_clock::duration>(duration<double>(m_idleSeconds));
    auto deadline = m_lastActivity + limit;
    if (m_writing)
        deadline = std::min(deadline, m_writeStarted + limit);
    m_idle.expires_at(deadline);
    m_idle.async_wait([self = shared_from_this()](const boost::system::error_code& ec) {
        if (ec || self->m_closed || self->m_closeAfterWrite)
            return; // cancelled, closed, or a refusal's own deadline has taken the timer
        const auto now = steady_clock::now();
        const auto limit =
            duration_cast<steady_clock::duration>(duration<double>(self->m_idleSeconds));
        const int s = static_cast<int>(std::lround(self->m_idleSeconds));
        if (self->m_writing && now - self->m_writeStarted >= limit) {
            // Nothing can be said to it (it does not read): close without a final frame.
            self->m_host.dropped(*self, "does not read its replies (none taken for " +
                                            std::to_string(s) + " s)");
            self->close();
            return;
        }
        if (now - self->m_lastActivity < limit) {
            self->waitIdle();
            return;
        }
        const std::string why = self->m_admitted ? "no frame for " + std::to_string(s) + " s"
                                                 : "no hello within " + std::to_string(s) + " s";
        self->m_host.dropped(*self, why);
        if (self->m_stream->tls() && !self->m_secured) {
            self->close(); // no TLS session to say it in
            return;
        }
        self->refuse({ErrorCode::Timeout, why});
    });
}

void ControllerSession::read() {
    m_stream->asyncReadSome(asio::buffer(m_readBuffer), [self = shared_from_this()](
                                                             const boost::system::error_code& ec,
                                                             std::size_t n) {
        if (self->m_closed)
            return;
        if (ec) {
            self->close();
            return;
        }
        // After a refusal the input is drained, not decoded, until the peer closes: closing
        // with unread input would send a reset that can destroy the error frame in flight.
        if (!self->m_received && !self->m_stream->tls() &&
            looksLikeTls(self->m_readBuffer.data(), n)) {
            // A frame would only confuse its handshake: close, and say why here.
            self->m_host.dropped(*self, "a TLS client on a plaintext port (this controller "
                                        "was started without --tls-certificate)");
            self->close();
            return;
        }
        self->m_received = true;
        if (!self->m_closeAfterWrite) {
            self->m_decoder.append(self->m_readBuffer.data(), n);
            Frame f;
            for (;;) {
                const auto st = self->m_decoder.next(f);
                if (st == FrameDecoder::Status::NeedMore)
                    break;
                if (st == FrameDecoder::Status::Error) {
                    self->refuse({self->m_decoder.error().code, self->m_decoder.error().reason});
                    break;
                }
                self->onFrame(f);
                if (self->m_closed || self->m_closeAfterWrite)
                    break;
            }
        }
        if (!self->m_closed)
            self->read();
    });
}

void ControllerSession::onFrame(const Frame& f) {
    m_lastActivity = std::chrono::steady_clock::now();
    if (!m_admitted) {
        const auto* hello = std::get_if<HelloMsg>(&f.message);
        if (!hello) {
            refuse({ErrorCode::ProtocolViolation, std::string("expected hello, received ") +
                                                      messageTypeName(messageTypeOf(f.message))});
            return;
        }
        if (hello->version != kProtocolVersion) {
            refuse({ErrorCode::UnsupportedVersion,
                    "protocol version " + std::to_string(hello->version) +
                        " is not supported (this controller speaks version " +
                        std::to_string(kProtocolVersion) + ")"});
            return;
        }
        HelloAckMsg ack;
        double delay = 0.0;
        if (auto refusal = m_host.admit(*this, *hello, ack, delay)) {
            refuseLater(*refusal, delay);
            return;
        }
        m_admitted = true;
        m_sessionId = hello->sessionId;
        armIdle(m_host.idleTimeout());
        send(ack);
        return;
    }
    if (const auto* hb = std::get_if<HeartbeatMsg>(&f.message)) {
        send(*hb);
        return;
    }
    if (std::holds_alternative<ByeMsg>(f.message)) {
        close();
        return;
    }
    if (std::holds_alternative<ErrorMsg>(f.message))
        return; // the console's complaint; it will act on it
    if (auto reply = m_host.handle(*this, f.message))
        send(*reply);
}

void ControllerSession::send(const Message& m) {
    if (m_closed || m_closeAfterWrite)
        return; // nothing follows a refusal
    std::vector<std::uint8_t> bytes;
    encodeFrame(m, m_sequence++, bytes);
    if (m_queuedBytes + bytes.size() > kMaxQueuedBytes) {
        // The client does not read its replies (e.g. heartbeats sent, never read): drop it
        // rather than let its queue grow without bound.
        m_host.dropped(*this, "does not read its replies (send queue past " +
                                  std::to_string(kMaxQueuedBytes / 1024) + " KiB)");
        close();
        return;
    }
    m_queuedBytes += bytes.size();
    m_writes.push_back(std::move(bytes));
    write();
}

void ControllerSession::refuse(const ErrorMsg& e) {
    if (m_closed || m_closeAfterWrite)
        return;
    send(e);
    if (m_closed)
        return; // the frame itself did not fit in the queue: closed at once
    m_closeAfterWrite = true;
    // The final frame gets kRefusalGrace to be written (then finish() gives the peer as long
    // again to close its side); a peer that does not read would otherwise keep the refused
    // session open for ever.
    m_idle.expires_after(kRefusalGrace);
    m_idle.async_wait([self = shared_from_this()](const boost::system::error_code& ec) {
        if (!ec)
            self->close();
    });
}

void ControllerSession::refuseLater(const ErrorMsg& e, double delay) {
    if (delay <= 0.0) {
        refuse(e);
        return;
    }
    if (m_closed || m_closeAfterWrite)
        return;
    m_closeAfterWrite = true; // drain the input, stop the idle timer's verdicts
    m_idle.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
        std::chrono::duration<double>(delay)));
    m_idle.async_wait([self = shared_from_this(), e](const boost::system::error_code& ec) {
        if (ec || self->m_closed)
            return;
        self->m_closeAfterWrite = false;
        self->refuse(e);
    });
}

void ControllerSession::finish() {
    // All written: half-close, and give the peer a moment to read and close its side.
    m_stream->shutdownSend();
    m_idle.expires_after(kRefusalGrace);
    m_idle.async_wait([self = shared_from_this()](const boost::system::error_code& e) {
        if (!e)
            self->close();
    });
}

void ControllerSession::write() {
    if (m_writing || m_writes.empty() || m_closed)
        return;
    m_writing = true;
    m_writeStarted = std::chrono::steady_clock::now();
    m_stream->asyncWrite(
        asio::buffer(m_writes.front()),
        [self = shared_from_this()](const boost::system::error_code& ec, std::size_t) {
            self->m_writing = false;
            if (self->m_closed)
                return;
            if (ec) {
                self->close();
                return;
            }
            self->m_queuedBytes -= self->m_writes.front().size();
            self->m_writes.pop_front();
            if (self->m_writes.empty() && self->m_closeAfterWrite)
                self->finish();
            else
                self->write();
        });
}

void ControllerSession::close() {
    if (m_closed)
        return;
    m_closed = true;
    m_idle.cancel();
    m_stream->close();
    m_writes.clear();
    m_queuedBytes = 0;
    m_host.closed(*this);
}

} // namespace hsmu::comms
