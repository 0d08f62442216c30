#include "comms/link/LinkClient.h"

#include "comms/protocol/FrameDecoder.h"
#include "comms/tls/ByteStream.h"

#include <boost/asio/connect.hpp>
#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>

#include <array>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

namespace hsmu::comms {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;
using Clock = std::chrono::steady_clock;

namespace {

Clock::duration seconds(double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

std::string secondsText(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g s", s);
    return buf;
}

struct Conn {
    explicit Conn(std::unique_ptr<ByteStream> s) : stream(std::move(s)) {}
    std::unique_ptr<ByteStream> stream;
    bool received = false; // any byte yet
    FrameDecoder decoder;
    std::array<std::uint8_t, 8192> buffer{};
    std::deque<std::vector<std::uint8_t>> writes;
    bool writing = false;
    bool closed = false;
    std::uint32_t sequence = 1;
};

struct ConnectState {
    std::mutex mu;
    std::condition_variable cv;
    bool done = false, cancelled = false;
    std::string error;
    std::shared_ptr<Conn> conn;
    std::shared_ptr<tcp::resolver> resolver;
};

} // namespace

struct LinkClient::Impl {
    LinkClientOptions opt;
    asio::io_context io{1};
    asio::executor_work_guard<asio::io_context::executor_type> work{asio::make_work_guard(io)};
    asio::steady_timer heartbeat{io};
    std::thread thread;
    // io thread only
    std::shared_ptr<Conn> conn;
    Clock::time_point lastSent, lastReceived;
    std::uint64_t nonce = 0;
    // shared with the caller
    mutable std::mutex mu;
    std::condition_variable cv;
    struct Arrived {
        Message message;
        Clock::time_point at;
    };
    std::deque<Arrived> inbox;
    bool open = false;
    bool interrupted = false;
    std::string reason;

    explicit Impl(const LinkClientOptions& o) : opt(o) {
        thread = std::thread([this] { io.run(); });
        asio::post(io, [this] { armHeartbeat(); });
    }

    ~Impl() {
        asio::post(io, [this] {
            if (conn)
                fail(conn, "closed by the console");
            heartbeat.cancel();
            io.stop();
        });
        work.reset();
        thread.join();
    }

    void fail(const std::shared_ptr<Conn>& c, const std::string& why) {
        if (c->closed)
            return;
        c->closed = true;
        c->stream->close();
        if (conn != c)
            return;
        conn.reset();
        std::lock_guard lock(mu);
        open = false;
        if (reason.empty())
            reason = why;
        cv.notify_all();
    }

    void read(const std::shared_ptr<Conn>& c) {
        c->stream->asyncReadSome(
            asio::buffer(c->buffer), [this, c](const boost::system::error_code& ec, std::size_t n) {
                if (c->closed)
                    return;
                if (ec) {
                    fail(c, readFailure(*c->stream, ec));
                    return;
                }
                if (!c->received && !c->stream->tls() && looksLikeTls(c->buffer.data(), n)) {
                    fail(c, "the controller speaks TLS on this port: connect with "
                            "tls://HOST:PORT and the configuration's tls block");
                    return;
                }
                c->received = true;
                lastReceived = Clock::now();
                c->decoder.append(c->buffer.data(), n);
                Frame f;
                for (;;) {
                    const auto st = c->decoder.next(f);
                    if (st == FrameDecoder::Status::NeedMore)
                        break;
                    if (st == FrameDecoder::Status::Error) {
                        fail(c,
                             "malformed frame from the controller: " + c->decoder.error().reason);
                        return;
                    }
                    if (std::holds_alternative<HeartbeatMsg>(f.message))
                        continue;
                    std::lock_guard lock(mu);
                    inbox.push_back({std::move(f.message), Clock::now()});
                    cv.notify_all();
                }
                read(c);
            });
    }

