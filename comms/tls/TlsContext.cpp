#include "comms/tls/TlsContext.h"

#include "comms/tls/OpenSslLibrary.h"

#include <openssl/err.h>
#include <openssl/ssl.h>

namespace hsmu::comms {

namespace ssl = boost::asio::ssl;

TlsContext makeTlsContext(const TlsSpec& spec, TlsRole role, std::string& error) {
    if (!checkTlsSpec(spec, error) || !loadOpenSsl(error))
        return {};
    auto policy = std::make_shared<PeerPolicy>();
    if (!PeerPolicy::load(spec, *policy, error))
        return {};
    auto ctx = std::make_shared<ssl::context>(role == TlsRole::Client ? ssl::context::tls_client
                                                                      : ssl::context::tls_server);
    SSL_CTX* native = ctx->native_handle();
    SSL_CTX_set_min_proto_version(native, TLS1_3_VERSION);
    SSL_CTX_set_max_proto_version(native, TLS1_3_VERSION);
    boost::system::error_code ec;
    auto step = [&](const std::string& what) {
        if (!ec)
            return true;
        error = what + ": " + ec.message();
        return false;
    };
    if (!spec.ca.empty()) {
        ctx->load_verify_file(spec.ca, ec);
        if (!step(spec.ca + ": cannot load the CA certificate"))
            return {};
    }
    ctx->use_certificate_chain_file(spec.certificate, ec);
    if (!step(spec.certificate + ": cannot load the certificate"))
        return {};
    ctx->use_private_key_file(spec.key, ssl::context::pem, ec);
    if (!step(spec.key + ": cannot load the private key"))
        return {};
    if (SSL_CTX_check_private_key(native) != 1) {
        error = spec.key + ": the key does not belong to the certificate " + spec.certificate;
        return {};
    }
    ctx->set_verify_mode(role == TlsRole::Client
                             ? ssl::verify_peer
                             : ssl::verify_peer | ssl::verify_fail_if_no_peer_cert);
    if (role == TlsRole::Server) // no session tickets: each connection shows its certificate
        SSL_CTX_set_num_tickets(native, 0);
    return {ctx, policy};
}

std::string tlsFailureText(const boost::system::error_code& ec, const std::string& verifier) {
    std::string text = ec.message();
    if (const auto paren = text.find(" ("); paren != std::string::npos)
        text.erase(paren); // " (SSL routines)"
    if (!verifier.empty())
        text += " (" + verifier + ")";
    return text;
}

} // namespace hsmu::comms
