#pragma once
// RthsSession: an RTHS run on the console's built-in virtual lab (docs/rths.md, "The console's
// RTHS view"): core's runRths on a worker thread, at the simulated (fast) or the wall clock's
// pace, through the controller's own pieces (comms/rths/RthsMonitor: MonitorGate for the holds
// and the real-time pacer, TelemetryFeed for one sample every decimation ticks), so a local run
// and a monitored `hsmu-controller --rths` run reach the view as the same samples.
// The GUI thread drains the samples every kPollMs and emits them in order; at the fast pace the
// loop waits while half the feed's ring is undrained (nothing dropped, the simulated time does
// not care). hold() / emergencyHold() hold the loop before its next tick; resume() lets a held
// run go on from the tick where it held (core's RthsRunner locally; on a controller, a new
// connection that sends resume: docs/rths.md, "Hold and resume"). The destructor holds a
// running loop and joins it.
// A local run with a record folder writes every tick to the first free record.h5 /
// record-N.h5 there (core's RthsRecording: the same RthsRecordFeed and RecordWriter as
// `hsmu rths`, batched on the writer's thread), a hold as the last tick's alarm (the file stays
// open while the run may resume, the resume a note); the loop's thread closes it.
// The damper twin (docs/rths.md, "The console's RTHS view"): sendTwinUpdate() posts new values
// of its parameters, applied before the loop's next tick (a local run's PostedTwinUpdates), or
// sends them over the link (rths-update, as `hsmu rths --controller --update`); every decision,
// applied or refused, comes back as twinUpdates() with its tick.
// Thread rules: GUI thread, except the loop's own thread inside.

#include "comms/rths/RthsMonitor.h"
#include "core/config/RthsConfig.h"
#include "core/record/RthsRecord.h"
#include "core/rths/RthsRunner.h"
#include "gui/cli/RthsLink.h"

