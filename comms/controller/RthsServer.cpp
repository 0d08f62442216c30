#include "comms/controller/RthsServer.h"

#include "comms/ListenSocket.h"
#include "comms/controller/ControllerSession.h"
#include "comms/controller/SecretCompare.h"
#include "comms/tls/ByteStream.h"
#include "comms/rths/RthsMonitor.h"
#include "core/record/RthsRecord.h"
#include "core/rths/RthsRunner.h"
#include "core/updating/TwinProposals.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/signal_set.hpp>

#include <atomic>
#include <mutex>
#include <utility>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <set>
#include <sstream>
#include <thread>

namespace hsmu::comms {

namespace asio = boost::asio;

namespace {
/// How often the io thread drains the telemetry ring and looks for the run's end.
constexpr auto kPoll = std::chrono::milliseconds(2);
} // namespace

struct RthsServer::Impl final : SessionHost {
    RthsServerOptions opt;
    RthsJob job;
    asio::io_context io{1};
    asio::ip::tcp::acceptor acceptor{io};
    asio::signal_set signals{io};
    asio::steady_timer poll{io};
    std::set<std::shared_ptr<ControllerSession>> sessions;
    ControllerSession* monitor = nullptr;

    // The run (one at a time).
    MonotonicClock monotonic;
    std::unique_ptr<SpinningClock> clock;
    std::unique_ptr<RealtimePacer> pacer;
    std::unique_ptr<MonitorGate> gate;
    std::unique_ptr<FastPaceGate> fastGate; ///< the fast pace's: waits for the ring to drain
    std::unique_ptr<TelemetryFeed> feed;
    std::unique_ptr<rths::RthsRecording> record;      // --record: this run's record.h5
    rths::TickObservers observers;                    // feed, then the record, then outbox
    UpdateOutbox outbox;                              // the twin's update decisions
    std::unique_ptr<rths::PostedTwinUpdates> posted;  // the monitor's rths-update
    std::unique_ptr<rths::TwinIdentification> identification; // the damper's, online
    std::unique_ptr<rths::TwinProposals> proposals;   // its offers for approval ("approve")
    rths::TwinUpdateSources sources;                  // identification, then posted
    std::unique_ptr<rths::RthsRunner> runner;         // the run; kept while held (resume)
    std::thread loop;
    std::atomic<bool> finished{false};
    bool running = false;
    bool held = false;      ///< the last run held and may resume (its runner kept)
    rths::RthsRun result;
    std::string loopError, priorityRefusal;
    std::string holdAsked;  ///< the hold's sentence as requested (io thread)
    long undelivered = 0;   ///< samples taken from the ring with no monitor to send them to
    long sent = 0;          ///< telemetry frames handed to the monitor's session
    bool stopping = false;

    Impl(const RthsServerOptions& o, RthsJob j) : opt(o), job(std::move(j)) {}

