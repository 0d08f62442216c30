#include "comms/ListenSocket.h"

#include <boost/asio/ip/address.hpp>

namespace hsmu::comms {

bool listenOn(boost::asio::ip::tcp::acceptor& acceptor, const std::string& bind,
              std::uint16_t port, std::string& error, const std::string& addressPrefix) {
    namespace asio = boost::asio;
    boost::system::error_code ec;
    const auto address = asio::ip::make_address(bind, ec);
    if (ec) {
        error = addressPrefix + "'" + bind + "' is not an IP address";
        return false;
    }
    const asio::ip::tcp::endpoint ep(address, port);
    acceptor.open(ep.protocol(), ec);
    if (!ec)
        acceptor.set_option(asio::socket_base::reuse_address(true), ec);
    if (!ec)
        acceptor.bind(ep, ec);
    if (!ec)
        acceptor.listen(asio::socket_base::max_listen_connections, ec);
    if (ec) {
        error = "cannot listen on " + bind + ":" + std::to_string(port) + ": " + ec.message();
        return false;
    }
    return true;
}

} // namespace hsmu::comms
