#include "comms/openfresco/OfSocket.h"

#include "comms/ListenSocket.h"

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>

#include <chrono>
#include <cstdio>
#include <mutex>

#include <poll.h>

#if defined(__linux__)
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#endif

namespace hsmu::comms::of {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;
using Clock = std::chrono::steady_clock;

namespace {

constexpr auto kSlice = std::chrono::milliseconds(200);

std::string secondsText(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g s", s);
    return buf;
}

enum class Wait { Done, TimedOut, Cancelled };

/// now + timeout [s] (meaningless, and unused, when timeout <= 0).
Clock::time_point deadlineAfter(double timeout) {
    return Clock::now() + std::chrono::duration_cast<Clock::duration>(
                              std::chrono::duration<double>(timeout > 0.0 ? timeout : 0.0));
}

/// Run io until *done, the deadline (timeout <= 0: none) or cancel; never returns with a
/// handler of this operation still pending when the caller then aborts and drains.
Wait runUntil(asio::io_context& io, const bool& done, double timeout,
              const std::function<bool()>& cancel) {
    const bool bounded = timeout > 0.0;
    const auto deadline =
        Clock::now() + std::chrono::duration_cast<Clock::duration>(
                           std::chrono::duration<double>(bounded ? timeout : 0.0));
    while (!done) {
        auto slice = std::chrono::duration_cast<Clock::duration>(kSlice);
        if (bounded) {
            const auto left = deadline - Clock::now();
            if (left <= Clock::duration::zero())
                return Wait::TimedOut;
            slice = std::min(slice, left);
        }
        io.run_one_for(slice);
        if (!done && cancel && cancel())
            return Wait::Cancelled;
    }
    return Wait::Done;
}

} // namespace

struct OfSocket::Impl {
    std::shared_ptr<asio::io_context> io = std::make_shared<asio::io_context>(1);
    std::unique_ptr<tcp::socket> socket = std::make_unique<tcp::socket>(*io);
    std::function<bool()> cancel;
    std::string lineBuffer; ///< readLine(): bytes read past the last line
    bool eof = false, timedOut = false;
    std::string peer;
    // The descriptor interrupt() may shut down from another thread (-1 when closed).
    std::mutex fdMutex;
    int fd = -1;

    void configure() {
        {
            std::lock_guard lock(fdMutex);
            fd = socket->native_handle();
        }
        boost::system::error_code ec;
        socket->set_option(tcp::no_delay(true), ec);
        socket->set_option(asio::socket_base::keep_alive(true), ec);
        quickAck();
        const auto ep = socket->remote_endpoint(ec);
        peer = ec ? std::string("?") : ep.address().to_string() + ":" + std::to_string(ep.port());
    }

    /// Acknowledge what has arrived at once and stay in quick-ACK mode (Linux leaves it again
    /// on its own, so this is re-armed after every read). OpenSees' and OpenFresco's sockets
    /// keep Nagle on and write two frames back to back (e.g. [3] then [6]); without an
    /// immediate ACK of the first, their second waits for our delayed ACK: about 40 ms.
    void quickAck() {
#if defined(__linux__) && defined(TCP_QUICKACK)
        const int one = 1;
        ::setsockopt(socket->native_handle(), IPPROTO_TCP, TCP_QUICKACK, &one, sizeof one);
#endif
    }

    /// The one read of read() and readLine(): exactly n bytes (exact) or at least one of them
    /// into data, before deadline (timeout <= 0: none, only the cancel predicate). On failure
    /// the socket is closed (a half-read frame must never be followed by another read) and
    /// error says why, timeout [s] being the caller's whole allowance.
    bool readInto(void* data, std::size_t n, bool exact, double timeout,
                  Clock::time_point deadline, std::size_t& got, std::string& error) {
        bool done = false;
        boost::system::error_code result;
        got = 0;
        Wait w = Wait::TimedOut;
        const double left =
            timeout > 0.0 ? std::chrono::duration<double>(deadline - Clock::now()).count() : 0.0;
        if (timeout <= 0.0 || left > 0.0) {
            io->restart();
            auto handler = [&](const boost::system::error_code& ec, std::size_t k) {
                result = ec;
                got = k;
                done = true;
            };
            if (exact)
                asio::async_read(*socket, asio::buffer(data, n), handler);
            else
                socket->async_read_some(asio::buffer(data, n), handler);
            w = runUntil(*io, done, left, cancel);
        }
        if (w != Wait::Done) {
            abort(); // the pending handler runs here, while its captures live
            timedOut = w == Wait::TimedOut;
            error = timedOut ? "no reply within " + secondsText(timeout) : "cancelled";
            return false;
        }
        if (result) {
            eof = result == asio::error::eof;
            abort();
            error = eof ? (got == 0 ? "the peer closed the connection"
                                    : "the peer closed the connection in the middle of a frame (" +
                                          std::to_string(got) + " of " + std::to_string(n) +
                                          " bytes)")
                        : "connection lost: " + result.message();
            return false;
        }
        quickAck();
        return true;
    }

