#include "gui/app/TestWorker.h"

#include "core/output/RunLayout.h"
#include "core/output/RunSummary.h"
#include "core/session/TestSession.h"
#include "core/experiment/HybridTest.h"
#include "core/experimental/ExperimentalElement.h"
#include "core/output/ElementUnits.h"
#include "core/structure/Structure.h"
#include "core/updating/ModelUpdater.h"
#include "gui/app/RecordBuffer.h"

#include <QTimer>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hsmu::gui {

namespace {
constexpr int kChunkMs = 15;     // longest stretch of stepping before queued calls are served
constexpr int kProgressMs = 100; // progress / snapshot period while running

std::string number(double v) {
    std::ostringstream o;
    o.precision(10);
    o << v;
    return o.str();
}

std::string valuesText(const ParameterLayout& names, const std::vector<double>& values) {
    std::string out;
    for (std::size_t k = 0; k < names.size() && k < values.size(); ++k)
        out += (out.empty() ? "" : ", ") + names.name(k) + "=" + number(values[k]);
    return out;
}

/// "#<id> <targets>" and "u0=<v> <unit> (sd <s>) F0=<v> <unit> (sd <s>)" for the record.
std::pair<std::string, std::string> offsetsText(const ModelUpdater& u, const OffsetProposal& p,
                                                const ElementUnits& units) {
    std::string targets;
    for (const ReporterTarget& t : u.reporter().targets())
        targets += (targets.empty() ? "" : ",") + t.element;
    return {"#" + std::to_string(p.id) + " " + targets,
            "u0=" + number(p.deformationOffset) + " " + units.deformation + " (sd " +
                number(p.deformationSd) + ") F0=" + number(p.forceOffset) + " " + units.force +
                " (sd " + number(p.forceSd) + ")"};
}

SessionOptions consoleSession(RecordStart record, const QString& recordPath) {
    SessionOptions o;
    o.speed = 1.0; // real time until the operator changes it
    o.reconnect.attempts = TestWorker::kReconnectAttempts;
    o.recordPath = recordPath.toStdString();
    o.recordStart = std::move(record);
    return o;
}
} // namespace

TestWorker::TestWorker(std::unique_ptr<HybridTest> test, std::shared_ptr<RecordBuffer> buffer,
                       bool allowUnstable, RecordStart record, QString recordPath)
    : m_session(std::make_unique<TestSession>(std::move(test),
                                              consoleSession(std::move(record), recordPath))),
      m_buffer(std::move(buffer)), m_allowUnstable(allowUnstable),
      m_recordPath(std::move(recordPath)), m_flushTimer(new QTimer(this)) {
    m_session->addObserver(this);
    m_session->onReconnect = [this](const TestSession::Reconnect& r) {
        publishAlarms();
        // Held on a link fault, the policy reconnecting: the console shows "holding" (not
        // "running" at 0 steps/s) until a step is taken again (runChunk).
        m_reconnecting = true;
        emit stateChanged(RunState::Holding,
                          tr("link fault (%1): reconnecting in %2 s (attempt %3 of %4)")
                              .arg(QString::fromStdString(r.reason))
                              .arg(r.delay, 0, 'f', 1)
                              .arg(r.attempt)
                              .arg(r.of));
    };
    m_flushTimer->setInterval(500); // notes and alarms reach the file while paused or held
    connect(m_flushTimer, &QTimer::timeout, this, [this] { m_session->tick(); });
}

TestWorker::~TestWorker() {
    m_session->removeObserver(this);
    m_session->finish();
}

bool TestWorker::openRecord() {
    if (m_recordPath.isEmpty() || m_session->record())
        return true;
    if (!m_session->openRecord()) {
        m_recordPath.clear();
        setState(RunState::Failed, tr("the record cannot be written: %1")
                                       .arg(QString::fromStdString(m_session->lastError())));
        return false;
    }
    emit recordingStarted(m_recordPath);
    return true;
}

void TestWorker::logEvent(const char* action, std::string oldValue, std::string newValue) {
    const OperatorEvent e = OperatorEvent::now(test().currentStep(), test().time(), action,
                                               std::move(oldValue), std::move(newValue));
    m_session->addNote(e.time, e.step, e.recordText());
    emit operatorEvent(e);
}

void TestWorker::onStep(const StepRecord& record) {
    if (m_buffer->push(record))
        emit recordsAvailable();
}

bool TestWorker::ensurePrepared() {
    if (m_session->prepared())
        return true;
    if (!m_session->prepare()) {
        setState(RunState::Failed, QString::fromStdString(m_session->lastError()));
        return false;
    }
    m_flushTimer->start();
    publishAlarms();
    publishUpdating();
    return true;
}

