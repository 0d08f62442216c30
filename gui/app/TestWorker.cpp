#include "gui/app/TestWorker.h"

#include "core/output/RunLayout.h"
#include "core/output/RunSummary.h"
#include "core/test/HybridTest.h"
#include "core/updating/ModelUpdater.h"
#include "gui/app/RecordBuffer.h"

#include <QTimer>

#include <cmath>

namespace hsmu::gui {

namespace {
constexpr int kChunkMs = 15;     // longest stretch of stepping before queued calls are served
constexpr int kProgressMs = 100; // progress / snapshot period while running
} // namespace

TestWorker::TestWorker(std::unique_ptr<HybridTest> test, std::shared_ptr<RecordBuffer> buffer,
                       bool allowUnstable, RecordStart record, QString recordPath)
    : m_test(std::move(test)), m_buffer(std::move(buffer)), m_allowUnstable(allowUnstable),
      m_recordStart(std::move(record)), m_recordPath(std::move(recordPath)) {
    m_test->addObserver(this);
}

TestWorker::~TestWorker() {
    m_test->removeObserver(this);
    if (m_record) {
        m_test->removeObserver(m_record.get());
        m_record->finish();
    }
}

bool TestWorker::openRecord() {
    if (m_recordPath.isEmpty())
        return true;
    try {
        m_record = std::make_unique<RecordWriter>(m_recordPath.toStdString(),
                                                  RunLayout::of(*m_test), m_recordStart);
    } catch (const std::exception& e) {
        setState(RunState::Failed, tr("the record cannot be written: %1").arg(e.what()));
        return false;
    }
    m_record->trackAlarms(&m_test->alarms());
    m_test->addObserver(m_record.get());
    emit recordingStarted(m_recordPath);
    return true;
}

void TestWorker::onStep(const StepRecord& record) {
    if (m_buffer->push(record))
        emit recordsAvailable();
}

bool TestWorker::ensurePrepared() {
    if (m_prepared)
        return true;
    if (!m_record && !openRecord()) // before prepare(): step 0 is recorded too
        return false;
    if (!m_test->prepare()) {
        setState(RunState::Failed, QString::fromStdString(m_test->lastError()));
        return false;
    }
    m_prepared = true;
    publishAlarms();
    publishUpdating();
    return true;
}

void TestWorker::prepare() {
    if (m_state != RunState::Ready || !ensurePrepared())
        return;
    emit preflightReady(preflightOf(*m_test, m_allowUnstable));
}

void TestWorker::start() {
    if (m_state != RunState::Ready || !ensurePrepared())
        return;
    restartPacing();
    setState(RunState::Running);
    schedule(0);
}

void TestWorker::pause() {
    if (m_state == RunState::Running)
        setState(RunState::Paused);
}

void TestWorker::singleStep() {
    if (m_state == RunState::Ready) {
        if (!ensurePrepared())
            return;
        setState(RunState::Paused);
    }
    if (m_state != RunState::Paused)
        return;
    if (stepOnce()) {
        emitProgress(true);
        publishUpdating();
    }
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
    const bool prepared = m_state == RunState::Ready && m_prepared;
    if (m_state != RunState::Running && m_state != RunState::Paused && !prepared)
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

void TestWorker::addNote(const QString& text) {
    if (text.trimmed().isEmpty())
        return;
    if (!m_record || !m_record->ok()) {
        emit commandRefused(tr("the note was not kept: this test is not recorded"));
        return;
    }
    m_record->addNote(m_test->time(), m_test->currentStep(), text.toStdString());
}

void TestWorker::setParameterBounds(const QString& name, double lower, double upper) {
    ModelUpdater* u = m_test->updater();
    if (!u)
        return emit commandRefused(tr("this test has no model updating"));
    if (!(lower <= upper) || !std::isfinite(lower) || !std::isfinite(upper))
        return emit commandRefused(
            tr("%1: the lower bound must be a number not above the upper bound").arg(name));
    if (!u->identifier().setBounds(name.toStdString(), {lower, upper}))
        return emit commandRefused(tr("%1: bounds [%2, %3] refused (they would not keep the "
                                      "law admissible)")
                                       .arg(name)
                                       .arg(lower)
                                       .arg(upper));
    publishUpdating();
}

void TestWorker::setParameterLocked(const QString& name, bool locked) {
    ModelUpdater* u = m_test->updater();
    if (!u)
        return emit commandRefused(tr("this test has no model updating"));
    if (!u->identifier().setLocked(name.toStdString(), locked))
        return emit commandRefused(
            tr("%1: the %2 cannot lock this parameter")
                .arg(name, QString::fromStdString(u->identifier().methodName())));
    publishUpdating();
}

void TestWorker::approveUpdate(int proposalId) {
    if (!m_test->approveUpdate(proposalId))
        emit commandRefused(tr("update #%1 was not applied (no longer pending, or refused by "
                               "the law; see the alarms)")
                                .arg(proposalId));
    publishAlarms();
    publishUpdating();
}

void TestWorker::rejectUpdate(int proposalId) {
    if (!m_test->rejectUpdate(proposalId))
        emit commandRefused(tr("update #%1 is no longer pending").arg(proposalId));
    publishUpdating();
}

void TestWorker::setReporterPolicy(ReporterPolicy policy, int everyN) {
    ModelUpdater* u = m_test->updater();
    if (!u)
        return emit commandRefused(tr("this test has no model updating"));
    u->reporter().setPolicy(policy, everyN);
    publishUpdating();
}

void TestWorker::setFitThreshold(double threshold) {
    ModelUpdater* u = m_test->updater();
    if (!u)
        return emit commandRefused(tr("this test has no model updating"));
    if (!(threshold > 0.0) || !std::isfinite(threshold))
        return emit commandRefused(tr("the fit-error threshold must be a positive number"));
    InspectorSettings s = u->inspector().settings();
    s.threshold = threshold;
    u->inspector().setSettings(s);
    publishUpdating();
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

bool TestWorker::stepOnce() {
    const HybridTest::StepResult r = m_test->step();
    publishAlarms();
    if (r == HybridTest::StepResult::Advanced)
        return true;
    if (r == HybridTest::StepResult::Finished)
        setState(RunState::Finished);
    else if (r == HybridTest::StepResult::Held)
        setState(RunState::Holding,
                 QString::fromStdString(holdReason(*m_test).value_or(std::string())));
    else
        setState(RunState::Failed, QString::fromStdString(m_test->lastError()));
    return false;
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
        if (!stepOnce())
            return;
    }
    emitProgress(false);
    schedule(0);
}

void TestWorker::setState(RunState state, const QString& message) {
    m_state = state;
    if (m_record) {
        if (state == RunState::Finished || state == RunState::Stopped || state == RunState::Failed)
            m_record->finish();
        else
            m_record->flush();
    }
    emitProgress(true);
    publishUpdating();
    emit stateChanged(state, message);
}

void TestWorker::publishAlarms() {
    const auto& alarms = m_test->alarms();
    for (; m_alarmsSeen < alarms.size(); ++m_alarmsSeen)
        emit alarmRaised(alarms[m_alarmsSeen]);
}

void TestWorker::publishUpdating() {
    if (m_test->updater())
        emit updatingChanged(snapshotOf(*m_test));
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
    if (!force && m_state == RunState::Running)
        publishUpdating();
}

} // namespace hsmu::gui
