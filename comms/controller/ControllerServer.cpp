#include "comms/controller/ControllerServer.h"

#include "comms/ListenSocket.h"
#include "comms/LogText.h"
#include "comms/controller/ControllerSession.h"
#include "comms/controller/SecretCompare.h"
#include "comms/tls/TlsContext.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/signal_set.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>

#include <deque>
#include <optional>
#include <map>

#include <pthread.h>
#include <sched.h>
#include <set>

namespace hsmu::comms {

namespace asio = boost::asio;
using Clock = std::chrono::steady_clock;

namespace {
/// Connections that have not been admitted yet (no valid hello): past this many, the oldest
/// is closed for the newcomer, so idle strangers can never lock out a token holder (each
/// must send its hello within 5 s anyway). Admitted connections are not counted.
constexpr std::size_t kMaxPending = 16;
/// Failed tokens: past kMaxTokenFailures per peer address in kTokenWindow, each further wrong
/// token is refused only after kLateRefusal (the connection held meanwhile), so guessing is
/// slow; the token is always compared, and the right one is admitted at once and clears the
/// address's failures: wrong guesses from the same host or NAT never keep the console out.
constexpr int kMaxTokenFailures = 5;
constexpr auto kTokenWindow = std::chrono::seconds(10);
constexpr double kLateRefusal = 1.0;                   // [s]
constexpr auto kSpin = std::chrono::microseconds(100); // real-time pace: see waitTick()
}

struct ControllerServer::Impl final : SessionHost {
    ControllerServerOptions opt;
    std::vector<std::unique_ptr<SpecimenStation>> stations;
    asio::io_context io{1};
    asio::ip::tcp::acceptor acceptor{io};
    asio::signal_set signals{io};
    asio::signal_set hangup{io}; // SIGHUP: reload the TLS files
    TlsContext tls;              // the listener's; replaced by a reload
    asio::steady_timer ticker{io};
    std::set<std::shared_ptr<ControllerSession>> sessions;
    std::deque<std::weak_ptr<ControllerSession>> pending; // accepted, not admitted, oldest first
    std::map<std::string, std::deque<Clock::time_point>> tokenFailures; // per peer address
    std::vector<ControllerSession*> stationSession; // the admitted connection per station
    bool hasOwner = false;
    std::uint64_t owner = 0;
    std::optional<std::uint64_t> lastSession; ///< the last admitted session (kept after it left)
    bool ticking = false;
    Clock::time_point nextTick;
    Clock::duration period;
    ControllerStatistics stats;

    Impl(const ControllerServerOptions& o, std::vector<std::unique_ptr<SpecimenStation>> st)
        : opt(o), stations(std::move(st)), stationSession(stations.size(), nullptr),
          period(std::chrono::duration_cast<Clock::duration>(
              std::chrono::duration<double>(1.0 / o.rate))) {}

    void log(const std::string& line) const {
        if (!opt.quiet)
            std::fprintf(stderr, "hsmu-controller: %s\n", line.c_str());
    }

    void accept() {
        acceptor.async_accept(
            [this](const boost::system::error_code& ec, asio::ip::tcp::socket socket) {
                if (ec == asio::error::operation_aborted)
                    return;
                if (!ec) {
                    auto stream = tls.ssl ? std::make_unique<ByteStream>(std::move(socket), tls, "")
                                          : std::make_unique<ByteStream>(std::move(socket));
                    auto s = std::make_shared<ControllerSession>(std::move(stream), *this);
                    sessions.insert(s);
                    pending.push_back(s);
                    s->start();
                    prunePending();
                }
                accept();
            });
    }

    bool reloadTls(std::string& error) {
        if (!opt.tls)
            return true;
        TlsContext fresh = makeTlsContext(*opt.tls, TlsRole::Server, error);
        if (!fresh.ssl)
            return false;
        tls = std::move(fresh);
        for (const auto& s : std::set<std::shared_ptr<ControllerSession>>(sessions))
            if (tls.policy->revoked.count(s->peerFingerprint())) {
                log("closing " + s->peer() + ": its certificate is now revoked");
                s->refuse({ErrorCode::Unauthorized, "the client certificate is revoked"});
            }
        return true;
    }

    void waitHangup() {
        hangup.async_wait([this](const boost::system::error_code& ec, int) {
            if (ec)
                return;
            std::string error;
            if (!opt.tls)
                log("SIGHUP: no TLS files to reload (this controller has no --tls-* options); "
                    "nothing changed");
            else if (reloadTls(error))
                log("SIGHUP: TLS files reloaded (" + std::to_string(tls.policy->pins.size()) +
                    " pins, " + std::to_string(tls.policy->revoked.size()) + " revoked" +
                    (opt.tls->crl.empty() ? std::string() : ", CRL " + opt.tls->crl) + ")");
            else
                log("SIGHUP: TLS reload refused, the previous files stay: " + error);
            waitHangup();
        });
    }

