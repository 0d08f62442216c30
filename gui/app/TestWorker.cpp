#include "gui/app/TestWorker.h"

#include "core/output/RunLayout.h"
#include "core/output/RunSummary.h"
#include "core/experiment/HybridTest.h"
#include "core/updating/ModelUpdater.h"
#include "gui/app/RecordBuffer.h"

#include <QDir>
#include <QFileInfo>
#include <QTimer>

#include <nlohmann/json.hpp>

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

std::string valuesText(const ParameterValues& values) {
    std::string out;
    for (const auto& [name, v] : values)
        out += (out.empty() ? "" : ", ") + name + "=" + number(v);
    return out;
}

/// The configuration text and notes with the updating policy in force at the first step.
void withPolicy(RecordStart& start, const Reporter& reporter) {
    try {
        nlohmann::json cfg = nlohmann::json::parse(start.configuration);
        if (cfg.contains("updating") && cfg["updating"].is_object()) {
            cfg["updating"]["reporter"]["policy"] = reporterPolicyName(reporter.policy());
            cfg["updating"]["reporter"]["everyN"] = reporter.everyN();
            start.configuration = cfg.dump();
        }
    } catch (const std::exception&) {
        // not JSON (a test's hand-made RecordStart): kept as given
    }
    const std::string key = ", updating = ";
    if (const auto at = start.operatorNotes.find(key); at != std::string::npos)
        start.operatorNotes = start.operatorNotes.substr(0, at) + key +
                              reporterPolicyName(reporter.policy());
}
} // namespace

TestWorker::TestWorker(std::unique_ptr<HybridTest> test, std::shared_ptr<RecordBuffer> buffer,
                       bool allowUnstable, RecordStart record, QString recordPath)
    : m_test(std::move(test)), m_buffer(std::move(buffer)), m_allowUnstable(allowUnstable),
      m_recordStart(std::move(record)), m_recordPath(std::move(recordPath)) {
    m_test->addObserver(this);
}

TestWorker::~TestWorker() {
    m_test->removeObserver(this);
    if (m_record)
        m_record->finish();
}

bool TestWorker::openRecord() {
    if (m_recordPath.isEmpty() || m_record)
        return true;
    try {
        if (!QDir().mkpath(QFileInfo(m_recordPath).absolutePath()))
            throw std::runtime_error("cannot create the folder " +
                                     QFileInfo(m_recordPath).absolutePath().toStdString());
        if (const ModelUpdater* u = m_test->updater())
            withPolicy(m_recordStart, u->reporter());
        m_record = std::make_unique<RecordWriter>(m_recordPath.toStdString(),
                                                  RunLayout::of(*m_test), m_recordStart);
    } catch (const std::exception& e) {
        m_recordPath.clear();
        setState(RunState::Failed, tr("the record cannot be written: %1").arg(e.what()));
        return false;
    }
    m_record->trackAlarms(&m_test->alarms());
    for (const StepRecord& row : m_unrecorded)
        m_record->onStep(row);
    m_unrecorded.clear();
    for (const Note& n : m_unrecordedNotes)
        m_record->addNote(n.time, n.step, n.text);
    m_unrecordedNotes.clear();
    m_record->flush();
    emit recordingStarted(m_recordPath);
    return true;
}

void TestWorker::logEvent(const char* action, std::string oldValue, std::string newValue) {
    const OperatorEvent e = OperatorEvent::now(m_test->currentStep(), m_test->time(), action,
                                               std::move(oldValue), std::move(newValue));
    if (m_record)
        m_record->addNote(e.time, e.step, e.recordText());
    else if (!m_recordPath.isEmpty())
        m_unrecordedNotes.push_back({e.time, e.step, e.recordText()});
    emit operatorEvent(e);
}

void TestWorker::onStep(const StepRecord& record) {
    if (m_buffer->push(record))
        emit recordsAvailable();
    if (m_recordPath.isEmpty())
        return;
    if (!m_record) {
        m_unrecorded.push_back(record); // step 0 of prepare(), written when the record opens
        return;
    }
    if (m_approved.empty() || !record.hasUpdating) {
        m_record->onStep(record);
        return;
    }
    // Updates approved between two steps go to /updating/events with this row.
    StepRecord row = record;
    row.updating.applied.insert(row.updating.applied.begin(), m_approved.begin(), m_approved.end());
    m_approved.clear();
    m_record->onStep(row);
}

