#pragma once
// LinkAddress: where the console finds an actuator controller, parsed from
// "builtin" or "tcp://HOST:PORT" (the form of `hsmu run --controller`). No Qt, no sockets.

#include <cstdint>
#include <optional>
#include <string>

namespace hsmu::comms {

struct LinkAddress {
    enum class Kind { Builtin, Tcp };
    Kind kind = Kind::Builtin;
    std::string host;       ///< for Tcp: host name or IPv4/IPv6 literal
    std::uint16_t port = 0; ///< for Tcp: 1..65535

    /// Parse; on failure returns nullopt and sets *error to a sentence saying what was expected.
    static std::optional<LinkAddress> parse(const std::string& text, std::string* error = nullptr);
    std::string toString() const;
};

} // namespace hsmu::comms
