#include "gui/app/TestWorker.h"

#include "core/output/RunSummary.h"
#include "core/test/HybridTest.h"
#include "gui/app/RecordBuffer.h"

#include <QTimer>

#include <cmath>

namespace hsmu::gui {

namespace {
constexpr int kChunkMs = 15;     // longest stretch of stepping before queued calls are served
constexpr int kProgressMs = 100; // progress signal period while running
} // namespace

TestWorker::TestWorker(std::unique_ptr<HybridTest> test, std::shared_ptr<RecordBuffer> buffer)
    : m_test(std::move(test)), m_buffer(std::move(buffer)) {
    m_test->addObserver(this);
}

TestWorker::~TestWorker() {
    m_test->removeObserver(this);
}

void TestWorker::onStep(const StepRecord& record) {
    if (m_buffer->push(record))
        emit recordsAvailable();
}

void TestWorker::start() {
    if (m_state != RunState::Ready)
        return;
    if (!m_test->prepare()) {
        setState(RunState::Failed, QString::fromStdString(m_test->lastError()));
        return;
    }
    publishAlarms();
    restartPacing();
    setState(RunState::Running);
    schedule(0);
}

void TestWorker::pause() {
    if (m_state == RunState::Running)
        setState(RunState::Paused);
}

void TestWorker::resume() {
    if (m_state == RunState::Holding)
        m_test->resume();
    else if (m_state != RunState::Paused)
        return;
    publishAlarms();
    restartPacing();
    setState(RunState::Running);
    schedule(0);
}

void TestWorker::stop() {
    if (m_state == RunState::Running || m_state == RunState::Paused) {
        m_test->hold(tr("stopped by the operator").toStdString());
        publishAlarms();
    }
    if (m_state != RunState::Finished && m_state != RunState::Failed &&
        m_state != RunState::Stopped)
        setState(RunState::Stopped);
}

void TestWorker::emergencyHold(const QString& reason) {
    if (m_state != RunState::Running && m_state != RunState::Paused)
        return;
    const QString why = reason.isEmpty() ? tr("emergency hold by the operator") : reason;
    m_test->hold(why.toStdString());
    publishAlarms();
    setState(RunState::Holding, why);
}

void TestWorker::setSpeed(double factor) {
    m_speed = std::isfinite(factor) ? factor : 0.0;
    restartPacing();
}

void TestWorker::restartPacing() {
    m_pace.start();
    m_paceStartTime = m_test->time();
    m_progressTimer.start();
    m_progressStep = m_test->currentStep();
}

void TestWorker::schedule(int delayMs) {
    if (m_scheduled)
        return;
    m_scheduled = true;
    QTimer::singleShot(delayMs, this, &TestWorker::runChunk);
}

void TestWorker::runChunk() {
    m_scheduled = false;
    if (m_state != RunState::Running)
        return;
    QElapsedTimer chunk;
    chunk.start();
    while (chunk.elapsed() < kChunkMs) {
        if (m_speed > 0.0) {
            const double allowed = m_paceStartTime + m_pace.nsecsElapsed() * 1e-9 * m_speed;
            const double ahead = m_test->time() + m_test->dt() - allowed;
            if (ahead > 0.0) {
                emitProgress(false);
                schedule(std::max(1, int(std::ceil(ahead / m_speed * 1000.0))));
                return;
            }
        }
        const HybridTest::StepResult r = m_test->step();
        publishAlarms();
        if (r == HybridTest::StepResult::Advanced)
            continue;
        emitProgress(true);
        if (r == HybridTest::StepResult::Finished)
            setState(RunState::Finished);
        else if (r == HybridTest::StepResult::Held)
            setState(RunState::Holding,
                     QString::fromStdString(holdReason(*m_test).value_or(std::string())));
        else
            setState(RunState::Failed, QString::fromStdString(m_test->lastError()));
        return;
    }
    emitProgress(false);
    schedule(0);
}

void TestWorker::setState(RunState state, const QString& message) {
    m_state = state;
    emitProgress(true);
    emit stateChanged(state, message);
}

void TestWorker::publishAlarms() {
    const auto& alarms = m_test->alarms();
    for (; m_alarmsSeen < alarms.size(); ++m_alarmsSeen)
        emit alarmRaised(alarms[m_alarmsSeen]);
}

void TestWorker::emitProgress(bool force) {
    if (!force && m_progressTimer.isValid() && m_progressTimer.elapsed() < kProgressMs)
        return;
    const double seconds = m_progressTimer.isValid() ? m_progressTimer.nsecsElapsed() * 1e-9 : 0.0;
    if (seconds > 0.05) { // a rate over a shorter span is noise
        m_lastRate = (m_test->currentStep() - m_progressStep) / seconds;
        m_progressTimer.start();
        m_progressStep = m_test->currentStep();
    }
    const double rate = m_state == RunState::Running ? m_lastRate : 0.0;
    emit progress(m_test->currentStep(), m_test->totalSteps(), m_test->time(), rate);
}

} // namespace hsmu::gui
