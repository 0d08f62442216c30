#pragma once
// TestWorker: runs a HybridTest on the thread it lives on (a QThread owned by TestController).
//
// It steps in short chunks (<= ~15 ms of work) and re-queues itself, so every queued call
// (pause, resume, stop, emergency hold, speed) is honoured *between steps*. Pacing: with a
// speed factor s > 0 the test time follows s x wall time (1 = real time); s <= 0 runs as fast
// as possible. Every committed StepRecord goes into the RecordBuffer; recordsAvailable() is
// emitted only when the buffer turns non-empty (one coalesced signal per GUI drain).
//
// Thread rules: construct on the GUI thread, then moveToThread(); afterwards call slots only
// through queued connections / QMetaObject::invokeMethod. Signals are emitted on the worker
// thread. Destroy after the thread has finished.

#include "core/test/StepRecord.h"
#include "gui/app/AlarmMetaType.h"
#include "gui/app/RunState.h"

#include <QElapsedTimer>
#include <QObject>

#include <memory>

namespace hsmu {
class HybridTest;
}

namespace hsmu::gui {

class RecordBuffer;

class TestWorker : public QObject, public StepObserver {
    Q_OBJECT
public:
    TestWorker(std::unique_ptr<HybridTest> test, std::shared_ptr<RecordBuffer> buffer);
    ~TestWorker() override;

    void onStep(const StepRecord& record) override;

public slots:
    /// prepare() the test (emits step 0) and start stepping; Failed if it cannot start.
    void start();
    void pause();
    /// Leave a pause or a hold (a held step is retried).
    void resume();
    /// End the test in a safe hold.
    void stop();
    /// Hold at once, between steps (works while running or paused).
    void emergencyHold(const QString& reason);
    /// Test seconds per wall second; <= 0: as fast as possible.
    void setSpeed(double factor);

signals:
    void recordsAvailable();
    void stateChanged(hsmu::gui::RunState state, const QString& message);
    /// At most ~10 times a second while running, and at every state change.
    void progress(int step, int totalSteps, double testTime, double stepsPerSecond);
    void alarmRaised(const hsmu::Alarm& alarm);

private:
    void runChunk();
    void schedule(int delayMs);
    void setState(RunState state, const QString& message = {});
    void publishAlarms();
    void emitProgress(bool force);
    void restartPacing();

    std::unique_ptr<HybridTest> m_test;
    std::shared_ptr<RecordBuffer> m_buffer;
    RunState m_state = RunState::Ready;
    double m_speed = 1.0;
    bool m_scheduled = false;
    QElapsedTimer m_pace;
    double m_paceStartTime = 0.0;
    QElapsedTimer m_progressTimer;
    int m_progressStep = 0;
    double m_lastRate = 0.0;
    std::size_t m_alarmsSeen = 0;
};

} // namespace hsmu::gui
