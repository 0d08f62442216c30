#pragma once
// ByteStream: the byte stream a native-protocol connection's frames travel on, plain TCP or
// TLS 1.3 over TCP (docs/protocol.md: the same version-1 frames either way). LinkClient (the
// console) and ControllerSession (the controller) read, decode, encode and write frames
// through it with the same code and the same timeouts; only the handshake differs. Internal
// to comms (includes Asio); thread rules: the io thread that owns it.

#include "comms/tls/TlsContext.h"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl/stream.hpp>
#include <boost/asio/write.hpp>

#include <memory>
#include <optional>
#include <string>

namespace hsmu::comms {

class ByteStream {
public:
    using tcp = boost::asio::ip::tcp;
    using TlsStream = boost::asio::ssl::stream<tcp::socket>;

    /// Plain TCP.
    explicit ByteStream(tcp::socket socket) : m_plain(std::move(socket)) {}
    /// TLS over socket with context (the handshake is asyncHandshake()'s). host: the name or
    /// address dialled (console side: checked against the peer's certificate, sent as SNI
    /// when a name); "" on the controller's side.
    ByteStream(tcp::socket socket, const TlsContext& context, const std::string& host);

    bool tls() const { return m_tls != nullptr; }
    /// The TCP socket underneath (connect, options, addresses, close).
    tcp::socket& socket() { return m_tls ? m_tls->next_layer() : *m_plain; }
    /// The OpenSSL handle (TLS only).
    SSL* nativeHandle() { return m_tls->native_handle(); }
    /// Why the verifier refused the peer's certificate ("" if it did not).
    const std::string& verifyFailure() const { return *m_verifyFailure; }

    template <class Handler> void asyncHandshake(bool server, Handler&& h) {
        m_tls->async_handshake(server ? TlsStream::server : TlsStream::client,
                               std::forward<Handler>(h));
    }
    template <class Buffer, class Handler> void asyncReadSome(const Buffer& b, Handler&& h) {
        if (m_tls)
            m_tls->async_read_some(b, std::forward<Handler>(h));
        else
            m_plain->async_read_some(b, std::forward<Handler>(h));
    }
    template <class Buffer, class Handler> void asyncWrite(const Buffer& b, Handler&& h) {
        if (m_tls)
            boost::asio::async_write(*m_tls, b, std::forward<Handler>(h));
        else
            boost::asio::async_write(*m_plain, b, std::forward<Handler>(h));
    }
    /// Half-close (no more bytes from here; TLS: without close_notify, the TCP FIN says it).
    void shutdownSend();
    /// Shut down both directions and close the socket.
    void close();

private:
    std::optional<tcp::socket> m_plain;
    std::unique_ptr<TlsStream> m_tls;
    std::shared_ptr<const boost::asio::ssl::context> m_context; // outlives the stream
    std::shared_ptr<std::string> m_verifyFailure = std::make_shared<std::string>();
};

/// The first bytes of a TLS handshake record (what a TLS client sends first): a plaintext
/// end that receives them talks to a TLS peer.
inline bool looksLikeTls(const std::uint8_t* bytes, std::size_t n) {
    return n >= 3 && (bytes[0] == 0x16 || bytes[0] == 0x15) && bytes[1] == 0x03 && bytes[2] <= 0x04;
}

} // namespace hsmu::comms
