#include "comms/tls/PeerPolicy.h"

#include <openssl/evp.h>
#include <openssl/x509.h>
#include <openssl/x509_vfy.h>
#include <openssl/x509v3.h>

#include <boost/asio/ip/address.hpp>

#include <cstdio>

namespace hsmu::comms {

bool PeerPolicy::load(const TlsSpec& spec, PeerPolicy& out, std::string& error) {
    out = {};
    std::vector<std::string> pins = spec.pins, revoked;
    if (!spec.pinsFile.empty() && !readFingerprintFile(spec.pinsFile, pins, error))
        return false;
    if (!spec.revokedFile.empty() && !readFingerprintFile(spec.revokedFile, revoked, error))
        return false;
    out.pins.insert(pins.begin(), pins.end());
    out.revoked.insert(revoked.begin(), revoked.end());
    return true;
}

std::string certificateFingerprint(void* x509) {
    unsigned char md[EVP_MAX_MD_SIZE];
    unsigned int n = 0;
    if (!x509 || X509_digest(static_cast<X509*>(x509), EVP_sha256(), md, &n) != 1)
        return {};
    std::string hex;
    char b[3];
    for (unsigned i = 0; i < n; ++i) {
        std::snprintf(b, sizeof b, "%02x", md[i]);
        hex += b;
    }
    return hex;
}

PeerVerifier::PeerVerifier(std::shared_ptr<const PeerPolicy> policy, std::string host,
                           std::shared_ptr<std::string> failure)
    : m_policy(std::move(policy)), m_host(std::move(host)), m_failure(std::move(failure)) {}

bool PeerVerifier::refuse(std::string why) {
    if (m_failure && m_failure->empty())
        *m_failure = std::move(why);
    return false;
}

namespace {
/// Errors that only say the chain does not lead to a trusted CA: a pinned leaf may pass them.
bool trustError(int e) {
    return e == X509_V_ERR_UNABLE_TO_GET_ISSUER_CERT ||
           e == X509_V_ERR_UNABLE_TO_GET_ISSUER_CERT_LOCALLY ||
           e == X509_V_ERR_DEPTH_ZERO_SELF_SIGNED_CERT ||
           e == X509_V_ERR_SELF_SIGNED_CERT_IN_CHAIN ||
           e == X509_V_ERR_UNABLE_TO_VERIFY_LEAF_SIGNATURE || e == X509_V_ERR_CERT_UNTRUSTED;
}
} // namespace

bool PeerVerifier::operator()(bool preverified, boost::asio::ssl::verify_context& ctx) {
    X509_STORE_CTX* store = ctx.native_handle();
    const int depth = X509_STORE_CTX_get_error_depth(store);
    const int err = X509_STORE_CTX_get_error(store);
    X509* cert = X509_STORE_CTX_get_current_cert(store);
    const bool pinned = m_policy->pins.count(certificateFingerprint(cert)) > 0;
    if (depth > 0) {
        if (preverified)
            return true;
        if (!m_policy->pins.empty() && trustError(err)) {
            m_chainTrusted = false; // the leaf must then be pinned
            return true;
        }
        return refuse(std::string("certificate chain: ") + X509_verify_cert_error_string(err));
    }
    const std::string fp = certificateFingerprint(cert);
    if (m_policy->revoked.count(fp)) {
        X509_STORE_CTX_set_error(store, X509_V_ERR_CERT_REVOKED); // the peer's alert says so
        return refuse("the certificate " + fp.substr(0, 16) + "... is revoked");
    }
    if (!preverified) {
        // A pinned leaf from another issuer has no CRL of that issuer: its pin is its trust,
        // and the revoked list its revocation.
        if (!(pinned && (trustError(err) || err == X509_V_ERR_UNABLE_TO_GET_CRL)))
            return refuse(X509_verify_cert_error_string(err));
    } else if (!m_chainTrusted && !pinned) {
        X509_STORE_CTX_set_error(store, X509_V_ERR_CERT_UNTRUSTED);
        return refuse("not signed by the trusted CA and not pinned");
    }
    if (pinned && X509_cmp_current_time(X509_get0_notAfter(cert)) < 0) {
        X509_STORE_CTX_set_error(store, X509_V_ERR_CERT_HAS_EXPIRED);
        return refuse("certificate has expired");
    }
    if (pinned && X509_cmp_current_time(X509_get0_notBefore(cert)) > 0) {
        X509_STORE_CTX_set_error(store, X509_V_ERR_CERT_NOT_YET_VALID);
        return refuse("certificate is not yet valid");
    }
    if (!m_host.empty()) {
        boost::system::error_code ec;
        boost::asio::ip::make_address(m_host, ec);
        const int match = ec ? X509_check_host(cert, m_host.data(), m_host.size(), 0, nullptr)
                             : X509_check_ip_asc(cert, m_host.c_str(), 0);
        if (match != 1) {
            X509_STORE_CTX_set_error(store, ec ? X509_V_ERR_HOSTNAME_MISMATCH
                                               : X509_V_ERR_IP_ADDRESS_MISMATCH);
            return refuse("the certificate does not name " + m_host +
                          " in its subjectAltName (issue it with --ip or --dns " + m_host + ")");
        }
    }
    return true;
}

} // namespace hsmu::comms