    void prunePending() {
        std::size_t live = 0;
        for (auto it = pending.begin(); it != pending.end();) {
            const auto s = it->lock();
            if (!s || s->admitted()) {
                it = pending.erase(it);
                continue;
            }
            ++live;
            ++it;
        }
        while (live > kMaxPending && !pending.empty()) {
            if (const auto oldest = pending.front().lock()) {
                log("too many connections without a hello: closing " + oldest->peer());
                oldest->refuse({ErrorCode::Busy, "too many connections without a hello"});
                --live;
            }
            pending.pop_front();
        }
    }

    static std::string addressOf(const std::string& peer) {
        const auto colon = peer.rfind(':');
        return colon == std::string::npos ? peer : peer.substr(0, colon);
    }

    /// Whether this address has used up its failed tokens; forgets failures past the window.
    bool tokenLocked(const std::string& address) {
        auto& q = tokenFailures[address];
        const auto now = Clock::now();
        while (!q.empty() && now - q.front() > kTokenWindow)
            q.pop_front();
        const std::size_t failures = q.size();
        if (failures == 0)
            tokenFailures.erase(address); // q dangles from here on
        return failures >= std::size_t(kMaxTokenFailures);
    }

    void dropped(ControllerSession& s, const std::string& why) override {
        log("dropped " + s.peer() + ": " + why);
    }

    bool ownerConnected() const {
        for (const auto& s : sessions)
            if (s->admitted() && s->sessionId() == owner)
                return true;
        return false;
    }

    std::optional<ErrorMsg> admit(ControllerSession& s, const HelloMsg& hello, HelloAckMsg& ack,
                                  double& delay) override {
        auto refuse = [&](ErrorCode c, std::string why) {
            ++stats.sessionsRefused;
            log("refused " + s.peer() + ": " + why);
            return std::optional<ErrorMsg>(ErrorMsg{c, std::move(why)});
        };
        if (!opt.token.empty()) {
            const std::string address = addressOf(s.peer());
            if (!sameSecret(hello.token, opt.token)) {
                const bool locked = tokenLocked(address);
                tokenFailures[address].push_back(Clock::now());
                if (!locked)
                    return refuse(ErrorCode::Unauthorized, "wrong token");
                delay = kLateRefusal;
                return refuse(ErrorCode::Unauthorized,
                              "wrong token; too many wrong tokens from " + address +
                                  ": each further one is refused after 1 s");
            }
            tokenFailures.erase(address);
        }
        int index = hello.element.empty() ? 0 : -1;
        for (std::size_t i = 0; i < stations.size() && index < 0; ++i)
            if (stations[i]->name() == hello.element)
                index = static_cast<int>(i);
        if (index < 0 || stations.empty())
            return refuse(ErrorCode::UnknownElement, "this controller has no specimen named '" +
                                                         logText(hello.element, 64) + "'");
        if (hasOwner && owner != hello.sessionId && ownerConnected())
            return refuse(ErrorCode::Busy,
                          "another console session is running a test on this controller "
                          "(one session at a time)");
        if (ControllerSession* old = stationSession[static_cast<std::size_t>(index)]) {
            log("connection " + old->peer() + " replaced by " + s.peer());
            old->send(ByeMsg{"replaced by a new connection of the same session"});
            old->close();
        }
        if (lastSession && *lastSession != hello.sessionId) {
            // A hold is per console session (docs/protocol.md, "Holds and sessions"): the
            // previous session's console hold ends with it; a trip stays and is reported.
            for (auto& station : stations)
                if (station->releaseConsoleHold())
                    log("specimen '" + station->name() + "': the previous session's hold ends "
                        "with it (a new session arms through its own pre-flight)");
        }
        hasOwner = true;
        owner = hello.sessionId;
        lastSession = hello.sessionId;
        s.setStation(index);
        stationSession[static_cast<std::size_t>(index)] = &s;
        ++stats.sessionsAdmitted;
        ack = stations[static_cast<std::size_t>(index)]->status();
        log("session " + s.peer() + " on specimen '" + ack.element + "' at step " +
            std::to_string(ack.committedSteps));
        return std::nullopt;
    }

    std::optional<Message> handle(ControllerSession& s, const Message& m) override {
        SpecimenStation& st = *stations[static_cast<std::size_t>(s.station())];
        std::optional<Message> reply;
        if (const auto* c = std::get_if<ConfigureMsg>(&m))
            reply = st.configure(*c);
        else if (std::holds_alternative<TargetMsg>(m) || std::holds_alternative<TargetsMsg>(m)) {
            if (opt.realTime)
                catchUp(); // the ticks due before this target arrived come first
            const auto* t = std::get_if<TargetMsg>(&m);
            reply = t ? st.target(*t) : st.targets(std::get<TargetsMsg>(m));
            if (opt.replyDelay > 0.0 && reply) {
                // Test setting: the measurement leaves replyDelay after the target came.
                auto timer = std::make_shared<asio::steady_timer>(
                    io, std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(opt.replyDelay)));
                timer->async_wait([timer, self = s.shared_from_this(),
                                   measured = std::move(*reply)](const boost::system::error_code& ec) {
                    if (!ec)
                        self->send(measured);
                });
                reply.reset();
            }
        } else if (const auto* c = std::get_if<CommitMsg>(&m))
            reply = st.commit(*c);
        else if (const auto* h = std::get_if<HoldMsg>(&m)) {
            reply = st.hold(h->reason);
            log("specimen '" + st.name() + "' holds at the console's request: " + h->reason);
        }
        else if (std::holds_alternative<ResumeMsg>(m))
            reply = st.resume();
        else if (std::holds_alternative<ResetMsg>(m))
            reply = st.reset();
        else
            reply = ErrorMsg{ErrorCode::ProtocolViolation, std::string("unexpected ") +
                                                               messageTypeName(messageTypeOf(m)) +
                                                               " from a console"};
        if (reply)
            if (const auto* e = std::get_if<ErrorMsg>(&*reply);
                e && (e->code == ErrorCode::Interlock || e->code == ErrorCode::SpecimenFault))
                log(e->reason);
        if (opt.realTime)
            armTicker();
        return reply;
    }

