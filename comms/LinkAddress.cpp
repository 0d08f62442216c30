#include "comms/LinkAddress.h"

#include <boost/asio/ip/address.hpp>

#include <charconv>

namespace hsmu::comms {

namespace {
std::optional<LinkAddress> fail(std::string* error, const std::string& text, const char* why) {
    if (error)
        *error = "controller address '" + text + "': " + why +
                 " (expected 'builtin', 'tcp://HOST:PORT', 'simapp://HOST:PORT', "
                 "'generictcp://HOST:PORT', 'adapter://HOST:PORT' or 'tls://HOST:PORT')";
    return std::nullopt;
}
} // namespace

std::optional<LinkAddress> LinkAddress::parse(const std::string& text, std::string* error) {
    if (text.empty() || text == "builtin")
        return LinkAddress{};
    const std::pair<const char*, Kind> schemes[] = {{"tcp://", Kind::Tcp},
                                                    {"simapp://", Kind::SimApp},
                                                    {"generictcp://", Kind::GenericTcp},
                                                    {"adapter://", Kind::Adapter},
                                                    {"tls://", Kind::Tls}};
    std::string rest;
    Kind kind = Kind::Builtin;
    for (const auto& [scheme, k] : schemes)
        if (text.rfind(scheme, 0) == 0) {
            rest = text.substr(std::string(scheme).size());
            kind = k;
        }
    if (kind == Kind::Builtin)
        return fail(error, text, "unknown scheme");
    std::string host;
    std::string portText;
    if (!rest.empty() && rest.front() == '[') { // [IPv6]:port
        const auto close = rest.find(']');
        if (close == std::string::npos || close + 1 >= rest.size() || rest[close + 1] != ':')
            return fail(error, text, "malformed IPv6 literal");
        host = rest.substr(1, close - 1);
        portText = rest.substr(close + 2);
    } else {
        const auto colon = rest.rfind(':');
        if (colon == std::string::npos)
            return fail(error, text, "missing port");
        host = rest.substr(0, colon);
        portText = rest.substr(colon + 1);
    }
    if (host.empty())
        return fail(error, text, "missing host");
    unsigned value = 0;
    const auto [ptr, ec] =
        std::from_chars(portText.data(), portText.data() + portText.size(), value);
    if (ec != std::errc() || ptr != portText.data() + portText.size() || value == 0 ||
        value > 65535)
        return fail(error, text, "port must be a number in 1..65535");
    LinkAddress a;
    a.kind = kind;
    a.host = host;
    a.port = static_cast<std::uint16_t>(value);
    return a;
}

std::string LinkAddress::toString() const {
    if (kind == Kind::Builtin)
        return "builtin";
    const bool v6 = host.find(':') != std::string::npos;
    const char* scheme = kind == Kind::SimApp       ? "simapp://"
                         : kind == Kind::GenericTcp ? "generictcp://"
                         : kind == Kind::Adapter    ? "adapter://"
                         : kind == Kind::Tls        ? "tls://"
                                                    : "tcp://";
    return scheme + (v6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

bool isLoopbackAddress(const std::string& address) {
    boost::system::error_code ec;
    const auto a = boost::asio::ip::make_address(address, ec);
    if (ec)
        return false;
    if (a.is_v6() && a.to_v6().is_v4_mapped())
        return boost::asio::ip::make_address_v4(boost::asio::ip::v4_mapped, a.to_v6())
            .is_loopback();
    return a.is_loopback();
}

std::string LinkAddress::security() const {
    if (kind == Kind::Builtin)
        return "builtin";
    if (kind == Kind::Tls)
        return "tls";
    return host == "localhost" || isLoopbackAddress(host) ? "plaintext-loopback"
                                                          : "insecure-plaintext";
}

} // namespace hsmu::comms