    void write(const std::shared_ptr<Conn>& c) {
        if (c->writing || c->writes.empty() || c->closed)
            return;
        c->writing = true;
        c->stream->asyncWrite(asio::buffer(c->writes.front()),
                          [this, c](const boost::system::error_code& ec, std::size_t) {
                              c->writing = false;
                              if (c->closed)
                                  return;
                              if (ec) {
                                  fail(c, "connection lost while sending: " + ec.message());
                                  return;
                              }
                              c->writes.pop_front();
                              write(c);
                          });
    }

    void queue(const Message& m) {
        if (!conn || conn->closed)
            return;
        std::vector<std::uint8_t> bytes;
        encodeFrame(m, conn->sequence++, bytes);
        conn->writes.push_back(std::move(bytes));
        lastSent = Clock::now();
        write(conn);
    }

    static std::string readFailure(const ByteStream& s, const boost::system::error_code& ec) {
        if (ec == asio::error::eof || ec == asio::ssl::error::stream_truncated)
            return "the controller closed the connection";
        if (ec.category() == asio::error::get_ssl_category())
            return "the controller ended the TLS session: " +
                   tlsFailureText(ec, s.verifyFailure()) +
                   " (it refuses this console's certificate: see its log)";
        return "connection lost: " + ec.message();
    }

