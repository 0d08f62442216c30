#include "core/session/TestSession.h"

#include "core/output/RunLayout.h"
#include "core/output/RunSummary.h"
#include "core/updating/ModelUpdater.h"
#include "core/util/CoarseClock.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <thread>

namespace hsmu {

namespace {

double seconds(std::chrono::steady_clock::duration d) {
    return std::chrono::duration<double>(d).count();
}

/// The configuration text and notes with the updating policy in force at the first step
/// (the operator may have changed it between loading and starting).
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
        start.operatorNotes =
            start.operatorNotes.substr(0, at) + key + reporterPolicyName(reporter.policy());
}

} // namespace

double ReconnectPolicy::delayBefore(int attempt) const {
    const double d = firstDelay * std::pow(2.0, std::max(0, attempt - 1));
    return std::max(0.0, std::min(d, maxDelay));
}

TestSession::TestSession(std::unique_ptr<HybridTest> test, SessionOptions options)
    : m_test(std::move(test)), m_options(std::move(options)) {
    m_test->addObserver(this);
    restartPacing();
}

TestSession::~TestSession() {
    m_test->removeObserver(this);
    finish();
}

bool TestSession::prepare() {
    if (m_prepared)
        return true;
    if (!m_test->prepare()) {
        m_lastError = m_test->lastError();
        return false;
    }
    m_prepared = true;
    restartPacing();
    return true;
}

bool TestSession::openRecord() {
    if (m_options.recordPath.empty() || m_record)
        return true;
    try {
        const std::filesystem::path parent =
            std::filesystem::absolute(m_options.recordPath).parent_path();
        std::error_code ec;
        std::filesystem::create_directories(parent, ec);
        if (ec)
            throw std::runtime_error(m_options.recordPath + ": cannot create the folder " +
                                     parent.string() + " (" + ec.message() + ")");
        if (const ModelUpdater* u = m_test->updater())
            withPolicy(m_options.recordStart, u->reporter());
        m_record = std::make_unique<RecordWriter>(m_options.recordPath, RunLayout::of(*m_test),
                                                  m_options.recordStart);
    } catch (const std::exception& e) {
        m_lastError = e.what();
        m_options.recordPath.clear();
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
    return true;
}

void TestSession::onStep(const StepRecord& row) {
    if (m_options.recordPath.empty())
        return;
    if (!m_record) {
        m_unrecorded.push_back(row); // step 0 of prepare(), written when the record opens
        return;
    }
    if (m_approved.empty() || !row.hasUpdating) {
        m_record->onStep(row);
        return;
    }
    // Updates approved between two steps go to /updating/events with this row.
    StepRecord withEvents = row;
    // Approved updates join the row's applied ones; rejected ones its decided ones.
    const auto firstDecided = std::stable_partition(
        m_approved.begin(), m_approved.end(), [](const UpdateEvent& e) { return e.ok; });
    withEvents.updating.applied.insert(withEvents.updating.applied.begin(), m_approved.begin(),
                                       firstDecided);
    withEvents.updating.decided.insert(withEvents.updating.decided.begin(), firstDecided,
                                       m_approved.end());
    m_approved.clear();
    m_record->onStep(withEvents);
}

void TestSession::setSpeed(double factor) {
    m_options.speed = std::isfinite(factor) ? factor : 0.0;
    restartPacing();
}

void TestSession::restartPacing() {
    m_paceStart = Clock::now();
    m_paceStartTime = m_test->time();
}

bool TestSession::takeEmergency() {
    if (!m_emergency.exchange(false))
        return false;
    std::string why;
    {
        std::lock_guard<std::mutex> lock(m_emergencyMutex);
        why.swap(m_emergencyReason);
    }
    hold(why.empty() ? std::string("emergency hold by the operator") : why);
    return true;
}

void TestSession::emergencyHold(const std::string& reason) {
    {
        std::lock_guard<std::mutex> lock(m_emergencyMutex);
        m_emergencyReason = reason;
    }
    m_emergency.store(true);
    // Out of band: every control gets its hold now, also while a step is blocked on a silent
    // link (HybridTest::emergencyHold is callable from any thread).
    m_test->emergencyHold(reason);
}

void TestSession::hold(const std::string& reason) {
    m_retryAt.reset();
    m_operatorHold = true; // stands until the operator resumes, whatever held the test before
    m_test->hold(reason);
    flush();
}

void TestSession::resume() {
    m_retryAt.reset();
    m_operatorHold = false;
    m_attempts = 0;
    m_stepAtResume = -1;
    m_test->resume();
    restartPacing();
}

bool TestSession::heldOnControlFault() const {
    const auto& alarms = m_test->alarms();
    return m_test->state() == HybridTest::State::Holding && !alarms.empty() &&
           alarms.back().kind == AlarmKind::ControlFault;
}

/// After a hold: nothing (the hold stands), a wait (backoff pending), or resumed (nullopt
/// with the test Running again).
std::optional<TestSession::Progress> TestSession::reconnectIfDue() {
    if (m_retryAt) {
        const double left = seconds(*m_retryAt - Clock::now());
        if (left > 0.0)
            return Progress{Status::Waiting, left};
        m_retryAt.reset();
        m_stepAtResume = m_test->currentStep();
        m_test->resume(HybridTest::ResumeCause::Reconnect); // the control's own attempts
        restartPacing();
        return std::nullopt;
    }
    if (m_test->currentStep() > m_stepAtResume)
        m_attempts = 0; // the test advanced since the last resume: a new fault
    if (m_operatorHold || m_attempts >= m_options.reconnect.attempts || !heldOnControlFault())
        return Progress{Status::Held, 0.0};
    ++m_attempts;
    const double delay = m_options.reconnect.delayBefore(m_attempts);
    flush(); // the hold and its alarm reach the file before a reconnect may block
    if (onReconnect)
        onReconnect({m_attempts, m_options.reconnect.attempts, delay,
                     holdReason(*m_test).value_or("held")});
    m_retryAt = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(delay));
    return Progress{Status::Waiting, delay};
}

