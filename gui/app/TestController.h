#pragma once
// TestController: owns the test worker and its thread; the widgets' only handle on a test.
//
// load() builds a HybridTest from a TestConfig on the GUI thread (errors are thrown there, as
// ConfigError / GroundMotionError / std::exception), then moves a TestWorker holding it to a
// fresh QThread. Commands (start, pause, ...) are queued to the worker and run between steps.
// Rows reach the GUI through a RecordBuffer: on the worker's coalesced recordsAvailable() a
// single-shot ~30 Hz timer starts; when it fires, every pending row is moved out and emitted
// once in recordsArrived(). On every worker state change the buffer is drained first, so the
// rows of a finished test are all delivered before stateChanged(Finished).
//
// Thread rules: GUI thread only. Signals are emitted on the GUI thread.

#include "core/config/TestConfig.h"
#include "core/config/TestFactory.h"
#include "core/output/RunLayout.h"
#include "core/test/StepRecord.h"
#include "gui/app/AlarmMetaType.h"
#include "gui/app/RunState.h"

#include <QObject>
#include <QTimer>

#include <memory>
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

    /// Replace the current test (stopped and destroyed first) by one built from cfg.
    /// Throws on a configuration or record error; the previous test is gone either way.
    void load(const TestConfig& cfg);
    /// Controls of the experimental elements for the next load() (empty: built-in virtual
    /// specimens), e.g. comms::makeControlFactory(tcp address).
    void setControlFactory(ControlFactory factory) { m_controls = std::move(factory); }

    bool hasTest() const { return m_worker != nullptr; }
    const RunLayout& layout() const { return m_layout; }
    const TestConfig& config() const { return m_config; }
    RunState state() const { return m_state; }
    /// Rows emitted through recordsArrived() since load().
    qint64 recordsDelivered() const { return m_delivered; }

public slots:
    void start();
    void pause();
    void resume();
    void stop();
    void emergencyHold(const QString& reason = QString());
    /// Test seconds per wall second (1 = real time); <= 0 as fast as possible.
    void setSpeed(double factor);

signals:
    /// Rows since the last emission, oldest first (GUI thread, at most ~30 Hz).
    void recordsArrived(const std::vector<hsmu::StepRecord>& rows);
    void stateChanged(hsmu::gui::RunState state, const QString& message);
    void progress(int step, int totalSteps, double testTime, double stepsPerSecond);
    void alarmRaised(const hsmu::Alarm& alarm);
    /// A new test was loaded (layout() and config() describe it).
    void testLoaded();

private:
    void drain();
    void teardown();
    void onWorkerState(RunState state, const QString& message);
    void invokeOnWorker(void (TestWorker::*slot)());

    QThread* m_thread = nullptr;
    TestWorker* m_worker = nullptr;
    std::shared_ptr<RecordBuffer> m_buffer;
    QTimer m_drainTimer;
    RunLayout m_layout;
    TestConfig m_config;
    ControlFactory m_controls;
    RunState m_state = RunState::Idle;
    double m_speed = 1.0;
    qint64 m_delivered = 0;
};

} // namespace hsmu::gui