bool TestWorker::ensurePrepared() {
    if (m_prepared)
        return true;
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

void TestWorker::confirmPreflight() {
    if (m_state == RunState::Ready)
        logEvent(OperatorEvent::kPreflightConfirmed, "unconfirmed", "confirmed");
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
    logEvent(OperatorEvent::kSingleStep, std::to_string(m_test->currentStep()),
             std::to_string(m_test->currentStep() + 1));
    if (stepOnce()) {
        emitProgress(true);
        publishUpdating();
    }
}

void TestWorker::resume() {
    if (!m_armed)
        return; // never drives a test the operator has not confirmed
    if (m_state == RunState::Holding)
        m_test->resume();
    else if (m_state != RunState::Paused)
        return;
    logEvent(OperatorEvent::kResume, m_state == RunState::Holding ? "holding" : "paused",
             "running");
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
        m_test->hold("stopped by the operator"); // the record's text: language-neutral
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
    m_test->hold(why);
    publishAlarms();
    setState(RunState::Holding,
             reason.isEmpty() ? tr("emergency hold by the operator") : reason);
}

void TestWorker::setSpeed(double factor) {
    m_speed = std::isfinite(factor) ? factor : 0.0;
    restartPacing();
}

void TestWorker::addNote(const QString& text) {
    if (text.trimmed().isEmpty())
        return;
    if (m_recordPath.isEmpty() || (m_record && !m_record->ok())) {
        emit commandRefused(tr("the note was not kept: this test is not recorded"));
        return;
    }
    if (m_record)
        m_record->addNote(m_test->time(), m_test->currentStep(), text.toStdString());
    else // written when the record opens, at the first driven step
        m_unrecordedNotes.push_back({m_test->time(), m_test->currentStep(), text.toStdString()});
}

void TestWorker::setParameterBounds(const QString& name, double lower, double upper) {
    ModelUpdater* u = m_test->updater();
    if (!u)
        return emit commandRefused(tr("this test has no model updating"));
    if (!(lower <= upper) || !std::isfinite(lower) || !std::isfinite(upper))
        return emit commandRefused(
            tr("%1: the lower bound must be a number not above the upper bound").arg(name));
    ParameterBounds before{std::nan(""), std::nan("")};
    if (const auto it = u->identifier().bounds().find(name.toStdString());
        it != u->identifier().bounds().end())
        before = it->second;
    if (!u->identifier().setBounds(name.toStdString(), {lower, upper}))
        return emit commandRefused(tr("%1: bounds [%2, %3] refused (they would not keep the "
                                      "law admissible)")
                                       .arg(name)
                                       .arg(lower)
                                       .arg(upper));
    logEvent(OperatorEvent::kBounds,
             name.toStdString() + " [" + number(before.lower) + ", " + number(before.upper) + "]",
             name.toStdString() + " [" + number(lower) + ", " + number(upper) + "]");
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
    logEvent(OperatorEvent::kLock, name.toStdString() + (locked ? " unlocked" : " locked"),
             name.toStdString() + (locked ? " locked" : " unlocked"));
    publishUpdating();
}

void TestWorker::approveUpdate(int proposalId) {
    std::optional<UpdateProposal> proposal;
    if (const ModelUpdater* u = m_test->updater())
        for (const UpdateProposal& p : u->reporter().pending())
            if (p.id == proposalId)
                proposal = p;
    if (!m_test->approveUpdate(proposalId)) {
        emit commandRefused(tr("update #%1 was not applied (no longer pending, or refused by "
                               "the law; see the alarms)")
                                .arg(proposalId));
    } else if (proposal) {
        logEvent(OperatorEvent::kApprove,
                 "#" + std::to_string(proposalId) + " " + proposal->element + " " +
                     valuesText(proposal->current),
                 valuesText(proposal->proposed));
        m_approved.push_back({m_test->currentStep(), m_test->time(), proposal->element,
                              proposal->proposed, true, {}});
    }
    publishAlarms();
    publishUpdating();
}

void TestWorker::rejectUpdate(int proposalId) {
    std::string element;
    if (const ModelUpdater* u = m_test->updater())
        for (const UpdateProposal& p : u->reporter().pending())
            if (p.id == proposalId)
                element = p.element + " " + valuesText(p.proposed);
    if (!m_test->rejectUpdate(proposalId))
        emit commandRefused(tr("update #%1 is no longer pending").arg(proposalId));
    else
        logEvent(OperatorEvent::kReject, "#" + std::to_string(proposalId), "rejected " + element);
    publishUpdating();
}

void TestWorker::setReporterPolicy(ReporterPolicy policy, int everyN) {
    ModelUpdater* u = m_test->updater();
    if (!u)
        return emit commandRefused(tr("this test has no model updating"));
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
    ModelUpdater* u = m_test->updater();
    if (!u)
        return emit commandRefused(tr("this test has no model updating"));
    if (!(threshold > 0.0) || !std::isfinite(threshold))
        return emit commandRefused(tr("the fit-error threshold must be a positive number"));
    InspectorSettings s = u->inspector().settings();
    logEvent(OperatorEvent::kThreshold, number(s.threshold), number(threshold));
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