void TestWorker::prepare() {
    if (m_state != RunState::Ready || !ensurePrepared())
        return;
    emit preflightReady(preflightReport());
}

PreflightReport TestWorker::preflightReport() {
    PreflightReport r = preflightOf(test(), m_allowUnstable);
    for (SpecimenPreflight& s : r.specimens)
        if (const auto it = m_freshRefused.find(s.element); it != m_freshRefused.end() && s.loaded())
            s.freshRefused = it->second;
    return r;
}

void TestWorker::chooseLoadedSpecimens(bool fresh) {
    if (m_state != RunState::Ready || m_armed || !m_session->prepared())
        return;
    for (const auto& e : test().structure().elements()) {
        auto* x = dynamic_cast<ExperimentalElement*>(e.get());
        const auto h = x ? x->control().priorLoading() : std::nullopt;
        if (!h || h->committedSteps == 0)
            continue;
        const std::string loaded =
            x->name() + ": " + std::to_string(h->committedSteps) +
            " committed steps, last deformation " + QString::number(h->lastDeformation, 'g', 6).toStdString() +
            " " + elementUnits(x->typeName()).deformation;
        if (!fresh) {
            logEvent(OperatorEvent::kLoadedSpecimen, loaded, "continue");
            continue;
        }
        const ControlResult r = x->control().freshSpecimen();
        logEvent(OperatorEvent::kLoadedSpecimen, loaded, r.ok ? "fresh" : "fresh-refused");
        if (r.ok) {
            m_freshRefused.erase(x->name());
        } else {
            m_freshRefused[x->name()] = r.reason;
            refuse(QT_TR_NOOP("the controller of %1 refused a fresh specimen: %2; replace the "
                              "specimen at the controller, or continue on the loaded specimen"),
                   {QString::fromStdString(x->name()), QString::fromStdString(r.reason)});
        }
    }
    if (fresh)
        emit preflightReady(preflightReport());
}

void TestWorker::confirmPreflight() {
    if (m_state == RunState::Ready)
        logEvent(OperatorEvent::kPreflightConfirmed, "unconfirmed", "confirmed");
}

void TestWorker::skipPreflight() {
    if (m_state == RunState::Ready)
        logEvent(OperatorEvent::kPreflightSkipped, "unconfirmed", "command line");
}

void TestWorker::start() {
    if (m_state != RunState::Ready || !ensurePrepared() || !openRecord())
        return;
    m_armed = true;
    logEvent(OperatorEvent::kStart, "ready", "running");
    restartPacing();
    setState(RunState::Running);
    schedule(0);
}

void TestWorker::pause() {
    if (m_state != RunState::Running)
        return;
    logEvent(OperatorEvent::kPause, "running", "paused");
    setState(RunState::Paused);
}

void TestWorker::singleStep() {
    if (m_state == RunState::Ready) {
        if (!ensurePrepared() || !openRecord())
            return;
        m_armed = true;
        setState(RunState::Paused);
    }
    if (m_state != RunState::Paused)
        return;
    logEvent(OperatorEvent::kSingleStep, std::to_string(test().currentStep()),
             std::to_string(test().currentStep() + 1));
    if (stepOnce()) {
        emitProgress(true);
        publishUpdating();
    }
}

void TestWorker::resume() {
    if (!m_armed)
        return; // never drives a test the operator has not confirmed
    if (m_state == RunState::Holding || test().state() == HybridTest::State::Holding)
        m_session->resume();
    else if (m_state != RunState::Paused)
        return;
    logEvent(OperatorEvent::kResume,
             m_state == RunState::Holding || m_reconnecting ? "holding" : "paused", "running");
    publishAlarms();
    restartPacing();
    setState(RunState::Running);
    schedule(0);
}

void TestWorker::stop() {
    if (m_state == RunState::Running || m_state == RunState::Paused ||
        m_state == RunState::Holding)
        logEvent(OperatorEvent::kStop, "armed", "stopped, data kept");
    if (m_state == RunState::Running || m_state == RunState::Paused) {
        m_session->hold(kStopReason); // the record's text: language-neutral
        publishAlarms();
    }
    if (m_state != RunState::Finished && m_state != RunState::Failed &&
        m_state != RunState::Stopped)
        setState(RunState::Stopped);
}

