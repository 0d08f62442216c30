#include "LoopbackProxy.h"

#include "comms/protocol/FrameCodec.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>

#include <array>
#include <atomic>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

namespace asio = boost::asio;
using tcp = asio::ip::tcp;
using hsmu::comms::MessageType;

namespace {

struct Pair : std::enable_shared_from_this<Pair> {
    Pair(asio::io_context& io, tcp::socket s) : down(std::move(s)), up(io) {}
    tcp::socket down, up;
    std::array<std::uint8_t, 8192> downBuf{}, upBuf{};
    std::vector<std::uint8_t> pending; // console bytes not yet forming a whole frame
    bool closed = false;
    bool muted = false; // after a cut: the controller's answers are swallowed
    void close() {
        if (closed)
            return;
        closed = true;
        boost::system::error_code ec;
        down.close(ec);
        up.close(ec);
    }
};

} // namespace

struct LoopbackProxy::Impl {
    asio::io_context io{1};
    tcp::acceptor acceptor{io};
    std::uint16_t upstream;
    std::set<std::shared_ptr<Pair>> pairs;
    std::mutex mu;
    bool armed = false;
    MessageType cutType = MessageType::Target;
    int cutCount = 0, seen = 0;
    std::atomic<int> cuts{0};
    std::thread thread;

    void accept() {
        acceptor.async_accept([this](const boost::system::error_code& ec, tcp::socket s) {
            if (ec)
                return;
            auto p = std::make_shared<Pair>(io, std::move(s));
            pairs.insert(p);
            p->up.async_connect(tcp::endpoint(asio::ip::address_v4::loopback(), upstream),
                                [this, p](const boost::system::error_code& e) {
                                    if (e) {
                                        p->close();
                                        return;
                                    }
                                    boost::system::error_code ignore;
                                    p->up.set_option(tcp::no_delay(true), ignore);
                                    p->down.set_option(tcp::no_delay(true), ignore);
                                    pumpDown(p);
                                    pumpUp(p);
                                });
            accept();
        });
    }

    // controller -> console: raw bytes
    void pumpUp(const std::shared_ptr<Pair>& p) {
        p->up.async_read_some(asio::buffer(p->upBuf),
                              [this, p](const boost::system::error_code& ec, std::size_t n) {
                                  if (ec || p->closed) {
                                      p->close();
                                      return;
                                  }
                                  boost::system::error_code wec;
                                  if (!p->muted)
                                      asio::write(p->down, asio::buffer(p->upBuf.data(), n), wec);
                                  if (wec) {
                                      p->close();
                                      return;
                                  }
                                  pumpUp(p);
                              });
    }

    // console -> controller: whole frames, counted, so a cut falls exactly after one
    void pumpDown(const std::shared_ptr<Pair>& p) {
        p->down.async_read_some(asio::buffer(p->downBuf), [this,
                                                           p](const boost::system::error_code& ec,
                                                              std::size_t n) {
            if (ec || p->closed) {
                p->close();
                return;
            }
            p->pending.insert(p->pending.end(), p->downBuf.begin(), p->downBuf.begin() + n);
            std::size_t used = 0;
            bool cut = false;
            while (!cut && p->pending.size() - used >= hsmu::comms::kHeaderSize) {
                const auto h = hsmu::comms::readHeader(p->pending.data() + used);
                const std::size_t size = hsmu::comms::kHeaderSize + h.length;
                if (p->pending.size() - used < size)
                    break;
                boost::system::error_code wec;
                asio::write(p->up, asio::buffer(p->pending.data() + used, size), wec);
                used += size;
                std::lock_guard lock(mu);
                if (armed && h.type == static_cast<std::uint16_t>(cutType) && ++seen == cutCount)
                    cut = true;
            }
            p->pending.erase(p->pending.begin(), p->pending.begin() + used);
            if (cut) {
                {
                    std::lock_guard lock(mu);
                    armed = false;
                }
                ++cuts;
                for (const auto& q : pairs)
                    q->muted = true;
                // Let the controller read the frame before the connection goes.
                auto t = std::make_shared<asio::steady_timer>(io, std::chrono::milliseconds(50));
                t->async_wait([this, t](const boost::system::error_code&) {
                    for (const auto& q : pairs)
                        q->close();
                    pairs.clear();
                });
                return;
            }
            pumpDown(p);
        });
    }
};

LoopbackProxy::LoopbackProxy(std::uint16_t upstreamPort) : d(std::make_unique<Impl>()) {
    d->upstream = upstreamPort;
    const tcp::endpoint ep(asio::ip::address_v4::loopback(), 0);
    d->acceptor.open(ep.protocol());
    d->acceptor.set_option(asio::socket_base::reuse_address(true));
    d->acceptor.bind(ep);
    d->acceptor.listen();
    d->accept();
    d->thread = std::thread([this] { d->io.run(); });
}

LoopbackProxy::~LoopbackProxy() {
    asio::post(d->io, [this] {
        boost::system::error_code ec;
        d->acceptor.close(ec);
        for (const auto& p : d->pairs)
            p->close();
        d->pairs.clear();
        d->io.stop();
    });
    d->thread.join();
}

std::uint16_t LoopbackProxy::port() const {
    return d->acceptor.local_endpoint().port();
}

void LoopbackProxy::cutAfter(MessageType type, int count) {
    std::lock_guard lock(d->mu);
    d->armed = true;
    d->cutType = type;
    d->cutCount = count;
    d->seen = 0;
}

int LoopbackProxy::cuts() const {
    return d->cuts.load();
}
