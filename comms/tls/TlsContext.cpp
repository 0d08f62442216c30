#include "comms/tls/TlsContext.h"

#include "comms/tls/OpenSslLibrary.h"

#include <openssl/err.h>
#include <openssl/pem.h>
#include <openssl/ssl.h>
#include <openssl/x509_vfy.h>

#include <cstdio>
#include <memory>

namespace hsmu::comms {

namespace ssl = boost::asio::ssl;

namespace {

/// Adds every CRL of the PEM file to the context's store and turns the check of the leaf's
/// CRL on (X509_V_FLAG_CRL_CHECK); false with a sentence in error (no CRL in the file, or one
/// that is not PEM).
bool loadCrl(SSL_CTX* ctx, const std::string& path, std::string& error) {
    const std::unique_ptr<BIO, decltype(&BIO_free)> bio(BIO_new_file(path.c_str(), "r"), BIO_free);
    if (!bio) {
        error = path + ": cannot read the CRL";
        return false;
    }
    X509_STORE* store = SSL_CTX_get_cert_store(ctx);
    int count = 0;
    ERR_clear_error();
    while (X509_CRL* crl = PEM_read_bio_X509_CRL(bio.get(), nullptr, nullptr, nullptr)) {
        const int added = X509_STORE_add_crl(store, crl);
        X509_CRL_free(crl);
        if (added != 1) {
            error = path + ": the CRL cannot be used";
            return false;
        }
        ++count;
    }
    ERR_clear_error(); // the end of the file reads as an error
    if (count == 0) {
        error = path + ": no CRL in the file (PEM \"BEGIN X509 CRL\" expected; made by "
                       "scripts/hsmu-certs.sh revoke)";
        return false;
    }
    X509_STORE_set_flags(store, X509_V_FLAG_CRL_CHECK);
    return true;
}

} // namespace

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
    if (!spec.crl.empty() && !loadCrl(native, spec.crl, error))
        return {};
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
