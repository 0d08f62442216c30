#pragma once
// TlsConfig: the "tls" block of a configuration (docs/configuration.md, "TLS"; docs/security.md)
// for links at tls://HOST:PORT, the native protocol inside TLS 1.3 with certificates on both
// ends:
//
//   "tls": {"ca": "lab-ca.pem", "certificate": "console.pem", "key": "console.key",
//           "pins": ["sha256 fingerprint of a controller certificate", ...],
//           "revoked": "revoked.txt", "crl": "crl.pem"}
//
// ca: the CA (PEM) whose certificates this end trusts; pins: SHA-256 fingerprints (64 hex
// digits, colons allowed) of peer certificates trusted without a CA; at least one of the two.
// certificate / key: this end's certificate chain and private key (PEM). The key file must be
// readable by its owner only (the token file's rule, core/util/SecretFile.h). Paths are
// resolved against the configuration's folder. A site may carry a tls block of its own; the
// top-level one applies to every other tls:// link. hsmu-controller takes the same fields
// as options (--tls-ca, --tls-certificate, --tls-key, --tls-pins FILE, --tls-revoked FILE,
// --tls-crl FILE).
// core only carries these values; comms builds the TLS contexts (comms/tls/TlsContext.h).

#include <optional>
#include <string>
#include <vector>

namespace hsmu {

class JsonCursor;

struct TlsSpec {
    std::string ca;                ///< CA certificate(s), PEM; "" = trust pins only
    std::string certificate;       ///< this end's certificate chain, PEM
    std::string key;               ///< this end's private key, PEM (mode 0600 or stricter)
    std::vector<std::string> pins; ///< SHA-256 fingerprints, 64 lower-case hex digits
    std::string pinsFile;    ///< more pins, one a line ("" = none; hsmu-controller --tls-pins)
    std::string revokedFile; ///< fingerprints refused even under the CA, one a line ("" = none)
    /// The CA's certificate revocation list(s), PEM ("" = none): with one, a certificate the CA
    /// signed is refused when the CRL lists it, or when no valid CRL of its CA is there (an
    /// expired CRL refuses every certificate of its CA: fail closed).
    std::string crl;
};

/// 64 lower-case hex digits from a fingerprint written with or without colons, in either
/// case, optionally after "sha256:" or "SHA256 Fingerprint="; nullopt if it is not one.
std::optional<std::string> normalizeFingerprint(const std::string& text);

/// Fingerprints of a list file (one a line; blank lines and '#' comments skipped) appended to
/// out; false with a sentence naming the file and line in error.
bool readFingerprintFile(const std::string& path, std::vector<std::string>& out,
                         std::string& error);

/// Checks a complete spec (certificate, key, ca or pins; the files readable, the key private);
/// false with a sentence in error.
bool checkTlsSpec(const TlsSpec& spec, std::string& error);

/// Read the tls object at c (paths resolved against baseDir). Throws ConfigError naming the
/// field.
TlsSpec parseTlsSpec(const JsonCursor& c, const std::string& baseDir);

} // namespace hsmu