    void armHeartbeat() {
        heartbeat.expires_after(seconds(std::max(0.005, opt.heartbeatInterval / 2)));
        heartbeat.async_wait([this](const boost::system::error_code& ec) {
            if (ec)
                return;
            const auto now = Clock::now();
            if (conn && !conn->closed) {
                if (now - lastReceived > seconds(opt.silenceTimeout))
                    fail(conn, "the controller was silent for " + secondsText(opt.silenceTimeout));
                else if (now - lastSent >= seconds(opt.heartbeatInterval))
                    queue(HeartbeatMsg{++nonce});
            }
            armHeartbeat();
        });
    }
};

LinkClient::LinkClient(const LinkClientOptions& options) : d(std::make_unique<Impl>(options)) {}

LinkClient::~LinkClient() = default;

bool LinkClient::connect(const std::string& host, std::uint16_t port, double timeout,
                         std::string& error) {
    close();
    auto st = std::make_shared<ConnectState>();
    const std::string where = host + ":" + std::to_string(port);
    TlsContext tls;
    if (d->opt.tls) {
        tls = makeTlsContext(*d->opt.tls, TlsRole::Client, error);
        if (!tls.ssl) {
            error = "tls://" + where + ": " + error;
            return false;
        }
    }
    asio::post(d->io, [this, st, host, port, where, tls] {
        tcp::socket socket(d->io);
        auto stream = tls.ssl ? std::make_unique<ByteStream>(std::move(socket), tls, host)
                              : std::make_unique<ByteStream>(std::move(socket));
        st->conn = std::make_shared<Conn>(std::move(stream));
        st->resolver = std::make_shared<tcp::resolver>(d->io);
        auto finish = [st](std::string e) {
            std::lock_guard lock(st->mu);
            st->done = true;
            st->error = std::move(e);
            st->cv.notify_all();
        };
        // Connected (and, over TLS, handshaken): the link is this connection from now on.
        auto install = [this, st] {
            std::lock_guard lock(st->mu);
            if (st->cancelled) {
                st->conn->stream->close();
                return;
            }
            d->conn = st->conn;
            d->lastReceived = d->lastSent = Clock::now();
            {
                std::lock_guard lock2(d->mu);
                d->inbox.clear();
                d->open = true;
                d->reason.clear();
            }
            d->read(d->conn);
            st->done = true;
            st->cv.notify_all();
        };
        st->resolver->async_resolve(
            host, std::to_string(port),
            [st, where, finish, install](const boost::system::error_code& ec,
                                         tcp::resolver::results_type results) {
                if (ec) {
                    finish("cannot resolve " + where + ": " + ec.message());
                    return;
                }
                asio::async_connect(
                    st->conn->stream->socket(), results,
                    [st, where, finish, install](const boost::system::error_code& ec2,
                                                 const tcp::endpoint&) {
                        if (ec2) {
                            finish("cannot connect to " + where + ": " + ec2.message());
                            return;
                        }
                        boost::system::error_code ignore;
                        st->conn->stream->socket().set_option(tcp::no_delay(true), ignore);
                        if (!st->conn->stream->tls()) {
                            install();
                            return;
                        }
                        auto handshaken = [st, where, finish,
                                           install](const boost::system::error_code& ec3) {
                            if (!ec3) {
                                install();
                                return;
                            }
                            const std::string& v = st->conn->stream->verifyFailure();
                            finish("TLS handshake with " + where + " failed: " +
                                   tlsFailureText(ec3, v.empty() ? ""
                                                                 : "the controller's certificate: " +
                                                                       v) +
                                   (v.empty() ? "; is the controller listening without TLS "
                                                "(tcp:// for a plaintext controller)?"
                                              : ""));
                        };
                        st->conn->stream->asyncHandshake(false, handshaken);
                    });
            });
    });
    std::unique_lock lock(st->mu);
    if (!st->cv.wait_for(lock, seconds(timeout), [&] { return st->done; })) {
        st->cancelled = true;
        lock.unlock();
        asio::post(d->io, [st] {
            boost::system::error_code ignore;
            if (st->resolver)
                st->resolver->cancel();
            if (st->conn)
                st->conn->stream->close();
        });
        error = "no connection to " + where + " within " + secondsText(timeout);
        return false;
    }
    if (!st->error.empty()) {
        error = st->error;
        return false;
    }
    return true;
}

void LinkClient::close() {
    {
        std::lock_guard lock(d->mu);
        if (d->open && d->reason.empty())
            d->reason = "closed by the console";
        d->open = false;
        d->cv.notify_all();
    }
    asio::post(d->io, [this] {
        if (d->conn)
            d->fail(d->conn, "closed by the console");
    });
}

bool LinkClient::isOpen() const {
    std::lock_guard lock(d->mu);
    return d->open;
}

std::string LinkClient::closeReason() const {
    std::lock_guard lock(d->mu);
    return d->reason;
}

bool LinkClient::send(const Message& m, std::string& error) {
    if (!isOpen()) {
        error = "not connected: " + closeReason();
        return false;
    }
    asio::post(d->io, [this, m] { d->queue(m); });
    return true;
}

bool LinkClient::sendRaw(std::vector<std::uint8_t> bytes, std::string& error) {
    if (!isOpen()) {
        error = "not connected: " + closeReason();
        return false;
    }
    asio::post(d->io, [this, b = std::move(bytes)]() mutable {
        if (!d->conn || d->conn->closed)
            return;
        d->conn->writes.push_back(std::move(b));
        d->write(d->conn);
    });
    return true;
}

void LinkClient::interrupt() {
    std::lock_guard lock(d->mu);
    d->interrupted = true;
    d->cv.notify_all();
}

void LinkClient::clearInterrupt() {
    std::lock_guard lock(d->mu);
    d->interrupted = false;
}

std::optional<Message> LinkClient::receive(double timeout, std::string& error,
                                           std::chrono::steady_clock::time_point* arrived) {
    std::unique_lock lock(d->mu);
    d->cv.wait_for(lock, seconds(timeout),
                   [&] { return !d->inbox.empty() || !d->open || d->interrupted; });
    if (d->interrupted) {
        d->interrupted = false;
        error = "interrupted";
        return std::nullopt;
    }
    if (!d->inbox.empty()) {
        Message m = std::move(d->inbox.front().message);
        if (arrived)
            *arrived = d->inbox.front().at;
        d->inbox.pop_front();
        return m;
    }
    if (!d->open)
        error = d->reason.empty() ? std::string("not connected") : d->reason;
    else
        error = "no reply within " + secondsText(timeout);
    return std::nullopt;
}

} // namespace hsmu::comms