    std::string describe() const {
        std::ostringstream o;
        o << "RTHS loop '" << job.name << "', " << job.settings.rate << " Hz, "
          << job.groundMotion.duration() << " s record, "
          << (opt.recordDirectory.empty() ? std::string("no record on the controller")
                                          : "recording each run in " + opt.recordDirectory);
        return o.str();
    }

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
                    // Plain TCP: the RTHS monitor link has no TLS yet (docs/rths.md).
                    auto s = std::make_shared<ControllerSession>(
                        std::make_unique<ByteStream>(std::move(socket)), *this);
                    sessions.insert(s);
                    s->start();
                }
                accept();
            });
    }

    std::optional<ErrorMsg> admit(ControllerSession& s, const HelloMsg& hello, HelloAckMsg& ack,
                                  double&) override {
        if (!opt.token.empty() && !sameSecret(hello.token, opt.token)) {
            log("refused " + s.peer() + ": wrong token");
            return ErrorMsg{ErrorCode::Unauthorized, "wrong token"};
        }
        if (monitor) {
            log("refused " + s.peer() + ": a monitor is connected");
            return ErrorMsg{ErrorCode::Busy, "another console monitors this RTHS loop (one at a time)"};
        }
        monitor = &s;
        ack.element = job.name;
        ack.description = describe();
        ack.holding = held || (gate && gate->holdRequested());
        ack.holdReason = held ? result.hold : holdAsked;
        log("monitor " + s.peer() + (running ? " joins the running loop" : " connected"));
        return std::nullopt;
    }

    std::optional<Message> handle(ControllerSession& s, const Message& m) override {
        if (const auto* start = std::get_if<RthsStartMsg>(&m))
            return startRun(*start);
        if (const auto* h = std::get_if<HoldMsg>(&m)) {
            requestHold("console hold (" + h->reason + ")");
            return AckMsg{MessageType::Hold, 0};
        }
        if (const auto* e = std::get_if<EmergencyHoldMsg>(&m)) {
            requestHold("emergency hold (" + e->reason + ")");
            return AckMsg{MessageType::EmergencyHold, 0};
        }
        if (const auto* u = std::get_if<RthsUpdateMsg>(&m))
            return update(*u);
        if (const auto* d = std::get_if<RthsDecisionMsg>(&m))
            return decide(*d);
        (void)s;
        if (std::holds_alternative<ResumeMsg>(m))
            return resumeRun();
        return ErrorMsg{ErrorCode::ProtocolViolation, std::string("unexpected ") +
                                                          messageTypeName(messageTypeOf(m)) +
                                                          " on an RTHS controller"};
    }

    /// rths-update: checked now (refused: nothing applied), applied before the next tick.
    std::optional<Message> update(const RthsUpdateMsg& m) {
        if (!running || !posted || finished.load(std::memory_order_acquire))
            return ErrorMsg{ErrorCode::UpdateRefused, "rths-update refused: no run in progress; nothing applied"};
        rths::TwinUpdate u{m.names, m.values, "operator", 0};
        if (const std::string why = rths::checkTwinUpdate(job.settings.damper, u); !why.empty()) {
            log("rths-update refused: " + why + "; nothing applied");
            return ErrorMsg{ErrorCode::UpdateRefused, "rths-update refused: " + why + "; nothing applied"};
        }
        posted->post(std::move(u));
        return AckMsg{MessageType::RthsUpdate, 0};
    }

    /// rths-decision: the operator approves (applied before the next tick) or rejects a proposal.
    std::optional<Message> decide(const RthsDecisionMsg& m) {
        if (!proposals || !running)
            return ErrorMsg{ErrorCode::UpdateRefused, "rths-decision refused: no run with proposals in progress"};
        const int id = int(m.id);
        const std::string why = m.approve ? proposals->approve(id) : proposals->reject(id);
        if (!why.empty()) {
            log("rths-decision refused: " + why);
            return ErrorMsg{ErrorCode::UpdateRefused, "rths-decision refused: " + why};
        }
        std::string line = "proposal #";
        line += std::to_string(id);
        line += m.approve ? " approved: applied before the loop's next tick" : " rejected";
        log(line);
        return AckMsg{MessageType::RthsDecision, 0};
    }

    void requestHold(const std::string& why) {
        if (!running) {
            log(why + ": no run in progress");
            return;
        }
        if (holdAsked.empty())
            holdAsked = why;
        gate->requestHold(why);
        log(why + ": the loop holds before its next tick");
    }

    void closed(ControllerSession& s) override {
        if (monitor == &s) {
            monitor = nullptr;
            if (running && !stopping) {
                if (opt.holdOnMonitorLoss)
                    requestHold("monitor link lost (" + s.peer() + ")");
                else
                    log("monitor link lost (" + s.peer() +
                        "): the loop goes on (--monitor-loss continue)");
            }
        }
        asio::post(io, [this, self = s.shared_from_this()] { sessions.erase(self); });
    }

    double idleTimeout() const override { return opt.idleTimeout; }
    void dropped(ControllerSession& s, const std::string& why) override {
        log("dropped " + s.peer() + ": " + why);
    }

    /// resume: the held run goes on from the tick where it held (RthsRunner::resume), or the
    /// reason it does not (Error(holding), the run stays held).
    std::optional<Message> resumeRun() {
        if (running)
            return ErrorMsg{ErrorCode::ProtocolViolation, "resume: the RTHS run is not held"};
        if (!held || !runner)
            return ErrorMsg{ErrorCode::ProtocolViolation,
                            "resume: no held RTHS run to resume (rths-start runs from rest)"};
        const std::string why = runner->resume();
        if (!why.empty()) {
            log("resume refused: " + why);
            return ErrorMsg{ErrorCode::Holding, why};
        }
        held = false;
        const long k = runner->next();
        std::ostringstream o;
        o.precision(6);
        o << "RTHS run resumed before tick " << k << " (t = " << double(k) / job.settings.rate << " s)";
        log(o.str());
        startLoop();
        return AckMsg{MessageType::Resume, 0};
    }

    /// The loop's thread: runner->run() until the end or a hold, then the run so far evaluated.
    void startLoop() {
        finished = false;
        running = true;
        holdAsked.clear();
        loopError.clear();
        priorityRefusal.clear();
        loop = std::thread([this] {
            if (opt.realTime && opt.realTimePriority > 0)
                priorityRefusal = enterRealtimePriority(opt.realTimePriority);
            try {
                runner->run();
                result = runner->result();
            } catch (const std::exception& e) {
                result = {};
                loopError = e.what();
            }
            finished.store(true, std::memory_order_release);
        });
        armPoll();
    }

    /// A held run given up (a new rths-start, the controller's end): its record closed.
    void discardHeld() {
        if (!held)
            return;
        held = false;
        proposals.reset();
        identification.reset();
        closeRecord();
        runner.reset();
    }

    std::optional<Message> startRun(const RthsStartMsg& m) {
        if (running)
            return ErrorMsg{ErrorCode::ProtocolViolation, "an RTHS run is in progress"};
        discardHeld();
        if (!(m.duration >= 0.0 && std::isfinite(m.duration)))
            return ErrorMsg{ErrorCode::ProtocolViolation, "rths-start: the duration must be >= 0 s"};
        const double h = 1.0 / job.settings.rate;
        if (opt.realTime && opt.spinMicros >= h * 1e6)
            return ErrorMsg{ErrorCode::ProtocolViolation,
                            "rths-start: --spin-us must stay below the loop period"};
        std::string error;
        if (!opt.recordDirectory.empty() && !openRecord(h, error))
            return ErrorMsg{ErrorCode::ProtocolViolation, "rths-start: " + error};
        clock = std::make_unique<SpinningClock>(
            monotonic, opt.spinMicros < 0.0 ? defaultSpinMargin(h)
                                            : std::chrono::nanoseconds(std::int64_t(opt.spinMicros * 1e3)));
        pacer = opt.realTime ? std::make_unique<RealtimePacer>(*clock, h, job.holdAfterMisses) : nullptr;
        gate = std::make_unique<MonitorGate>(pacer.get(), h);
        const long every = m.decimation > 0 ? long(m.decimation) : defaultDecimation(job.settings.rate);
        feed = std::make_unique<TelemetryFeed>(*gate, every);
        fastGate = opt.realTime ? nullptr : std::make_unique<FastPaceGate>(*gate, *feed);
        observers = {};
        observers.add(feed.get());
        observers.add(record ? record->feed() : nullptr);
        observers.add(&outbox);
        outbox.take();
        sources = {};
        posted.reset();
        proposals.reset();
        identification.reset();
        if (job.settings.damper.enabled) {
            if (job.identification.enabled) {
                rths::TwinIdentificationSettings is = job.identification;
                is.wait = !opt.realTime;
                identification = std::make_unique<rths::TwinIdentification>(job.settings.damper, is,
                                                                            job.settings.rate);
                if (is.approve)
                    proposals = std::make_unique<rths::TwinProposals>(*identification, job.settings.damper,
                                                                      job.settings.rate, !opt.realTime);
                sources.add(proposals ? static_cast<rths::TwinUpdateSource*>(proposals.get())
                                      : identification.get());
            }
            posted = std::make_unique<rths::PostedTwinUpdates>(!opt.realTime);
            sources.add(posted.get());
        }
        undelivered = sent = 0;
        rths::TickGate* g = fastGate ? static_cast<rths::TickGate*>(fastGate.get()) : gate.get();
        runner = std::make_unique<rths::RthsRunner>(job.partition, job.groundMotion, job.settings, g,
                                                    m.duration, &observers,
                                                    sources.empty() ? nullptr : &sources);
        startLoop();
        std::ostringstream o;
        o << "RTHS run started: " << job.settings.rate << " Hz, "
          << (opt.realTime ? "real-time" : "fast") << " pace, telemetry every " << every
          << " ticks";
        log(o.str());
        return AckMsg{MessageType::RthsStart, 0};
    }

    /// The first free DIR/record.h5, DIR/record-2.h5, ... (an earlier run's record is never
    /// overwritten), opened for this run; false with the reason.
    bool openRecord(double h, std::string& error) {
        try {
            record = std::make_unique<rths::RthsRecording>(
                opt.recordDirectory, RecordStart{job.configuration, job.name, {}, h}, job.groundMotion,
                int(job.partition.reference.m.rows()));
        } catch (const std::exception& e) {
            error = e.what();
            return false;
        }
        return true;
    }

    bool deadlineHold() const { return pacer && pacer->policyHolds(); }

    /// The run's record: its hold as a critical alarm, then closed (after the loop's join).
    void closeRecord() {
        if (!record)
            return;
        if (record->finish(result, deadlineHold()))
            log("record: " + record->path() + " (" + std::to_string(result.time.size()) + " ticks)");
        else
            log("record: " + record->path() + ": " + record->error());
        record.reset();
    }

    /// A held run's record: the hold's alarm written and flushed, the file kept open for a resume.
    void holdRecord() {
        if (!record)
            return;
        if (record->held(result, deadlineHold()))
            log("record: " + record->path() + " (" + std::to_string(result.time.size()) +
                " ticks; held: the ticks after a resume follow)");
        else
            log("record: " + record->path() + ": " + record->error());
    }

    void armPoll() {
        poll.expires_after(kPoll);
        poll.async_wait([this](const boost::system::error_code& ec) {
            if (ec)
                return;
            const bool done = finished.load(std::memory_order_acquire);
            drain();
            if (done && (!monitor || feed->pending() == 0))
                endRun();
            else
                armPoll();
        });
    }

    void drain() {
        for (const UpdateEvent& e : outbox.take()) {
            log(rths::describeTwinUpdate(e));
            if (!monitor)
                continue;
            const bool proposalOnly = e.decision == UpdateDecision::Proposed ||
                                      e.decision == UpdateDecision::Superseded ||
                                      e.decision == UpdateDecision::Rejected;
            if (!proposalOnly)
                monitor->send(RthsUpdateAppliedMsg{std::uint64_t(e.step), e.ok, e.message,
                                                   e.parameters.names(), e.applied});
            if (e.proposal != 0)
                monitor->send(RthsProposalMsg{std::uint32_t(e.proposal), std::uint64_t(e.step),
                                              std::uint8_t(e.decision), std::nan(""), e.message,
                                              e.parameters.names(), e.applied});
        }
        // Into the monitor's send queue only while it is below half its cap: a monitor that reads
        // slower than the loop makes (the fast pace) leaves the samples in the ring, where the
        // fast pace's gate waits for them and the real-time pace drops and counts them.
        TelemetrySample t;
        while ((!monitor || monitor->queuedBytes() < ControllerSession::kMaxQueuedBytes / 2) && feed->pop(t)) {
            if (!monitor) {
                ++undelivered;
                continue;
            }
            const bool holding = gate->holdRequested();
            monitor->send(TelemetryMsg{std::uint64_t(t.tick), t.time, t.desired, t.command,
                                       t.measured, t.force, std::uint64_t(t.misses),
                                       t.worstLateness,
                                       std::uint64_t(feed->dropped() + undelivered), holding,
                                       holding ? holdAsked : std::string()});
            ++sent;
        }
    }

    void endRun() {
        loop.join();
        if (posted) // asked for while the last tick ran: the run ended first
            for (const rths::TwinUpdate& u : posted->takeAll()) {
                UpdateEvent e{int(result.time.size()), 0.0, "damper twin", ParameterLayout(u.names), u.values, false,
                              u.source + ": the run ended before its next tick; nothing applied"};
                e.decision = UpdateDecision::Refused;
                outbox.onUpdate(0, e);
            }
        held = loopError.empty() && !result.hold.empty() && !stopping && runner && runner->held();
        if (identification) {
            if (!identification->failure().empty())
                log(identification->failure());
            if (!held) {
                proposals.reset();
                identification.reset(); // its worker stops
            }
        }
        if (held)
            holdRecord();
        else
            closeRecord();
        drain();
        running = false;
        if (!priorityRefusal.empty())
            log("real-time priority not taken (" + priorityRefusal + "); the loop ran at normal priority");
        RthsEndMsg end;
        end.ticks = result.time.size();
        for (int i = 0; i < 9; ++i)
            end.j[i] = result.criteria.j[std::size_t(i)];
        end.misses = std::uint64_t(pacer ? pacer->misses() : 0);
        end.worstLateness = pacer ? pacer->worstLateness() : 0.0;
        end.telemetrySent = std::uint64_t(sent);
        end.telemetryDropped = std::uint64_t(feed->dropped() + undelivered);
        end.peakForce = result.peakForce;
        end.peakStroke = result.peakStroke;
        end.peakVelocity = result.peakVelocity;
        end.trackingIndicator = result.trackingIndicator;
        end.frequencyAmplitude = result.frequency.amplitude;
        end.frequencyDelay = result.frequency.delay;
        end.frequency = result.frequency.frequency;
        end.hold = loopError.empty() ? result.hold : "the loop failed: " + loopError;
        std::ostringstream o;
        o.precision(4);
        o << "RTHS run ended after " << end.ticks << " ticks; J1 " << end.j[0] << " ms, J2 "
          << end.j[1] << " %, J4 " << end.j[3] << " %; " << end.misses
          << " deadline misses (worst " << end.worstLateness * 1e6 << " us); telemetry "
          << sent << " sent, " << end.telemetryDropped << " dropped"
          << (end.hold.empty() ? std::string() : "; " + end.hold);
        log(o.str());
        if (monitor)
            monitor->send(end);
    }
};

