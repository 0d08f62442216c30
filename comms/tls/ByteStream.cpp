#include "comms/tls/ByteStream.h"

#include <openssl/ssl.h>

namespace hsmu::comms {

ByteStream::ByteStream(tcp::socket socket, const TlsContext& context, const std::string& host)
    : m_tls(std::make_unique<TlsStream>(std::move(socket), *context.ssl)), m_context(context.ssl) {
    boost::system::error_code ec;
    if (!host.empty()) {
        boost::asio::ip::make_address(host, ec);
        if (ec) // a name (not an address literal): SNI
            SSL_set_tlsext_host_name(m_tls->native_handle(), const_cast<char*>(host.c_str()));
    }
    m_tls->set_verify_callback(PeerVerifier(context.policy, host, m_verifyFailure));
}

void ByteStream::shutdownSend() {
    boost::system::error_code ec;
    socket().shutdown(tcp::socket::shutdown_send, ec);
}

void ByteStream::close() {
    boost::system::error_code ec;
    socket().shutdown(tcp::socket::shutdown_both, ec);
    socket().close(ec);
}

} // namespace hsmu::comms