void TestWorker::emergencyHold(const QString& reason) {
    if (m_state == RunState::Ready) {
        // Nothing was driven and nothing is armed: the test stays Ready; a start must go
        // through the pre-flight again.
        logEvent(OperatorEvent::kHold, "ready", "not-armed");
        return;
    }
    if (m_state != RunState::Running && m_state != RunState::Paused)
        return;
    // The record's text is language-neutral; the console shows the translation.
    const std::string why =
        reason.isEmpty() ? std::string("emergency hold by the operator") : reason.toStdString();
    logEvent(OperatorEvent::kHold, m_state == RunState::Running ? "running" : "paused", "held");
    m_session->hold(why);
    publishAlarms();
    setState(RunState::Holding,
             reason.isEmpty() ? tr("emergency hold by the operator") : reason);
}

void TestWorker::setSpeed(double factor) {
    m_session->setSpeed(factor);
    restartPacing();
}

void TestWorker::refuse(const char* source, const QStringList& args) {
    QString english = QString::fromUtf8(source);
    for (const QString& a : args)
        english = english.arg(a);
    emit commandRefused(english, QString::fromUtf8(source), args);
}

QString TestWorker::refusalText(const QString& source, const QStringList& args) {
    QString text = tr(source.toUtf8().constData());
    for (const QString& a : args)
        text = text.arg(a);
    return text;
}

void TestWorker::addNote(const QString& text) {
    if (text.trimmed().isEmpty())
        return;
    if (!m_session->recording())
        return refuse(QT_TR_NOOP("the note was not kept: this test is not recorded"));
    if (!m_session->addNote(text.toStdString()))
        return refuse(QT_TR_NOOP("the note was not kept: %1"),
                      {QString::fromStdString(m_session->lastError())});
    // In the event list (the record keeps the note itself, not an operator-event row).
    emit operatorEvent(OperatorEvent::now(test().currentStep(), test().time(),
                                          OperatorEvent::kNote, {}, text.toStdString()));
}

void TestWorker::setParameterBounds(const QString& name, double lower, double upper) {
    ModelUpdater* u = test().updater();
    if (!u)
        return refuse(QT_TR_NOOP("this test has no model updating"));
    if (!(lower <= upper) || !std::isfinite(lower) || !std::isfinite(upper))
        return refuse(QT_TR_NOOP("%1: the lower bound must be a number not above the upper "
                                 "bound"),
                      {name});
    // The name from the console's table, resolved once; an unknown one is refused below.
    const std::optional<std::size_t> index = u->identifier().layout().find(name.toStdString());
    const ParameterBounds before =
        index ? u->identifier().bounds()[*index] : ParameterBounds{std::nan(""), std::nan("")};
    if (!index || !u->identifier().setBounds(*index, {lower, upper}))
        return refuse(QT_TR_NOOP("%1: bounds [%2, %3] refused (they would not keep the "
                                 "law admissible)"),
                      {name, QString::number(lower), QString::number(upper)});
    logEvent(OperatorEvent::kBounds,
             name.toStdString() + " [" + number(before.lower) + ", " + number(before.upper) + "]",
             name.toStdString() + " [" + number(lower) + ", " + number(upper) + "]");
    publishUpdating();
}

void TestWorker::setParameterLocked(const QString& name, bool locked) {
    ModelUpdater* u = test().updater();
    if (!u)
        return refuse(QT_TR_NOOP("this test has no model updating"));
    const std::optional<std::size_t> index = u->identifier().layout().find(name.toStdString());
    if (!index || !u->identifier().setLocked(*index, locked))
        return refuse(QT_TR_NOOP("%1: the %2 cannot lock this parameter"),
                      {name, QString::fromStdString(u->identifier().methodName())});
    logEvent(OperatorEvent::kLock, name.toStdString() + (locked ? " unlocked" : " locked"),
             name.toStdString() + (locked ? " locked" : " unlocked"));
    publishUpdating();
}

namespace {
// "#<id>", appended rather than "#" + std::to_string(): GCC 12 warns (-Wrestrict) on the latter.
std::string proposalTag(int id) {
    std::string tag(1, '#');
    tag += std::to_string(id);
    return tag;
}
} // namespace

