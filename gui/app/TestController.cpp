#include "gui/app/TestController.h"

#include "comms/link/ControlFactory.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "gui/app/RecordBuffer.h"
#include "gui/app/TestWorker.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QRegularExpression>
#include <QThread>

namespace hsmu::gui {

TestController::TestController(QObject* parent) : QObject(parent) {
    qRegisterMetaType<hsmu::gui::RunState>();
    qRegisterMetaType<hsmu::Alarm>();
    qRegisterMetaType<hsmu::gui::PreflightReport>();
    qRegisterMetaType<hsmu::gui::UpdatingSnapshot>();
    qRegisterMetaType<hsmu::gui::OperatorEvent>();
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
    m_test = nullptr;
    m_thread = nullptr;
    m_buffer.reset();
    m_siteMonitor.reset();
    m_state = RunState::Idle;
    m_preflight.reset();
    m_updating = UpdatingSnapshot{};
}

void TestController::load(const TestConfig& cfg, const comms::LinkAddress& controller) {
    teardown();
    m_delivered = 0;
    comms::TcpControlOptions link; // LinkTimeouts (core/config/LinkConfig.h), as hsmu run
    link.token = m_token.toStdString();
    std::unique_ptr<HybridTest> test =
        buildHybridTest(cfg, comms::makeControlFactory(controller, link, cfg)); // may throw
    m_siteMonitor = test->siteMonitor();
    m_config = cfg;
    m_address = controller;
    m_layout = RunLayout::of(*test); // with the updater's parameters, for the plots
    m_buffer = std::make_shared<RecordBuffer>();
    m_recordPath.clear();
    if (!m_recordDir.isEmpty()) {
        QString name = QString::fromStdString(cfg.name);
        name.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_.-]+")), QStringLiteral("-"));
        const QString run =
            QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss-zzz-")) + name;
        // The worker creates the folder at the first driven step (no empty run folders).
        m_recordPath = QDir(m_recordDir).filePath(run + QStringLiteral("/record.h5"));
    }
    // The JSON is the file as read; what the console's setup changed is in the notes.
    const std::string notes =
        "as run from the console: dt = " + std::to_string(cfg.analysis.dt) +
        " s, duration = " + std::to_string(cfg.analysis.duration) + " s, ground motion = " +
        (cfg.groundMotion.file.empty() ? cfg.groundMotion.builtin : cfg.groundMotion.file) + " x " +
        std::to_string(cfg.groundMotion.scale) + ", integrator = " + cfg.analysis.integrator +
        ", controller = " + controller.toString() +
        ", updating = " + (cfg.updating.enabled ? reporterPolicyName(cfg.updating.policy) : "off");
    RecordStart start{cfg.raw.dump(), cfg.name, notes, cfg.analysis.dt};
    start.dofRecording = cfg.record; // the configuration's "record" block
    start.siteSecurity = comms::siteSecurity(controller, cfg);
    m_test = test.get();
    m_worker =
        new TestWorker(std::move(test), m_buffer, cfg.analysis.allowUnstable, start, m_recordPath);
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
    connect(
        m_worker, &TestWorker::preflightReady, this,
        [this](const PreflightReport& r) {
            m_preflight = r;
            emit preflightReady(r);
        },
        Qt::QueuedConnection);
    connect(
        m_worker, &TestWorker::updatingChanged, this,
        [this](const UpdatingSnapshot& s) {
            m_updating = s;
            emit updatingChanged(s);
        },
        Qt::QueuedConnection);
    connect(m_worker, &TestWorker::commandRefused, this, &TestController::commandRefused,
            Qt::QueuedConnection);
    connect(m_worker, &TestWorker::recordingStarted, this, &TestController::recordingStarted,
            Qt::QueuedConnection);
    connect(m_worker, &TestWorker::operatorEvent, this, &TestController::operatorEvent,
            Qt::QueuedConnection);
    m_thread->start();
    onWorker([s = effectiveSpeed()](TestWorker* w) {
        w->setSpeed(s);
        w->publishUpdating(); // the parameters and the policy are shown before a start
    });
    m_state = RunState::Ready;
    emit testLoaded();
    emit stateChanged(m_state, QString());
}