RthsServer::RthsServer(const RthsServerOptions& options, RthsJob job)
    : d(std::make_unique<Impl>(options, std::move(job))) {}

RthsServer::~RthsServer() {
    if (d->loop.joinable()) {
        d->stopping = true;
        if (d->gate)
            d->gate->requestHold("controller shutting down");
        d->loop.join();
    }
    d->discardHeld();
}

bool RthsServer::listen(std::string& error) {
    if (!listenOn(d->acceptor, d->opt.bind, d->opt.port, error, "--bind: "))
        return false;
    // Before anyone is told the port: no TLS files to reload here, so SIGHUP is ignored (its
    // default action would end the process).
    std::signal(SIGHUP, SIG_IGN);
    d->accept();
    return true;
}

std::uint16_t RthsServer::port() const {
    boost::system::error_code ec;
    const auto ep = d->acceptor.local_endpoint(ec);
    return ec ? 0 : ep.port();
}

std::string RthsServer::describe() const {
    return d->describe();
}

void RthsServer::run() {
    d->signals.add(SIGINT);
    d->signals.add(SIGTERM);
    d->signals.async_wait([this](const boost::system::error_code& ec, int) {
        if (!ec)
            stop();
    });
    d->io.run();
}

void RthsServer::stop() {
    asio::post(d->io, [this] {
        d->stopping = true;
        if (d->running)
            d->gate->requestHold("controller shutting down");
        boost::system::error_code ec;
        d->acceptor.close(ec);
        d->poll.cancel();
        d->signals.cancel();
        for (const auto& s : std::set<std::shared_ptr<ControllerSession>>(d->sessions)) {
            s->send(ByeMsg{"controller shutting down"});
            s->close();
        }
        d->io.stop();
    });
}

} // namespace hsmu::comms
