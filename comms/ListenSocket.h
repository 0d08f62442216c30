#pragma once
// listenOn: the one way a server here opens its listening socket (hsmu-controller's native and
// RTHS servers, the OpenFresco listener): the address parsed, SO_REUSEADDR, bound, listening.
// False with the reason in error: "<prefix>'ADDR' is not an IP address" or "cannot listen on
// ADDR:PORT: <the system's reason>". No Qt; thread rules: the acceptor's.

#include <boost/asio/ip/tcp.hpp>

#include <cstdint>
#include <string>

namespace hsmu::comms {

bool listenOn(boost::asio::ip::tcp::acceptor& acceptor, const std::string& bind,
              std::uint16_t port, std::string& error, const std::string& addressPrefix = {});

} // namespace hsmu::comms
