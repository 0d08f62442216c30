#pragma once
// TestController: owns the test worker and its thread; the widgets' only handle on a test.
//
// load() builds a HybridTest from a TestConfig on the GUI thread (errors are thrown there, as
// ConfigError / GroundMotionError / std::exception), over the built-in virtual specimens or a
// TCP link to hsmu-controller, then moves a TestWorker holding it to a fresh QThread.
// Commands (prepare, start, pause, single step, ...) and the operator's updating decisions are
// queued to the worker and run between steps; with a record directory each test also writes
// its HDF5 record (its run folder created at the first driven step); nothing here ever waits for the worker except
// load() / the destructor, which stop the old test first.
// Rows reach the GUI through a RecordBuffer: on the worker's coalesced recordsAvailable() a
// single-shot ~30 Hz timer starts; when it fires, every pending row is moved out and emitted
// once in recordsArrived(). On every worker state change the buffer is drained first, so the
// rows of a finished test are all delivered before stateChanged(Finished).
//
// Thread rules: GUI thread only. Signals are emitted on the GUI thread.

#include "comms/LinkAddress.h"
#include "core/config/TestConfig.h"
#include "core/config/TestFactory.h"
#include "core/experimental/SiteStatus.h"
#include "core/output/RunLayout.h"
#include "core/experiment/StepRecord.h"
#include "gui/app/AlarmMetaType.h"
#include "gui/app/OperatorEvent.h"
#include "gui/app/PreflightReport.h"
#include "gui/app/RunState.h"
#include "gui/app/UpdatingSnapshot.h"

#include <QObject>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

class QThread;

namespace hsmu::gui {

class RecordBuffer;
class TestWorker;

class TestController : public QObject {
    Q_OBJECT
public:
    static constexpr int kDrainIntervalMs = 33; ///< ~30 Hz

    explicit TestController(QObject* parent = nullptr);
    ~TestController() override;

    /// Replace the current test (stopped and destroyed first) by one built from cfg, its
    /// specimens driven in-process (builtin) or through hsmu-controller at `controller`.
    /// Throws on a configuration or record error; the previous test is gone either way.
    void load(const TestConfig& cfg, const comms::LinkAddress& controller = {});

    bool hasTest() const { return m_worker != nullptr; }
    const RunLayout& layout() const { return m_layout; }
    const TestConfig& config() const { return m_config; }
    const comms::LinkAddress& controllerAddress() const { return m_address; }
    /// Per-site health of the loaded test (sites); nullptr before a load.
    std::shared_ptr<const SiteMonitor> siteMonitor() const { return m_siteMonitor; }
    RunState state() const { return m_state; }
    /// The token the next load()ed tests send in their hello to hsmu-controller ("" = none);
    /// held in memory only.
    void setLinkToken(const QString& token) { m_token = token; }
    /// Where the next load()ed tests record (DIR/<date-time>-<name>/record.h5); "" = none.
    void setRecordDirectory(const QString& dir) { m_recordDir = dir; }
    /// The record of the current test ("" if none).
    const QString& recordPath() const { return m_recordPath; }
    /// Rows emitted through recordsAvailable() since load().
    qint64 recordsDelivered() const { return m_delivered; }
    /// Rows the worker has committed since load(), read without the GUI's event loop.
    qint64 recordsCommitted() const;
    /// The last pre-flight report of this test (after prepare()).
    const std::optional<PreflightReport>& preflight() const { return m_preflight; }
    /// The last updating snapshot (enabled = false without updating).
    const UpdatingSnapshot& updating() const { return m_updating; }

public slots:
    /// Prepare the test (connect the link, check stability) and report preflightReady().
    void prepare();
    /// Record that the operator confirmed the pre-flight check (call before start()).
    void confirmPreflight();
    /// The operator's choice at the pre-flight for specimens loaded by an earlier test:
    /// continue on them, or fresh ones (their controllers reset them; the pre-flight is
    /// reported again). TestWorker::chooseLoadedSpecimens().
    void chooseLoadedSpecimens(bool fresh);
    /// Record that the test starts without the pre-flight dialog (hsmu --start).
    void skipPreflight();
    /// Arm and start stepping (prepares first if needed, without a pre-flight report).
    void start();
    void pause();
    void singleStep();
    void resume();
    void stop();
    /// Out of band while a test runs, is paused or holds: HybridTest::emergencyHold() is
    /// called here, on the GUI thread, so that the hold reaches every site at once even while
    /// the worker is blocked in a step; then the worker is told (queued) to show the hold.
    void emergencyHold(const QString& reason = QString());
    /// Test seconds per wall second (1 = real time); <= 0 as fast as possible.
    void setSpeed(double factor);
    /// Pace by wall time per step [s] instead (speed = dt / seconds); <= 0: use setSpeed's.
    void setWallTimePerStep(double seconds);
    /// The pace in force: test seconds per wall second (<= 0: as fast as possible).
    double effectiveSpeed() const;

    void setParameterBounds(const QString& name, double lower, double upper);
    void setParameterLocked(const QString& name, bool locked);
    void approveUpdate(int proposalId);
    void rejectUpdate(int proposalId);
    void approveOffsets(int id); ///< the twins' offsets (TestWorker::approveOffsets)
    void rejectOffsets(int id);
    void setReporterPolicy(hsmu::ReporterPolicy policy, int everyN);
    void setFitThreshold(double threshold);
    /// An operator note, recorded by the worker with its current step and time (queued; the
    /// GUI thread never touches the record). Refused (commandRefused) without a record.
    void addNote(const QString& text);

signals:
    /// Rows since the last emission, oldest first (GUI thread, at most ~30 Hz).
    void recordsArrived(const std::vector<hsmu::StepRecord>& rows);
    void stateChanged(hsmu::gui::RunState state, const QString& message);
    void progress(int step, int totalSteps, double testTime, double stepsPerSecond);
    void alarmRaised(const hsmu::Alarm& alarm);
    void preflightReady(const hsmu::gui::PreflightReport& report);
    void updatingChanged(const hsmu::gui::UpdatingSnapshot& snapshot);
    /// An operator command that could not be carried out: `reason` in English, and
    /// TestWorker::refusalText(source, args) in the current language.
    void commandRefused(const QString& reason, const QString& source, const QStringList& args);
    /// The current test's HDF5 record was opened (at the first driven step).
    void recordingStarted(const QString& path);
    /// An operator action as the worker stamped and recorded it.
    void operatorEvent(const hsmu::gui::OperatorEvent& event);
    /// A new test was loaded (layout() and config() describe it).
    void testLoaded();

private:
    void drain();
    void teardown();
    void onWorkerState(RunState state, const QString& message);
    /// Queue f(worker) to the worker thread (nothing without a test).
    template <class F> void onWorker(F&& f);

    QThread* m_thread = nullptr;
    TestWorker* m_worker = nullptr;
    HybridTest* m_test = nullptr; ///< owned by m_worker; only emergencyHold() is called on it
    std::shared_ptr<RecordBuffer> m_buffer;
    QTimer m_drainTimer;
    RunLayout m_layout;
    TestConfig m_config;
    comms::LinkAddress m_address;
    std::shared_ptr<const SiteMonitor> m_siteMonitor;
    RunState m_state = RunState::Idle;
    double m_speed = 1.0;
    double m_wallPerStep = 0.0; ///< [s]; > 0 overrides m_speed
    qint64 m_delivered = 0;
    std::optional<PreflightReport> m_preflight;
    UpdatingSnapshot m_updating;
    QString m_recordDir;
    QString m_token;
    QString m_recordPath;
};

} // namespace hsmu::gui