void TestWorker::approveUpdate(int proposalId) {
    std::optional<UpdateProposal> proposal;
    const Reporter* reporter = test().updater() ? &test().updater()->reporter() : nullptr;
    if (reporter)
        for (const UpdateProposal& p : reporter->pending())
            if (p.id == proposalId)
                proposal = p;
    if (!test().approveUpdate(proposalId)) {
        const std::optional<int> newer = reporter ? reporter->supersededBy(proposalId) : std::nullopt;
        if (newer)
            refuse(QT_TR_NOOP("update #%1 was not applied: the estimate has moved on and #%2 "
                              "replaced it; check #%2 and approve it if it is right"),
                   {QString::number(proposalId), QString::number(*newer)});
        else if (proposal && reporter->stale(*proposal, test().time()))
            refuse(QT_TR_NOOP("update #%1 was not applied: it is older than one proposal "
                              "interval (%2 s) and no longer what the estimator believes; "
                              "wait for the next proposal"),
                   {QString::number(proposalId), QString::number(reporter->proposalInterval())});
        else
            refuse(QT_TR_NOOP("update #%1 was not applied (no longer pending, or refused by "
                              "the law; see the alarms)"),
                   {QString::number(proposalId)});
    } else if (proposal) {
        logEvent(OperatorEvent::kApprove,
                 proposalTag(proposalId) + " " + proposal->element + " " +
                     valuesText(proposal->parameters, proposal->current),
                 valuesText(proposal->parameters, proposal->proposed));
        m_session->noteApproved({test().currentStep(), test().time(), proposal->element,
                                 proposal->parameters, proposal->proposed, true, {},
                                 UpdateDecision::Applied, proposalId});
    }
    publishAlarms();
    publishUpdating();
}

void TestWorker::rejectUpdate(int proposalId) {
    std::optional<UpdateProposal> proposal;
    if (const ModelUpdater* u = test().updater())
        for (const UpdateProposal& p : u->reporter().pending())
            if (p.id == proposalId)
                proposal = p;
    if (!test().rejectUpdate(proposalId) || !proposal) {
        const Reporter* reporter = test().updater() ? &test().updater()->reporter() : nullptr;
        if (const std::optional<int> newer =
                reporter ? reporter->supersededBy(proposalId) : std::nullopt)
            refuse(QT_TR_NOOP("update #%1 is no longer pending: #%2 replaced it"),
                   {QString::number(proposalId), QString::number(*newer)});
        else
            refuse(QT_TR_NOOP("update #%1 is no longer pending"), {QString::number(proposalId)});
    } else {
        logEvent(OperatorEvent::kReject, proposalTag(proposalId),
                 "rejected " + proposal->element + " " +
                     valuesText(proposal->parameters, proposal->proposed));
        // In /updating/events too (decision "rejected"), with the next committed step.
        m_session->noteApproved({test().currentStep(), test().time(), proposal->element,
                                 proposal->parameters, proposal->proposed, false,
                                 "rejected by the operator", UpdateDecision::Rejected,
                                 proposalId});
    }
    publishUpdating();
}

void TestWorker::approveOffsets(int id) {
    const ModelUpdater* u = test().updater();
    const OffsetProposal* pending = u ? u->pendingOffsets() : nullptr;
    if (!pending || pending->id != id) {
        refuse(QT_TR_NOOP("offsets #%1 are no longer pending"), {QString::number(id)});
        return publishUpdating();
    }
    const OffsetProposal p = *pending;
    const Element* specimen = test().structure().element(u->specimenElement());
    const auto [old, applied] =
        offsetsText(*u, p, elementUnits(specimen ? specimen->typeName() : std::string()));
    std::string error;
    if (!test().approveOffsets(id, &error))
        refuse(QT_TR_NOOP("offsets #%1 were not applied: %2"),
               {QString::number(id), QString::fromStdString(error)});
    else
        logEvent(OperatorEvent::kApproveOffsets, old, applied);
    publishAlarms();
    publishUpdating();
}

void TestWorker::rejectOffsets(int id) {
    const ModelUpdater* u = test().updater();
    const OffsetProposal* pending = u ? u->pendingOffsets() : nullptr;
    if (!pending || pending->id != id) {
        refuse(QT_TR_NOOP("offsets #%1 are no longer pending"), {QString::number(id)});
        return publishUpdating();
    }
    const Element* specimen = test().structure().element(u->specimenElement());
    const auto [old, offered] = offsetsText(
        *u, *pending, elementUnits(specimen ? specimen->typeName() : std::string()));
    test().rejectOffsets(id);
    logEvent(OperatorEvent::kRejectOffsets, old, offered);
    publishUpdating();
}

void TestWorker::setReporterPolicy(ReporterPolicy policy, int everyN) {
    ModelUpdater* u = test().updater();
    if (!u)
        return refuse(QT_TR_NOOP("this test has no model updating"));
    const Reporter& r = u->reporter();
    const std::string before = std::string(reporterPolicyName(r.policy())) +
                               (r.policy() == ReporterPolicy::EveryNSteps
                                    ? " N=" + std::to_string(r.everyN()) : std::string());
    u->reporter().setPolicy(policy, everyN);
    const std::string after = std::string(reporterPolicyName(policy)) +
                              (policy == ReporterPolicy::EveryNSteps
                                   ? " N=" + std::to_string(everyN) : std::string());
    if (after != before)
        logEvent(OperatorEvent::kPolicy, before, after);
    publishUpdating();
}

