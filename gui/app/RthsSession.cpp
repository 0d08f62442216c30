#include "gui/app/RthsSession.h"

#include "core/rths/RthsReport.h"

#include <chrono>
#include <cmath>

namespace hsmu::gui {

RthsSession::RthsSession(QObject* parent) : QObject(parent)
{
    m_poll.setInterval(kPollMs);
    connect(&m_poll, &QTimer::timeout, this, &RthsSession::poll);
}

RthsSession::~RthsSession()
{
    if (m_gate)
        m_gate->requestHold("console closed");
    if (m_link && m_active) {
        m_link->hold("console closed", false); // the controller's loop holds; nobody waits for its end
        m_link->abandon();
    }
    join();
}

void RthsSession::join()
{
    if (m_thread.joinable())
        m_thread.join();
}

bool RthsSession::start(const RthsConfig& cfg, const GroundMotion& ag, Pace pace, double duration,
                        const QString& recordFolder, QString* error)
{
    if (m_active) {
        if (error)
            *error = tr("an RTHS run is already going");
        return false;
    }
    join();
    rths::RthsSettings s = cfg.settings;
    rths::fitToNominalLoop(s);
    const rths::Partition part = cfg.partition();
    const rths::Preflight pre = rths::preflight(part, s);
    m_preflight = QString::fromStdString(pre.message);
    if (pre.refused) {
        if (error)
            *error = tr("refused in pre-flight: %1").arg(m_preflight);
        return false;
    }
    // About 1024 samples per second: the live window resolves the delay to a fraction of 1 ms.
    const long decimation = std::max(1L, long(std::lround(s.rate / 1024.0)));
    m_samplePeriod = double(decimation) / s.rate;
    m_pacer = pace == Pace::RealTime
                  ? std::make_unique<comms::RealtimePacer>(m_clock, 1.0 / s.rate, cfg.holdAfterMisses)
                  : nullptr;
    m_recording.reset();
    m_recordPath.clear();
    m_recordError.clear();
    m_ag = ag;
    if (!recordFolder.isEmpty()) {
        try {
            const RecordStart record{cfg.raw.dump(), cfg.name, {}, 1.0 / s.rate};
            m_recording = std::make_unique<rths::RthsRecording>(recordFolder.toStdString(), record, m_ag,
                                                                int(part.reference.m.rows()));
        } catch (const std::exception& e) {
            if (error)
                *error = tr("the record cannot be created in %1: %2").arg(recordFolder, QString::fromStdString(e.what()));
            return false;
        }
        m_recordPath = QString::fromStdString(m_recording->path());
    }
    m_gate = std::make_unique<comms::MonitorGate>(m_pacer.get(), 1.0 / s.rate);
    m_feed = std::make_unique<comms::TelemetryFeed>(*m_gate, decimation);
    m_observers = {};
    m_observers.add(m_feed.get());
    m_observers.add(m_recording ? m_recording->feed() : nullptr);
    m_observers.add(&m_outbox);
    m_outbox.take();
    m_posted = s.damper.enabled ? std::make_unique<rths::PostedTwinUpdates>(pace == Pace::Fast) : nullptr;
    m_backpressure = std::make_unique<comms::FastPaceGate>(*m_gate, *m_feed);
    rths::TickGate* gate = pace == Pace::Fast ? static_cast<rths::TickGate*>(m_backpressure.get()) : m_gate.get();
    m_run = {};
    m_link.reset();
    m_failure.clear();
    m_holdAfterMisses = cfg.holdAfterMisses;
    m_runner = std::make_unique<rths::RthsRunner>(part, m_ag, s, gate, duration, &m_observers, m_posted.get());
    launchLocal();
    return true;
}

void RthsSession::launchLocal()
{
    m_done = false;
    m_resumable = false;
    m_thread = std::thread([this] {
        bool failed = false;
        try {
            m_runner->run();
            m_run = m_runner->result();
        } catch (const std::exception& e) {
            m_run.hold = std::string("the loop failed: ") + e.what();
            failed = true;
        }
        m_resumable = !failed && m_runner->held();
        // The record is written here, off the GUI thread: a hold is its last tick's alarm; the
        // file stays open while the run may resume.
        if (m_recording) {
            const bool deadline = m_pacer && m_pacer->policyHolds();
            const bool ok = m_resumable ? m_recording->held(m_run, deadline) : m_recording->finish(m_run, deadline);
            if (!ok)
                m_recordError = m_recording->error();
        }
        m_ticks = long(m_run.time.size());
        m_done = true;
    });
    m_active = true;
    m_poll.start();
}

bool RthsSession::resume(QString* why)
{
    const auto refuse = [why](const QString& text) {
        if (why)
            *why = text;
        return false;
    };
    if (!resumable())
        return refuse(tr("no held RTHS run to resume"));
    join();
    if (m_link) {
        launchRemote(true);
        return true;
    }
    if (const std::string no = m_runner->resume(); !no.empty())
        return refuse(QString::fromStdString(no));
    launchLocal();
    return true;
}

bool RthsSession::startRemote(const RthsConfig& cfg, const QString& host, quint16 port, const QString& token,
                              double duration, QString* error)
{
    if (m_active) {
        if (error)
            *error = tr("an RTHS run is already going");
        return false;
    }
    join();
    const double rate = cfg.settings.rate;
    const long decimation = std::max(1L, long(std::lround(rate / 1024.0)));
    m_samplePeriod = double(decimation) / rate;
    m_preflight = tr("the controller's (%1:%2)").arg(host).arg(port);
    m_backpressure.reset();
    m_feed.reset();
    m_gate.reset();
    m_pacer.reset();
    m_recording.reset();
    m_recordPath.clear();
    m_recordError.clear();
    m_runner.reset();
    m_posted.reset();
    m_link = std::make_unique<RthsLink>();
    m_remoteSamples.clear();
    m_description.clear();
    m_described = false;
    m_failure.clear();
    m_run = {};
    m_ticks = 0;
    m_host = host.toStdString();
    m_port = port;
    m_token = token.toStdString();
    m_decimation = decimation;
    m_duration = duration;
    launchRemote(false);
    return true;
}

void RthsSession::launchRemote(bool resume)
{
    m_done = false;
    m_resumable = false;
    m_failure.clear();
    if (resume)
        m_link = std::make_unique<RthsLink>(); // the held run's link said goodbye at its end
    m_thread = std::thread([this, resume] {
        std::string description, why;
        if (!m_link->open(m_host, m_port, m_token, unsigned(m_decimation), m_duration, description, why, resume)) {
            m_failure = why;
            m_resumable = resume; // a refused resume leaves the controller's run held
            m_done = true;
            return;
        }
        {
            std::lock_guard lock(m_remoteMutex);
            m_description = description;
        }
        for (;;) {
            const RthsLink::Event ev = m_link->next();
            if (ev.kind == RthsLink::Event::Kind::Telemetry) {
                const comms::TelemetryMsg& f = ev.telemetry;
                std::lock_guard lock(m_remoteMutex);
                m_remoteSamples.push_back({long(f.tick), f.time, f.desired, f.command, f.measured, f.force,
                                           long(f.misses), f.worstLateness});
                continue;
            }
            if (ev.kind == RthsLink::Event::Kind::End) {
                m_run.hold = ev.end.hold;
                for (int i = 0; i < 9; ++i)
                    m_run.criteria.j[i] = ev.end.j[i];
                m_ticks = long(ev.end.ticks);
                m_resumable = !ev.end.hold.empty();
                m_link->bye(m_resumable ? "run held" : "run ended");
            } else {
                m_failure = ev.lost ? tr("the link to the controller was lost: %1 (the controller holds the loop per its --monitor-loss policy)")
                                          .arg(QString::fromStdString(ev.error)).toStdString()
                                    : ev.error;
            }
            break;
        }
        m_done = true;
    });
    m_active = true;
    m_poll.start();
}

void RthsSession::hold()
{
    if (m_gate)
        m_gate->requestHold("console hold: operator");
    if (m_link)
        m_link->hold("operator at the console", false);
}

void RthsSession::emergencyHold()
{
    if (m_gate)
        m_gate->requestHold("emergency hold (console)");
    if (m_link)
        m_link->hold("operator at the console", true);
}

bool RthsSession::sendTwinUpdate(const rths::TwinUpdate& update, QString* why)
{
    if (!m_active) {
        if (why)
            *why = tr("no RTHS run is going");
        return false;
    }
    if (m_link) {
        if (m_link->update(update.names, update.values))
            return true;
        if (why)
            *why = tr("the link to the controller is closed");
        return false;
    }
    if (!m_posted) {
        if (why)
            *why = tr("this RTHS run has no damper twin");
        return false;
    }
    m_posted->post(update);
    return true;
}

bool RthsSession::decideProposal(int id, bool approve, QString* why)
{
    if (m_active && m_link && m_link->decide(std::uint32_t(id), approve))
        return true;
    if (why)
        *why = tr("no controller's RTHS run is going");
    return false;
}

void RthsSession::poll()
{
    const bool done = m_done.load(); // before draining: every sample of a finished run is taken
    m_batch.clear();
    if (m_feed) {
        comms::TelemetrySample sample;
        while (m_feed->pop(sample)) {
            m_batch.push_back(sample);
        }
    } else {
        std::string description;
        {
            std::lock_guard lock(m_remoteMutex);
            m_batch.swap(m_remoteSamples);
            if (!m_described && !m_description.empty())
                description = m_description;
        }
        if (!description.empty()) {
            m_described = true;
            emit controllerDescribed(QString::fromStdString(description));
        }
    }
    if (!m_batch.empty())
        emit samples(m_batch);
    std::vector<UpdateEvent> decisions = m_outbox.take();
    if (m_link) {
        for (const comms::RthsUpdateAppliedMsg& u : m_link->takeUpdates())
            decisions.push_back(RthsLink::eventOf(u));
        for (UpdateEvent& e : m_link->takeProposals())
            decisions.push_back(std::move(e));
    }
    if (!decisions.empty())
        emit twinUpdates(decisions);
    if (!done)
        return;
    m_poll.stop();
    join();
    m_active = false;
    if (!m_failure.empty())
        emit failed(QString::fromStdString(m_failure));
    else
        emit finished(QString::fromStdString(m_run.hold), m_run.criteria, m_ticks);
}

} // namespace hsmu::gui
