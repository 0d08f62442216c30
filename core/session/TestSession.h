#pragma once
// TestSession: one hybrid test driven the same way by every front end (the console's worker,
// `hsmu run`, `hsmu compare`; docs/architecture.md "The test session"). It owns
//   - the HybridTest and its stepping loop (advance(): at most a wall-time budget of steps),
//   - pacing (speed: test seconds per wall second; <= 0 as fast as possible),
//   - the HDF5 record (RecordWriter): opened by openRecord() (its folder created), rows
//     committed before it opened (step 0 of prepare()) and notes written then; alarms
//     tracked; updates approved between steps attached to the next row; flushed at every
//     call of advance() / tick() that finds it due (RecordWriter::kFlushInterval), so a note
//     added while paused or held reaches the file within about a second,
//   - the hold / reconnect / resume policy (ReconnectPolicy: automatic resumes after a
//     control fault with a doubling backoff; never after a limit, operator or estimator hold),
//   - the emergency hold entry point, callable from any thread.
// It never sleeps except in runToEnd() (for pacing and backoff, the blocking driver of the
// command line); advance() returns how long to wait instead, so an event loop schedules it.
//
// Thread rules: everything on the thread that owns the session, except emergencyHold() and
// emergencyHoldPending(), which any thread may call at any time.

#include "core/experiment/HybridTest.h"
#include "core/session/SessionOptions.h"

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace hsmu {

class TestSession final : private StepObserver {
public:
    enum class Status {
        Advanced, ///< the budget was spent stepping; call advance() again
        Waiting,  ///< ahead of the pace or in a reconnect backoff: call again after `wait`
        Finished,
        Held,   ///< in a hold that the policy does not resume (limit, operator, retries spent)
        Failed, ///< the test cannot step (lastError())
    };
    struct Progress {
        Status status = Status::Advanced;
        double wait = 0.0; ///< [s] of wall time before the next advance() is useful (Waiting)
    };
    /// A reconnect attempt the policy is about to make (for the front end's messages).
    struct Reconnect {
        int attempt = 0, of = 0;
        double delay = 0.0; ///< [s] waited before it
        std::string reason; ///< the hold's reason
    };

    TestSession(std::unique_ptr<HybridTest> test, SessionOptions options);
    ~TestSession() override; ///< finishes the record
    TestSession(const TestSession&) = delete;
    TestSession& operator=(const TestSession&) = delete;

    HybridTest& test() { return *m_test; }
    const HybridTest& test() const { return *m_test; }
    const SessionOptions& options() const { return m_options; }

    /// HybridTest::prepare() once (idempotent). False with lastError() if it cannot start.
    bool prepare();
    bool prepared() const { return m_prepared; }
    const std::string& lastError() const { return m_lastError; }

    /// Create the record's folder and file (idempotent; nothing when recordPath is empty).
    /// False with lastError() when it cannot be written (nothing is recorded then).
    bool openRecord();
    /// The open record, or nullptr.
    RecordWriter* record() { return m_record.get(); }
    bool recording() const { return !m_options.recordPath.empty(); }

    /// Observers of every committed step (not owned; remove before they die).
    void addObserver(StepObserver* o) { m_test->addObserver(o); }
    void removeObserver(StepObserver* o) { m_test->removeObserver(o); }

    /// Step for at most budget seconds of wall time (at least one step unless paced or held),
    /// measured on the coarse clock (core/util/CoarseClock.h: up to one kernel tick, 1-10 ms,
    /// more).
    /// Honours a pending emergency hold before every step, the pace, and the reconnect policy.
    Progress advance(double budgetSeconds);
    /// Exactly one step, ignoring the pace (the console's single step).
    HybridTest::StepResult stepOnce();
    /// Blocking driver: advance() until Finished, Held or Failed, sleeping through waits and
    /// flushing while it sleeps. onProgress (may be empty) is called after every advance().
    Status runToEnd(const std::function<void(const Progress&)>& onProgress = {});

    void setSpeed(double testSecondsPerWallSecond);
    /// Restart the pace from the current test time (after a pause, a hold, a speed change).
    void restartPacing();

    /// Operator hold between steps (on the session's thread); cancels a pending reconnect.
    void hold(const std::string& reason);
    /// Operator resume: leaves a hold (the held step is retried); the reconnect count restarts.
    void resume();
    /// Any thread: the test holds before its next step (a pending reconnect is cancelled).
    /// The out-of-band part (reaching the controls while a step is blocked) is the controls'
    /// own thread-safe hold, forwarded from here.
    void emergencyHold(const std::string& reason);
    bool emergencyHoldPending() const { return m_emergency.load(); }
    /// Called when the policy starts a reconnect attempt (may be empty).
    std::function<void(const Reconnect&)> onReconnect;
    /// Attempts made for the current control fault (0 when none).
    int reconnectAttempts() const { return m_attempts; }

    /// An operator note at the current step and test time (kept until the record opens;
    /// after finish() appended to the closed record). False when this session records
    /// nothing or the record failed (lastError() says why when a write failed).
    bool addNote(const std::string& text);
    bool addNote(double time, int step, const std::string& text);
    /// An update the operator approved (ok) or rejected between steps: written to
    /// /updating/events with the next committed row.
    void noteApproved(const UpdateEvent& event);
    /// Flush the record if due (call at least once a second while paused or held).
    void tick();
    /// Flush the record now (a state change).
    void flush();
    /// Finish the record; false with lastError() if any write failed. Idempotent.
    bool finish();

private:
    void onStep(const StepRecord& record) override;
    bool takeEmergency();
    bool heldOnControlFault() const;
    std::optional<Progress> reconnectIfDue();

    std::unique_ptr<HybridTest> m_test;
    SessionOptions m_options;
    std::unique_ptr<RecordWriter> m_record;
    bool m_prepared = false;
    bool m_finished = false;
    std::string m_lastError;

    std::vector<StepRecord> m_unrecorded; ///< rows before the record opened (step 0)
    struct Note {
        double time;
        int step;
        std::string text;
    };
    std::vector<Note> m_unrecordedNotes;
    std::vector<UpdateEvent> m_approved;

    using Clock = std::chrono::steady_clock;
    Clock::time_point m_paceStart{};
    double m_paceStartTime = 0.0;
    int m_attempts = 0;
    int m_stepAtResume = -1;
    std::optional<Clock::time_point> m_retryAt;
    bool m_operatorHold = false; ///< hold() since the last resume(): never resumed automatically

    std::atomic<bool> m_emergency{false};
    mutable std::mutex m_emergencyMutex;
    std::string m_emergencyReason;
};

} // namespace hsmu
