#pragma once
// PeerPolicy and PeerVerifier: which peer certificates one end of a tls:// link accepts
// (docs/security.md, "TLS"). A certificate is accepted when
//   - its chain verifies up to the configured CA (dates included), or its SHA-256 fingerprint
//     is pinned (then only its own dates are checked), and
//   - its fingerprint is not in the revoked list, nor (with a CRL: TlsSpec::crl, checked by
//     OpenSSL's X509_STORE with X509_V_FLAG_CRL_CHECK) its serial in its CA's CRL, and
//   - on the console's side, the host name or IP address dialled matches its subjectAltName.
// The controller keeps a PeerPolicy per listening context and builds a new one on SIGHUP
// (pins and revoked lists re-read): connections that arrive after the reload use it.
// Internal to comms (includes Asio's ssl); thread rules: the io thread that owns the stream.

#include "core/config/TlsConfig.h"

#include <boost/asio/ssl/verify_context.hpp>

#include <memory>
#include <set>
#include <string>

namespace hsmu::comms {

struct PeerPolicy {
    std::set<std::string> pins;    ///< trusted without a CA (64 lower-case hex digits)
    std::set<std::string> revoked; ///< refused whatever signed them

    /// spec's pins, pinsFile and revokedFile; false with a sentence in error.
    static bool load(const TlsSpec& spec, PeerPolicy& out, std::string& error);
};

/// The SHA-256 fingerprint of a certificate (64 lower-case hex digits).
std::string certificateFingerprint(void* x509);

/// The verify callback of one TLS stream (Asio's set_verify_callback); failure() says why it
/// refused the peer's certificate ("" when it did not).
class PeerVerifier {
public:
    /// host: the name or address dialled (console side), "" on the controller's side.
    PeerVerifier(std::shared_ptr<const PeerPolicy> policy, std::string host,
                 std::shared_ptr<std::string> failure);
    bool operator()(bool preverified, boost::asio::ssl::verify_context& ctx);

private:
    bool refuse(std::string why);
    std::shared_ptr<const PeerPolicy> m_policy;
    std::string m_host;
    std::shared_ptr<std::string> m_failure;
    bool m_chainTrusted = true; ///< no CA error was let pass above the leaf
};

} // namespace hsmu::comms
