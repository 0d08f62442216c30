#pragma once
// TestWorker: runs a HybridTest on the thread it lives on (a QThread owned by TestController).
//
// It steps in short chunks (<= ~15 ms of work) and re-queues itself, so every queued call
// (pause, resume, single step, stop, emergency hold, speed and the operator's updating
// decisions: bounds, locks, approvals, policy, threshold) is honoured *between steps*.
// Pacing: with a speed factor s > 0 the test time follows s x wall time (1 = real time);
// s <= 0 runs as fast as possible. Every committed StepRecord goes into the RecordBuffer;
// recordsAvailable() is emitted only when the buffer turns non-empty (one coalesced signal per
// GUI drain). The stepping, the pace, the HDF5 record and the hold / reconnect policy are the
// TestSession's (core/session/TestSession.h, shared with `hsmu run` and `hsmu compare`): the
// worker calls TestSession::advance() for one chunk and schedules itself again after the wait
// it returns (pace, reconnect backoff). With a record path, every step (from step 0), alarm
// and operator note goes into the record, flushed at every state change and at least once a
// second while paused or held (TestSession::tick() on a timer). The record (and its run
// folder) is created only when the test is armed and its first step is driven, so a test that
// is loaded, prepared or cancelled at the pre-flight leaves no folder behind; notes and events
// from before are written then with their own step and time. After a lost link the session
// resumes (reconnects) up to kReconnectAttempts times with a doubling backoff (0.5 s to 8 s);
// meanwhile the state shown is Holding ("link fault ...: reconnecting in ..."), Running again
// with "link restored ..." once a step is taken (the record says the reconnect resumed it,
// not the operator).
// Arming: start() and singleStep() arm the test (the console calls them only after the
// pre-flight was confirmed, confirmPreflight()); an emergency hold before arming holds
// nothing and leaves the test Ready and unarmed (the pre-flight must be confirmed again), so
// Resume can never drive an unconfirmed test.
// Every operator action (pre-flight confirmation, start, pause, single step, resume, hold,
// stop, approve / reject an update or the offsets, bounds, lock, threshold, policy) becomes an OperatorEvent: emitted
// to the console and written to the record (language-neutral, as a /notes row). An approved
// update is also written to /updating/events with the next committed step. The updating
// panels get an UpdatingSnapshot at most ~10 times a second while running, and at once after every
// operator decision and state change.
//
// Thread rules: construct on the GUI thread, then moveToThread(); afterwards call slots only
// through queued connections / QMetaObject::invokeMethod. Signals are emitted on the worker
// thread. Destroy after the thread has finished.

#include "core/record/RecordWriter.h"
#include "core/session/TestSession.h"
#include "core/experiment/StepRecord.h"
#include "core/updating/Reporter.h"
#include "gui/app/AlarmMetaType.h"
#include "gui/app/OperatorEvent.h"
#include "gui/app/PreflightReport.h"
#include "gui/app/RunState.h"
#include "gui/app/UpdatingSnapshot.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <map>
#include <memory>
#include <string>

namespace hsmu::gui {

class RecordBuffer;

class TestWorker : public QObject, public StepObserver {
    Q_OBJECT
public:
    /// Automatic resumes after a control fault (TestSession's ReconnectPolicy).
    static constexpr int kReconnectAttempts = 5;
    /// The hold reason of an operator's Stop (the record's language-neutral text).
    static constexpr const char* kStopReason = "stopped by the operator";
    /// A refusal (commandRefused's `source` and `args`) in the current language (GUI thread).
    static QString refusalText(const QString& source, const QStringList& args);

    /// allowUnstable: the configuration forces an unstable explicit run (for the pre-flight).
    /// record: where prepare() opens the HDF5 record (docs/recording.md); empty: none.
    TestWorker(std::unique_ptr<HybridTest> test, std::shared_ptr<RecordBuffer> buffer,
               bool allowUnstable = false, RecordStart record = {}, QString recordPath = {});
    ~TestWorker() override;