    void abort() {
        {
            std::lock_guard lock(fdMutex); // interrupt() never touches a closed descriptor
            fd = -1;
        }
        boost::system::error_code ec;
        socket->shutdown(tcp::socket::shutdown_both, ec);
        socket->close(ec);
        io->restart();
        io->run(); // the aborted handler runs here, before its captures go out of scope
        peer.clear();
        lineBuffer.clear();
    }
};

OfSocket::OfSocket() : d(std::make_unique<Impl>()) {}

OfSocket::~OfSocket() {
    close();
}

void OfSocket::setCancel(std::function<bool()> cancelled) {
    d->cancel = std::move(cancelled);
}

bool OfSocket::closedByPeer() const {
    return d->eof;
}

bool OfSocket::timedOut() const {
    return d->timedOut;
}

bool OfSocket::isOpen() const {
    return d->socket->is_open();
}

std::string OfSocket::peer() const {
    return d->peer;
}

void OfSocket::interrupt() {
    std::lock_guard lock(d->fdMutex);
    if (d->fd >= 0)
        ::shutdown(d->fd, SHUT_RDWR);
}

void OfSocket::close() {
    if (d->socket->is_open())
        d->abort();
}

void OfSocket::closeAfterPeer(double timeout) {
    if (!isOpen())
        return;
    std::uint8_t sink[4096];
    std::string error;
    for (;;) {
        bool done = false;
        boost::system::error_code result;
        d->io->restart();
        d->socket->async_read_some(asio::buffer(sink),
                                   [&](const boost::system::error_code& ec, std::size_t) {
                                       result = ec;
                                       done = true;
                                   });
        if (runUntil(*d->io, done, timeout, d->cancel) != Wait::Done) {
            d->abort(); // no close from the peer in time: an ordinary close
            return;
        }
        if (result == asio::error::eof) {
            {
                std::lock_guard lock(d->fdMutex);
                d->fd = -1;
            }
            boost::system::error_code ec;
            d->socket->set_option(asio::socket_base::linger(true, 0), ec);
            d->socket->close(ec);
            d->io->restart();
            d->io->run();
            d->peer.clear();
            return;
        }
        if (result) {
            d->abort();
            return;
        }
    }
}

bool OfSocket::connect(const std::string& host, std::uint16_t port, double timeout,
                       std::string& error) {
    close();
    d->eof = d->timedOut = false;
    const std::string where = host + ":" + std::to_string(port);
    tcp::resolver resolver(*d->io);
    bool done = false;
    boost::system::error_code result;
    d->io->restart();
    resolver.async_resolve(
        host, std::to_string(port),
        [&](const boost::system::error_code& ec, tcp::resolver::results_type endpoints) {
            if (ec) {
                result = ec;
                done = true;
                return;
            }
            asio::async_connect(*d->socket, endpoints,
                                [&](const boost::system::error_code& ec2, const tcp::endpoint&) {
                                    result = ec2;
                                    done = true;
                                });
        });
    const Wait w = runUntil(*d->io, done, timeout, d->cancel);
    if (w != Wait::Done) {
        resolver.cancel();
        d->abort();
        d->timedOut = w == Wait::TimedOut;
        error = w == Wait::TimedOut
                    ? "no connection to " + where + " within " + secondsText(timeout)
                    : "cancelled";
        return false;
    }
    if (result) {
        d->abort();
        error = "cannot connect to " + where + ": " + result.message();
        return false;
    }
    d->configure();
    return true;
}

bool OfSocket::write(const void* data, std::size_t n, double timeout, std::string& error) {
    d->eof = d->timedOut = false;
    if (!isOpen()) {
        error = "not connected";
        return false;
    }
    bool done = false;
    boost::system::error_code result;
    d->io->restart();
    asio::async_write(*d->socket, asio::buffer(data, n),
                      [&](const boost::system::error_code& ec, std::size_t) {
                          result = ec;
                          done = true;
                      });
    const Wait w = runUntil(*d->io, done, timeout, d->cancel);
    if (w != Wait::Done) {
        d->abort();
        d->timedOut = w == Wait::TimedOut;
        error = w == Wait::TimedOut ? "could not send within " + secondsText(timeout) : "cancelled";
        return false;
    }
    if (result) {
        d->abort();
        error = "connection lost while sending: " + result.message();
        return false;
    }
    return true;
}

bool OfSocket::read(void* data, std::size_t n, double timeout, std::string& error) {
    d->eof = d->timedOut = false;
    if (!isOpen()) {
        error = "not connected";
        return false;
    }
    std::size_t got = 0;
    return d->readInto(data, n, true, timeout, deadlineAfter(timeout), got, error);
}

struct OfListener::Impl {
    std::shared_ptr<asio::io_context> io = std::make_shared<asio::io_context>(1);
    tcp::acceptor acceptor{*io};
    std::function<bool()> cancel;
};

OfListener::OfListener() : d(std::make_unique<Impl>()) {}

OfListener::~OfListener() {
    close();
}

void OfListener::setCancel(std::function<bool()> cancelled) {
    d->cancel = std::move(cancelled);
}

bool OfListener::listen(const std::string& bind, std::uint16_t port, std::string& error) {
    return listenOn(d->acceptor, bind, port, error);
}

std::uint16_t OfListener::port() const {
    boost::system::error_code ec;
    const auto ep = d->acceptor.local_endpoint(ec);
    return ec ? 0 : ep.port();
}

void OfListener::close() {
    boost::system::error_code ec;
    d->acceptor.close(ec);
}

bool OfListener::pending() const {
    if (!d->acceptor.is_open())
        return false;
    pollfd p{d->acceptor.native_handle(), POLLIN, 0};
    return ::poll(&p, 1, 0) > 0 && (p.revents & POLLIN) != 0;
}

bool OfListener::accept(OfSocket& out, double timeout, std::string& error) {
    out.close();
    // The accepted socket lives on the listener's io_context (one thread serves both).
    out.d->io = d->io;
    out.d->socket = std::make_unique<tcp::socket>(*d->io);
    bool done = false;
    boost::system::error_code result;
    d->io->restart();
    d->acceptor.async_accept(*out.d->socket, [&](const boost::system::error_code& ec) {
        result = ec;
        done = true;
    });
    if (runUntil(*d->io, done, timeout, d->cancel) != Wait::Done) {
        boost::system::error_code ec;
        d->acceptor.cancel(ec);
        d->io->restart();
        d->io->run();
        out.close();
        error.clear();
        return false;
    }
    if (result) {
        out.close();
        error = "accept failed: " + result.message();
        return false;
    }
    out.d->configure();
    return true;
}

bool OfSocket::readLine(std::string& line, std::size_t maxBytes, double timeout,
                        std::string& error) {
    d->eof = d->timedOut = false;
    if (!isOpen()) {
        error = "not connected";
        return false;
    }
    const auto deadline = deadlineAfter(timeout);
    for (;;) {
        if (const auto nl = d->lineBuffer.find('\n'); nl != std::string::npos) {
            line.assign(d->lineBuffer, 0, nl);
            d->lineBuffer.erase(0, nl + 1);
            if (!line.empty() && line.back() == '\r')
                line.pop_back();
            return true;
        }
        if (d->lineBuffer.size() > maxBytes) {
            d->abort();
            error = "a line longer than " + std::to_string(maxBytes) + " bytes";
            return false;
        }
        char chunk[512];
        std::size_t got = 0;
        if (!d->readInto(chunk, sizeof chunk, false, timeout, deadline, got, error))
            return false;
        d->lineBuffer.append(chunk, got);
    }
}

} // namespace hsmu::comms::of