    void closed(ControllerSession& s) override {
        for (auto& p : stationSession)
            if (p == &s)
                p = nullptr;
        // Deferred: the session may be inside one of its own handlers.
        asio::post(io, [this, self = s.shared_from_this()] {
            sessions.erase(self);
            if (hasOwner && !ownerConnected())
                hasOwner = false;
        });
    }

    double idleTimeout() const override { return opt.idleTimeout; }

    bool anyNeedsTicks() const {
        for (const auto& st : stations)
            if (st->needsTicks())
                return true;
        return false;
    }

    void tickAll() {
        ++stats.ticks;
        for (std::size_t i = 0; i < stations.size(); ++i)
            if (auto m = stations[i]->tick())
                if (stationSession[i])
                    stationSession[i]->send(*m);
    }

    void catchUp() {
        if (!ticking)
            return;
        const auto now = Clock::now();
        while (nextTick <= now) {
            const auto late = now - nextTick;
            if (late > period)
                ++stats.deadlineMisses;
            stats.maxLateness =
                std::max(stats.maxLateness, std::chrono::duration<double>(late).count());
            tickAll();
            nextTick += period;
        }
    }

    void armTicker() {
        if (ticking || !anyNeedsTicks())
            return;
        ticking = true;
        nextTick = Clock::now() + period;
        waitTick();
    }

    void waitTick() {
        // Wake kSpin before the deadline and spin to it: the timer's wake-up jitter (timer
        // slack, the reactor) then delays no tick.
        ticker.expires_at(nextTick - kSpin);
        ticker.async_wait([this](const boost::system::error_code& ec) {
            if (ec)
                return;
            while (Clock::now() < nextTick) {
            }
            catchUp();
            if (anyNeedsTicks()) {
                waitTick();
            } else {
                ticking = false;
            }
        });
    }
};

ControllerServer::ControllerServer(const ControllerServerOptions& options,
                                   std::vector<std::unique_ptr<SpecimenStation>> stations)
    : d(std::make_unique<Impl>(options, std::move(stations))) {}

ControllerServer::~ControllerServer() = default;

bool ControllerServer::reloadTls(std::string& error) {
    return d->reloadTls(error);
}

bool ControllerServer::listen(std::string& error) {
    if (d->opt.tls && !d->reloadTls(error))
        return false;
    if (!listenOn(d->acceptor, d->opt.bind, d->opt.port, error, "--bind: "))
        return false;
    // SIGHUP handled before anyone is told the port (its default action would end the
    // process): TLS files reloaded, or, without TLS, said and ignored. Served by run().
    d->hangup.add(SIGHUP);
    d->waitHangup();
    d->accept();
    return true;
}

std::uint16_t ControllerServer::port() const {
    boost::system::error_code ec;
    const auto ep = d->acceptor.local_endpoint(ec);
    return ec ? 0 : ep.port();
}

void ControllerServer::run() {
    d->signals.add(SIGINT);
    d->signals.add(SIGTERM);
    d->signals.async_wait([this](const boost::system::error_code& ec, int) {
        if (!ec)
            stop();
    });
    if (d->opt.realTime && d->opt.realTimePriority > 0) {
        sched_param sp{};
        sp.sched_priority = d->opt.realTimePriority;
        if (const int e = pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp); e != 0)
            d->log(std::string("real-time priority refused (") + std::strerror(e) +
                   "): the loop runs at normal priority");
    }
    if (d->opt.realTime)
        d->armTicker();
    d->io.run();
}

void ControllerServer::stop() {
    asio::post(d->io, [this] {
        boost::system::error_code ec;
        d->acceptor.close(ec);
        d->ticker.cancel();
        d->signals.cancel();
        d->hangup.cancel();
        for (const auto& s : std::set<std::shared_ptr<ControllerSession>>(d->sessions)) {
            s->send(ByeMsg{"controller shutting down"});
            s->close();
        }
        d->io.stop();
    });
}

ControllerStatistics ControllerServer::statistics() const {
    return d->stats;
}

} // namespace hsmu::comms