HybridTest::StepResult TestSession::stepOnce() {
    takeEmergency();
    return m_test->step();
}

TestSession::Progress TestSession::advance(double budgetSeconds) {
    // The budget on the coarse clock (a tick's resolution): read once a step (CoarseClock.h).
    const CoarseClock::time_point start = CoarseClock::now();
    Progress out{Status::Advanced, 0.0};
    for (;;) {
        if (takeEmergency()) {
            out = {Status::Held, 0.0};
            break;
        }
        if (m_test->state() == HybridTest::State::Holding) {
            if (auto p = reconnectIfDue()) {
                out = *p;
                break;
            }
        }
        if (m_options.speed > 0.0) {
            const double allowed =
                m_paceStartTime + seconds(Clock::now() - m_paceStart) * m_options.speed;
            const double ahead = m_test->time() + m_test->dt() - allowed;
            if (ahead > 0.0) {
                out = {Status::Waiting, ahead / m_options.speed};
                break;
            }
        }
        const HybridTest::StepResult r = m_test->step();
        if (r == HybridTest::StepResult::Finished) {
            out = {Status::Finished, 0.0};
            break;
        }
        if (r == HybridTest::StepResult::NotReady) {
            m_lastError = m_test->lastError().empty() ? std::string("the test is not prepared")
                                                      : m_test->lastError();
            out = {Status::Failed, 0.0};
            break;
        }
        if (r == HybridTest::StepResult::Held)
            continue; // the policy decides (above): wait, resume or stand
        if (std::chrono::duration<double>(CoarseClock::now() - start).count() >= budgetSeconds)
            break;
    }
    tick();
    return out;
}

TestSession::Status TestSession::runToEnd(const std::function<void(const Progress&)>& onProgress) {
    for (;;) {
        const Progress p = advance(0.1);
        if (onProgress)
            onProgress(p);
        if (p.status == Status::Advanced)
            continue;
        if (p.status != Status::Waiting)
            return p.status;
        // Sleep through the pace or the backoff, flushing at least twice a second.
        std::this_thread::sleep_for(std::chrono::duration<double>(std::min(p.wait, 0.25)));
        tick();
    }
}

bool TestSession::addNote(const std::string& text) {
    return addNote(m_test->time(), m_test->currentStep(), text);
}

bool TestSession::addNote(double time, int step, const std::string& text) {
    if (m_options.recordPath.empty() || (m_record && !m_record->ok()))
        return false;
    if (m_record && m_finished) { // the run ended: the note is appended to the closed record
        if (RecordWriter::appendNote(m_record->path(), time, step, text, &m_lastError))
            return true;
        return false;
    }
    if (m_record)
        m_record->addNote(time, step, text);
    else // written when the record opens, at the first driven step
        m_unrecordedNotes.push_back({time, step, text});
    return true;
}

void TestSession::noteApproved(const UpdateEvent& event) {
    m_approved.push_back(event);
}

void TestSession::tick() {
    if (m_record)
        m_record->flushIfDue();
}

void TestSession::flush() {
    if (m_record)
        m_record->flush();
}

bool TestSession::finish() {
    if (!m_record || m_finished)
        return !m_record || m_record->ok();
    m_finished = true;
    if (!m_record->finish()) {
        m_lastError = m_record->path() + ": the record could not be written: " + m_record->error();
        return false;
    }
    return true;
}

} // namespace hsmu