#include <QObject>
#include <QTimer>

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace hsmu::gui {

class RthsSession : public QObject {
    Q_OBJECT
public:
    enum class Pace { Fast, RealTime };
    static constexpr int kPollMs = 30;

    explicit RthsSession(QObject* parent = nullptr);
    ~RthsSession() override;

    /// Prepare cfg's settings (fitToNominalLoop), run pre-flight and start the loop over ag
    /// [m/s^2]; duration > 0 stops after that many seconds; recordFolder not empty: every tick
    /// recorded there (recordPath()). False with *error (pre-flight's refusal, a run already
    /// going, a record that cannot be created) and nothing started.
    bool start(const RthsConfig& cfg, const GroundMotion& ag, Pace pace, double duration,
               const QString& recordFolder, QString* error);
    /// Monitor the loop `hsmu-controller --rths` runs at host:port instead (RthsLink, the
    /// protocol of `hsmu rths --controller`; token: the hello's): the controller runs its own copy
    /// of the configuration at its own pace; cfg gives the rate, so the samples' spacing. The
    /// connection is made on the session's thread: a failure comes as failed().
    bool startRemote(const RthsConfig& cfg, const QString& host, quint16 port, const QString& token,
                     double duration, QString* error);
    /// From start() until finished() was emitted (GUI thread's view: the loop may have ended).
    bool running() const { return m_active; }
    /// The samples' spacing: decimation / rate [s].
    double samplePeriod() const { return m_samplePeriod; }
    /// Pre-flight's sentence of the last start().
    const QString& preflight() const { return m_preflight; }
    /// The last local run's record file ("" when not recorded).
    const QString& recordPath() const { return m_recordPath; }
    /// After finished(): why the record could not be completed ("" when it was, or none).
    QString recordError() const { return m_done ? QString::fromStdString(m_recordError) : QString(); }
    void hold();
    void emergencyHold();
    /// The last run held (and was not given up by a new start): it may be resumed.
    bool resumable() const { return !m_active && m_resumable; }
    /// Go on with the held run from the tick where it held (its samples, then finished() again
    /// with the whole run's criteria). False with *why (not held; a limit still breached, with
    /// the channel) and the run stays held. Monitoring a controller, the refusal comes from the
    /// controller and arrives as failed().
    bool resume(QString* why);
    /// New values of the damper twin's parameters (by name, in the twin's scales), applied
    /// before the next tick; what became of them comes as twinUpdates(). False with *why when
    /// no run is going or it has no twin (nothing sent). The loop (local) or the controller
    /// checks them (checkTwinUpdate: the box, the law) and refuses with the reason.
    bool sendTwinUpdate(const rths::TwinUpdate& update, QString* why);
    /// Approve or reject the controller's proposal `id` (a controller's run with
    /// "identification": {"approve": true}: docs/rths.md, "Proposals approved by the console");
    /// its fate comes as twinUpdates() (an event with the proposal's id). False with *why when
    /// no controller's run is going.
    bool decideProposal(int id, bool approve, QString* why);

signals:
    /// Every sample since the last batch, oldest first (GUI thread).
    void samples(const std::vector<hsmu::comms::TelemetrySample>& batch);
    /// The run ended: hold is why it stopped early ("" when it ran out), with its J1..J9.
    void finished(const QString& hold, const hsmu::rths::BenchmarkCriteria& criteria, long ticks);
    /// A monitored run could not be followed (refused, link lost): why.
    void failed(const QString& why);
    /// The monitored controller's hello-ack text (its loop, and where it records or that it
    /// does not), once connected.
    void controllerDescribed(const QString& description);
    /// Decisions on the twin's updates since the last batch (applied or refused, each with its
    /// tick as step; a controller's immediate refusal has step 0), oldest first (GUI thread);
    /// then the controller's proposals' events (UpdateEvent::proposal their id, decision
    /// Proposed, Superseded, Rejected, Refused or Applied).
    void twinUpdates(const std::vector<hsmu::UpdateEvent>& events);

private:
    void poll();
    void join();
    void launchLocal(); ///< the loop's thread: m_runner->run() until the end or a hold
    void launchRemote(bool resume); ///< the link's thread: open (rths-start or resume), follow

    QTimer m_poll;
    comms::MonotonicClock m_clock;
    std::unique_ptr<comms::RealtimePacer> m_pacer;
    std::unique_ptr<comms::MonitorGate> m_gate;
    std::unique_ptr<comms::TelemetryFeed> m_feed;
    std::unique_ptr<comms::FastPaceGate> m_backpressure;
    std::unique_ptr<rths::RthsRunner> m_runner; // the local run; kept while held
    bool m_resumable = false;
    int m_holdAfterMisses = 0;
    std::string m_host, m_token; // the monitored controller (startRemote)
    quint16 m_port = 0;
    long m_decimation = 1;
    double m_duration = 0.0;
    std::thread m_thread;
    std::atomic<bool> m_done{false};
    bool m_active = false;
    rths::RthsRun m_run; // written by the loop's thread until m_done
    GroundMotion m_ag;   // the run's record (the record feed reads it)
    std::unique_ptr<rths::RthsRecording> m_recording; // closed by the loop's thread
    rths::TickObservers m_observers;                  // the feed, the record, the outbox
    comms::UpdateOutbox m_outbox;                     // a local run's twin update decisions
    std::unique_ptr<rths::PostedTwinUpdates> m_posted; // a local run's operator updates
    QString m_recordPath;
    std::string m_recordError;                        // written by the thread until m_done
    double m_samplePeriod = 0.0;
    QString m_preflight;
    std::vector<comms::TelemetrySample> m_batch;
    // Monitoring a controller's loop (startRemote): the link, and the frames of its thread.
    std::unique_ptr<RthsLink> m_link;
    std::mutex m_remoteMutex;
    std::vector<comms::TelemetrySample> m_remoteSamples; // guarded by m_remoteMutex
    std::string m_description;                           // guarded by m_remoteMutex
    bool m_described = false;
    std::string m_failure;                               // written by the thread until m_done
    long m_ticks = 0;                                    // written by the thread until m_done
};

} // namespace hsmu::gui