qint64 TestController::recordsCommitted() const {
    return m_buffer ? qint64(m_buffer->pushedCount()) : 0;
}

template <class F> void TestController::onWorker(F&& f) {
    if (m_worker)
        QMetaObject::invokeMethod(
            m_worker, [w = m_worker, f = std::forward<F>(f)] { f(w); }, Qt::QueuedConnection);
}

void TestController::prepare() {
    onWorker([](TestWorker* w) { w->prepare(); });
}
void TestController::confirmPreflight() {
    onWorker([](TestWorker* w) { w->confirmPreflight(); });
}
void TestController::chooseLoadedSpecimens(bool fresh) {
    onWorker([fresh](TestWorker* w) { w->chooseLoadedSpecimens(fresh); });
}
void TestController::skipPreflight() {
    onWorker([](TestWorker* w) { w->skipPreflight(); });
}
void TestController::start() {
    onWorker([](TestWorker* w) { w->start(); });
}
void TestController::pause() {
    onWorker([](TestWorker* w) { w->pause(); });
}
void TestController::singleStep() {
    onWorker([](TestWorker* w) { w->singleStep(); });
}
void TestController::resume() {
    onWorker([](TestWorker* w) { w->resume(); });
}
void TestController::stop() {
    onWorker([](TestWorker* w) { w->stop(); });
}

void TestController::emergencyHold(const QString& reason) {
    // Not before arming (Ready): nothing is driven, nothing may be held at the lab.
    if (m_test && (m_state == RunState::Running || m_state == RunState::Paused ||
                   m_state == RunState::Holding))
        m_test->emergencyHold(reason.isEmpty() ? std::string("operator at the console")
                                               : reason.toStdString());
    onWorker([reason](TestWorker* w) { w->emergencyHold(reason); });
}

void TestController::setSpeed(double factor) {
    m_speed = factor;
    onWorker([s = effectiveSpeed()](TestWorker* w) { w->setSpeed(s); });
}

void TestController::setWallTimePerStep(double seconds) {
    m_wallPerStep = seconds;
    onWorker([s = effectiveSpeed()](TestWorker* w) { w->setSpeed(s); });
}

double TestController::effectiveSpeed() const {
    if (m_wallPerStep > 0.0 && m_config.analysis.dt > 0.0)
        return m_config.analysis.dt / m_wallPerStep;
    return m_speed;
}

void TestController::setParameterBounds(const QString& name, double lower, double upper) {
    onWorker([=](TestWorker* w) { w->setParameterBounds(name, lower, upper); });
}
void TestController::setParameterLocked(const QString& name, bool locked) {
    onWorker([=](TestWorker* w) { w->setParameterLocked(name, locked); });
}
void TestController::approveUpdate(int proposalId) {
    onWorker([=](TestWorker* w) { w->approveUpdate(proposalId); });
}
void TestController::rejectUpdate(int proposalId) {
    onWorker([=](TestWorker* w) { w->rejectUpdate(proposalId); });
}
void TestController::approveOffsets(int id) {
    onWorker([=](TestWorker* w) { w->approveOffsets(id); });
}
void TestController::rejectOffsets(int id) {
    onWorker([=](TestWorker* w) { w->rejectOffsets(id); });
}
void TestController::setReporterPolicy(ReporterPolicy policy, int everyN) {
    onWorker([=](TestWorker* w) { w->setReporterPolicy(policy, everyN); });
}
void TestController::setFitThreshold(double threshold) {
    onWorker([=](TestWorker* w) { w->setFitThreshold(threshold); });
}

void TestController::addNote(const QString& text) {
    onWorker([text](TestWorker* w) { w->addNote(text); });
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
