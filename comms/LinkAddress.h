#pragma once
// LinkAddress: where the console finds an actuator controller, parsed from
// "builtin", "tcp://HOST:PORT", "tls://HOST:PORT", "simapp://HOST:PORT",
// "generictcp://HOST:PORT" or "adapter://HOST:PORT" (the form of `hsmu run --controller`).
// tls:// is the native protocol inside TLS 1.3 with the configuration's "tls" certificates
// (docs/security.md). tcp:// speaks the protocol the
// configuration's controller.protocol names (native by default); simapp:// and generictcp://
// force that OpenFresco protocol, adapter:// drives OpenSees' `adapter` element (a numerical
// substructure in an OpenSees model; docs/openfresco.md). No Qt, no sockets.

#include <cstdint>
#include <optional>
#include <string>

namespace hsmu::comms {

struct LinkAddress {
    enum class Kind { Builtin, Tcp, SimApp, GenericTcp, Adapter, Tls };
    Kind kind = Kind::Builtin;
    std::string host;       ///< for a network kind: host name or IPv4/IPv6 literal
    std::uint16_t port = 0; ///< for a network kind: 1..65535

    /// Parse; on failure returns nullopt and sets *error to a sentence saying what was expected.
    static std::optional<LinkAddress> parse(const std::string& text, std::string* error = nullptr);
    std::string toString() const;
    /// How a link to this address is protected, for the record (docs/recording.md):
    /// "builtin" (in-process), "tls", "plaintext-loopback" (a loopback host: 127.0.0.0/8,
    /// ::1, localhost) or "insecure-plaintext" (plaintext across a network).
    std::string security() const;
};

/// Whether address is a loopback IP address (127.0.0.0/8, ::1, ::ffff:127.x); false for a
/// text that is not an IP address.
bool isLoopbackAddress(const std::string& address);

} // namespace hsmu::comms
