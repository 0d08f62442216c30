#include "gui/app/TestController.h"

#include "core/config/TestFactory.h"
#include "core/test/HybridTest.h"
#include "gui/app/RecordBuffer.h"
#include "gui/app/TestWorker.h"

#include <QCoreApplication>
#include <QThread>

namespace hsmu::gui {

TestController::TestController(QObject* parent) : QObject(parent) {
    qRegisterMetaType<hsmu::gui::RunState>();
    qRegisterMetaType<hsmu::Alarm>();
    m_drainTimer.setSingleShot(true);
    m_drainTimer.setInterval(kDrainIntervalMs);
    connect(&m_drainTimer, &QTimer::timeout, this, &TestController::drain);
}

TestController::~TestController() {
    teardown();
}

void TestController::teardown() {
    m_drainTimer.stop();
    if (!m_worker)
        return;
    // Hold the specimen safely before the thread goes away; runs between two steps.
    QMetaObject::invokeMethod(m_worker, &TestWorker::stop, Qt::BlockingQueuedConnection);
    m_thread->quit();
    m_thread->wait();
    delete m_worker; // its thread has finished: nothing runs on it any more
    delete m_thread;
    // Signals the old worker queued to us must not reach the next test's state.
    QCoreApplication::removePostedEvents(this, QEvent::MetaCall);
    m_worker = nullptr;
    m_thread = nullptr;
    m_buffer.reset();
    m_state = RunState::Idle;
}

void TestController::load(const TestConfig& cfg) {
    teardown();
    m_delivered = 0;
    std::unique_ptr<HybridTest> test = buildHybridTest(cfg, m_controls); // may throw
    m_config = cfg;
    m_layout = RunLayout::of(*test); // with the updater's parameters, for the plots
    m_buffer = std::make_shared<RecordBuffer>();
    m_worker = new TestWorker(std::move(test), m_buffer);
    m_thread = new QThread;
    m_thread->setObjectName(QStringLiteral("hsmu test worker"));
    m_worker->moveToThread(m_thread);
    connect(
        m_worker, &TestWorker::recordsAvailable, this,
        [this] {
            if (!m_drainTimer.isActive())
                m_drainTimer.start();
        },
        Qt::QueuedConnection);
    connect(m_worker, &TestWorker::stateChanged, this, &TestController::onWorkerState,
            Qt::QueuedConnection);
    connect(m_worker, &TestWorker::progress, this, &TestController::progress, Qt::QueuedConnection);
    connect(m_worker, &TestWorker::alarmRaised, this, &TestController::alarmRaised,
            Qt::QueuedConnection);
    m_thread->start();
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, s = m_speed] { w->setSpeed(s); }, Qt::QueuedConnection);
    m_state = RunState::Ready;
    emit testLoaded();
    emit stateChanged(m_state, QString());
}

void TestController::invokeOnWorker(void (TestWorker::*slot)()) {
    if (m_worker)
        QMetaObject::invokeMethod(m_worker, slot, Qt::QueuedConnection);
}

void TestController::start() {
    invokeOnWorker(&TestWorker::start);
}
void TestController::pause() {
    invokeOnWorker(&TestWorker::pause);
}
void TestController::resume() {
    invokeOnWorker(&TestWorker::resume);
}
void TestController::stop() {
    invokeOnWorker(&TestWorker::stop);
}

void TestController::emergencyHold(const QString& reason) {
    if (m_worker)
        QMetaObject::invokeMethod(
            m_worker, [w = m_worker, reason] { w->emergencyHold(reason); }, Qt::QueuedConnection);
}

void TestController::setSpeed(double factor) {
    m_speed = factor;
    if (m_worker)
        QMetaObject::invokeMethod(
            m_worker, [w = m_worker, factor] { w->setSpeed(factor); }, Qt::QueuedConnection);
}

void TestController::drain() {
    if (!m_buffer)
        return;
    std::vector<StepRecord> rows = m_buffer->takeAll();
    if (rows.empty())
        return;
    m_delivered += qint64(rows.size());
    emit recordsArrived(rows);
}

void TestController::onWorkerState(RunState state, const QString& message) {
    drain(); // every row committed before this state change reaches the GUI first
    m_state = state;
    emit stateChanged(state, message);
}

} // namespace hsmu::gui