void TestWorker::setFitThreshold(double threshold) {
    ModelUpdater* u = test().updater();
    if (!u)
        return refuse(QT_TR_NOOP("this test has no model updating"));
    if (!(threshold > 0.0) || !std::isfinite(threshold))
        return refuse(QT_TR_NOOP("the fit-error threshold must be a positive number"));
    InspectorSettings s = u->inspector().settings();
    logEvent(OperatorEvent::kThreshold, number(s.threshold), number(threshold));
    s.threshold = threshold;
    u->inspector().setSettings(s);
    publishUpdating();
}

void TestWorker::restartPacing() {
    m_session->restartPacing();
    m_progressTimer.start();
    m_progressStep = test().currentStep();
}

void TestWorker::schedule(int delayMs) {
    if (m_scheduled)
        return;
    m_scheduled = true;
    QTimer::singleShot(delayMs, this, &TestWorker::runChunk);
}

bool TestWorker::stepOnce() {
    const HybridTest::StepResult r = m_session->stepOnce();
    publishAlarms();
    if (r == HybridTest::StepResult::Advanced)
        return true;
    if (r == HybridTest::StepResult::Finished)
        setState(RunState::Finished);
    else if (r == HybridTest::StepResult::Held)
        setState(RunState::Holding,
                 QString::fromStdString(holdReason(test()).value_or(std::string())));
    else
        setState(RunState::Failed, QString::fromStdString(test().lastError()));
    return false;
}

void TestWorker::runChunk() {
    m_scheduled = false;
    if (m_state != RunState::Running)
        return;
    const TestSession::Progress p = m_session->advance(kChunkMs * 1e-3);
    publishAlarms();
    const bool moving = p.status == TestSession::Status::Advanced ||
                        p.status == TestSession::Status::Waiting;
    if (m_reconnecting && moving && test().state() != HybridTest::State::Holding)
        // The policy's reconnect worked (stepping, or waiting for the pace): running, and why.
        setState(RunState::Running,
                 tr("link restored: the test resumed after an automatic reconnect"));
    switch (p.status) {
    case TestSession::Status::Advanced:
        emitProgress(false);
        schedule(0);
        return;
    case TestSession::Status::Waiting: // the pace, or a reconnect backoff
        emitProgress(false);
        schedule(std::max(1, int(std::ceil(std::min(p.wait, 0.25) * 1000.0))));
        return;
    case TestSession::Status::Finished: setState(RunState::Finished); return;
    case TestSession::Status::Held:
        setState(RunState::Holding,
                 QString::fromStdString(holdReason(test()).value_or(std::string())));
        return;
    case TestSession::Status::Failed:
        setState(RunState::Failed, QString::fromStdString(m_session->lastError()));
        return;
    }
}

void TestWorker::setState(RunState state, const QString& message) {
    m_state = state;
    m_reconnecting = false;
    if (state == RunState::Finished || state == RunState::Stopped || state == RunState::Failed) {
        m_session->finish();
        m_flushTimer->stop();
    } else {
        m_session->flush();
    }
    emitProgress(true);
    publishUpdating();
    emit stateChanged(state, message);
}

void TestWorker::publishAlarms() {
    const auto& alarms = test().alarms();
    for (; m_alarmsSeen < alarms.size(); ++m_alarmsSeen)
        emit alarmRaised(alarms[m_alarmsSeen]);
}

void TestWorker::publishUpdating() {
    if (test().updater())
        emit updatingChanged(snapshotOf(test()));
}

void TestWorker::emitProgress(bool force) {
    if (!force && m_progressTimer.isValid() && m_progressTimer.elapsed() < kProgressMs)
        return;
    const double seconds = m_progressTimer.isValid() ? m_progressTimer.nsecsElapsed() * 1e-9 : 0.0;
    if (seconds > 0.05) { // a rate over a shorter span is noise
        m_lastRate = (test().currentStep() - m_progressStep) / seconds;
        m_progressTimer.start();
        m_progressStep = test().currentStep();
    }
    const double rate = m_state == RunState::Running ? m_lastRate : 0.0;
    emit progress(test().currentStep(), test().totalSteps(), test().time(), rate);
    if (!force && m_state == RunState::Running)
        publishUpdating();
}

} // namespace hsmu::gui