    void onStep(const StepRecord& record) override;

public slots:
    /// prepare() the test (connects a link, emits step 0) and report preflightReady(); Failed
    /// if it cannot start. Idempotent: a second call repeats the report.
    void prepare();
    /// The operator confirmed the pre-flight check (recorded as an event).
    void confirmPreflight();
    /// The test starts without the pre-flight dialog (hsmu --start: the command line is the
    /// operator's confirmation); recorded as an event.
    void skipPreflight();
    /// The operator's choice for the specimens an earlier test loaded (pre-flight; docs/
    /// console.md): continue on them, or ask their controllers for fresh ones
    /// (ExperimentalControl::freshSpecimen()). An event per loaded specimen (kLoadedSpecimen);
    /// a refusal is also reported (commandRefused). After `fresh` the pre-flight is reported
    /// again (preflightReady), the refusals named in it.
    void chooseLoadedSpecimens(bool fresh);
    /// Prepare if needed, arm and start stepping; Failed if it cannot start.
    void start();
    void pause();
    /// Exactly one step from Ready or Paused, then Paused (or Finished / Holding / Failed).
    void singleStep();
    /// Leave a pause or a hold (a held step is retried).
    void resume();
    /// End the test in a safe hold.
    void stop();
    /// Hold at once, between steps (running or paused); before arming: nothing is armed,
    /// the test stays Ready (an event says so).
    void emergencyHold(const QString& reason);
    /// Test seconds per wall second; <= 0: as fast as possible.
    void setSpeed(double factor);

    // Operator decisions on online model updating (refused with commandRefused() if invalid).
    void setParameterBounds(const QString& name, double lower, double upper);
    void setParameterLocked(const QString& name, bool locked);
    void approveUpdate(int proposalId);
    void rejectUpdate(int proposalId);
    /// The twins' offsets (ModelUpdater::approveOffsets), only ever by the operator.
    void approveOffsets(int id);
    void rejectOffsets(int id);
    void setReporterPolicy(hsmu::ReporterPolicy policy, int everyN);
    void setFitThreshold(double threshold);
    /// Emit the updating snapshot now (e.g. right after loading, before any start).
    void publishUpdating();
    /// An operator note at the current step and test time, into the record
    /// (RecordWriter::addNote); refused with commandRefused() when nothing is recorded.
    void addNote(const QString& text);

signals:
    void recordsAvailable();
    void stateChanged(hsmu::gui::RunState state, const QString& message);
    /// At most ~10 times a second while running, and at every state change.
    void progress(int step, int totalSteps, double testTime, double stepsPerSecond);
    void alarmRaised(const hsmu::Alarm& alarm);
    void preflightReady(const hsmu::gui::PreflightReport& report);
    void updatingChanged(const hsmu::gui::UpdatingSnapshot& snapshot);
    /// An operator command that could not be carried out, and why.
    /// `reason` in English (language-neutral, also for logs); `source` the untranslated
    /// template (TestWorker's tr() context) and `args` its arguments, so the console shows
    /// it in the current language and again in a new one (refusalText).
    void commandRefused(const QString& reason, const QString& source, const QStringList& args);
    /// The HDF5 record was opened at `path` (before the first driven step).
    void recordingStarted(const QString& path);
    /// An operator action, stamped with step, test time and wall time.
    void operatorEvent(const hsmu::gui::OperatorEvent& event);

private:
    bool ensurePrepared();
    /// preflightOf() with the controllers' refusals of a fresh specimen.
    PreflightReport preflightReport();
    /// Open the record before the first driven step (idempotent); false: Failed, no step.
    bool openRecord();
    HybridTest& test() { return m_session->test(); }
    /// Refuse an operator command: `source` is a QT_TR_NOOP template with %1.. for `args`.
    void refuse(const char* source, const QStringList& args = {});
    /// Stamp, emit and record an operator event.
    void logEvent(const char* action, std::string oldValue = {}, std::string newValue = {});
    void runChunk();
    /// One step; false (state changed to Finished / Holding / Failed) if it did not advance.
    bool stepOnce();
    void schedule(int delayMs);
    void setState(RunState state, const QString& message = {});
    void publishAlarms();
    void emitProgress(bool force);
    void restartPacing();

    std::unique_ptr<TestSession> m_session;
    std::shared_ptr<RecordBuffer> m_buffer;
    bool m_allowUnstable = false;
    std::map<std::string, std::string> m_freshRefused; ///< element -> the controller's refusal
    QString m_recordPath;
    QTimer* m_flushTimer = nullptr; ///< TestSession::tick() while paused or held
    bool m_armed = false;
    RunState m_state = RunState::Ready;
    /// The session's reconnect policy is at work (m_state stays Running; shown as Holding).
    bool m_reconnecting = false;
    bool m_scheduled = false;
    QElapsedTimer m_progressTimer;
    int m_progressStep = 0;
    double m_lastRate = 0.0;
    std::size_t m_alarmsSeen = 0;
};

} // namespace hsmu::gui
