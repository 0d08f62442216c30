#pragma once
// makeTlsContext: the TLS 1.3 context of one end of a tls:// link (docs/security.md, "TLS"):
// TLS 1.3 only (no fallback to older versions), this end's certificate chain and key (the key
// file refused when others can read it), the CA to verify the peer with, its CRL (X509_STORE's
// CRL check of the leaf, when TlsSpec::crl is given), and the peer policy (pins, revoked). The console's context requires the controller's certificate; the
// controller's requires a client certificate (mutual authentication). Internal to comms.

#include "comms/tls/PeerPolicy.h"

#include <boost/asio/ssl/context.hpp>

#include <memory>
#include <string>

namespace hsmu::comms {

enum class TlsRole { Client, Server };

struct TlsContext {
    std::shared_ptr<boost::asio::ssl::context> ssl;
    std::shared_ptr<const PeerPolicy> policy;
};

/// A context for spec; nullopt-like (ssl == nullptr) with a sentence in error.
TlsContext makeTlsContext(const TlsSpec& spec, TlsRole role, std::string& error);

/// The reason OpenSSL gave for a failed handshake or read, in words (ec.message() plus the
/// verifier's reason when it refused the peer).
std::string tlsFailureText(const boost::system::error_code& ec, const std::string& verifier);

} // namespace hsmu::comms
