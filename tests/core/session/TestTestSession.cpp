// Tests of TestSession (core/session/TestSession.h): the one stepping loop shared by the
// console, `hsmu run` and `hsmu compare`. SDOF frame, m = 2 t, k = 800 kN/m, 5 % damping, a
// 2 Hz sine of 2 m/s^2 for 1 s at 0.01 s (100 steps); the spring is a linear specimen behind a
// control that can fail its measurement at chosen targets (a lost link: ControlFault).

#include "core/experimental/ExperimentalElement.h"
#include "core/experimental/VirtualSpecimen.h"
#include "core/hysteresis/LinearElastic.h"
#include "core/integration/ExplicitNewmark.h"
#include "core/record/RecordReader.h"
#include "core/session/TestSession.h"
#include "core/structure/Structure.h"

#include <QtTest>

#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>
#include <set>
#include <thread>

using namespace hsmu;

namespace {

constexpr double kMass = 2.0, kStiff = 800.0;

/// Forwards to a VirtualSpecimen; measure() fails at the targets whose index is in faults.
class FlakyControl final : public ExperimentalControl {
public:
    FlakyControl(std::set<int> faults, int* resumes) : m_faults(std::move(faults)), m_resumes(resumes) {}
    std::string description() const override { return "flaky"; }
    ControlResult prepare(double dt) override { return m_inner.prepare(dt); }
    ControlResult setTarget(double d) override {
        ++m_targets;
        return m_inner.setTarget(d);
    }
    ControlResult measure(ControlMeasurement& out) override {
        if (m_faults.erase(m_targets) > 0)
            return ControlResult::fault("link lost");
        return m_inner.measure(out);
    }
    ControlResult commit() override { return m_inner.commit(); }
    void hold(const std::string& reason) override { m_inner.hold(reason); }
    void resume() override {
        ++*m_resumes;
        m_inner.resume();
    }

private:
    VirtualSpecimen m_inner{std::make_unique<LinearElastic>(kStiff), VirtualSpecimenOptions{}};
    std::set<int> m_faults;
    int* m_resumes;
    int m_targets = 0;
};

GroundMotion sine() {
    GroundMotion gm;
    gm.name = "sine";
    gm.dt = 0.01;
    for (int i = 0; i <= 100; ++i)
        gm.acceleration.push_back(2.0 * std::sin(2.0 * std::numbers::pi * 2.0 * i * gm.dt));
    return gm;
}

std::unique_ptr<HybridTest> sdof(std::set<int> faults, int* resumes,
                                 const SafetyLimits& limits = {}) {
    auto s = std::make_unique<Structure>();
    s->addDof("DOF 1", kMass);
    s->addElement(std::make_unique<ExperimentalElement>(
        "Spring", "lateralSpring", std::vector<DofTerm>{{0, 1.0}},
        std::make_unique<FlakyControl>(std::move(faults), resumes), limits, kStiff));
    s->setModalDamping(0.05, 1, 1);
    HybridTestOptions o;
    o.dt = 0.01;
    return std::make_unique<HybridTest>(std::move(s), std::make_unique<ExplicitNewmark>(), sine(),
                                        o);
}

struct Rows final : StepObserver {
    std::vector<double> u;
    void onStep(const StepRecord& r) override { u.push_back(r.u[0]); }
};

} // namespace

class TestTestSession : public QObject {
    Q_OBJECT
private slots:
    // Attempt k waits min(0.5 * 2^(k-1), 8) s.
    void backoffDoubles() {
        const ReconnectPolicy p;
        const double expected[] = {0.5, 1.0, 2.0, 4.0, 8.0, 8.0};
        for (int k = 1; k <= 6; ++k)
            QCOMPARE(p.delayBefore(k), expected[k - 1]);
    }

    // Two lost links, policy of 2 attempts without delay: the run finishes and its history
    // equals an undisturbed run bit for bit (a held step is retried from where it started).
    void reconnectsAndFinishesLikeAnUndisturbedRun() {
        int resumesA = 0, resumesB = 0;
        SessionOptions o;
        o.reconnect = {2, 0.0, 0.0};
        TestSession faulty(sdof({10, 40}, &resumesA), o);
        TestSession clean(sdof({}, &resumesB), o);
        Rows a, b;
        faulty.addObserver(&a);
        clean.addObserver(&b);
        std::vector<int> attempts;
        faulty.onReconnect = [&](const TestSession::Reconnect& r) {
            attempts.push_back(r.attempt);
            QCOMPARE(r.of, 2);
            QCOMPARE(r.reason, std::string("Spring: link lost"));
        };
        QVERIFY(faulty.prepare());
        QVERIFY(clean.prepare());
        QCOMPARE(faulty.runToEnd(), TestSession::Status::Finished);
        QCOMPARE(clean.runToEnd(), TestSession::Status::Finished);
        QCOMPARE(resumesA, 2);
        QCOMPARE(attempts, (std::vector<int>{1, 1})); // each fault is a new one (it advanced)
        QCOMPARE(a.u, b.u);
        QCOMPARE(int(a.u.size()), 101);
    }

    // Issue 25 item 12: an automatic reconnect was logged as the operator's ("test resumed",
    // kind OperatorHold). Who resumed is told truthfully: the policy's resumes are link events
    // (ControlFault, "test resumed after an automatic reconnect"); only resume() is the
    // operator's.
    void automaticResumeIsNotTheOperators() {
        int resumes = 0;
        SessionOptions o;
        o.reconnect = {2, 0.0, 0.0};
        TestSession s(sdof({10, 40}, &resumes), o);
        QVERIFY(s.prepare());
        QCOMPARE(s.runToEnd(), TestSession::Status::Finished);
        QCOMPARE(resumes, 2);
        int automatic = 0;
        for (const Alarm& a : s.test().alarms()) {
            QVERIFY2(a.kind != AlarmKind::OperatorHold, a.message.c_str());
            if (a.code == "test-resumed-reconnect") {
                ++automatic;
                QCOMPARE(a.kind, AlarmKind::ControlFault);
                QCOMPARE(a.severity, AlarmSeverity::Info);
                QCOMPARE(a.message, std::string("test resumed after an automatic reconnect"));
            }
        }
        QCOMPARE(automatic, 2);
        // The operator's own hold and resume stay the operator's.
        TestSession manual(sdof({}, &resumes), o);
        QVERIFY(manual.prepare());
        manual.advance(0.0);
        manual.hold("operator hold");
        manual.resume();
        const Alarm& last = manual.test().alarms().back();
        QCOMPARE(last.kind, AlarmKind::OperatorHold);
        QCOMPARE(last.code, std::string("test-resumed"));
    }

    // Faults in a row beyond the policy: the test stays held, the attempts are counted.
    void givesUpAfterTheAttempts() {
        int resumes = 0;
        SessionOptions o;
        o.reconnect = {2, 0.0, 0.0};
        TestSession s(sdof({10, 11, 12}, &resumes), o); // targets 11, 12: the retries fail too
        QVERIFY(s.prepare());
        QCOMPARE(s.runToEnd(), TestSession::Status::Held);
        QCOMPARE(resumes, 2);
        QCOMPARE(s.reconnectAttempts(), 2);
        QCOMPARE(s.test().currentStep(), 9);
    }

    // With a backoff the session does not resume at once: advance() returns Waiting with the
    // first delay, and the test is still holding.
    void backoffIsReturnedNotSlept() {
        int resumes = 0;
        SessionOptions o;
        o.reconnect = {3, 0.5, 8.0};
        TestSession s(sdof({5}, &resumes), o);
        QVERIFY(s.prepare());
        TestSession::Progress p;
        do
            p = s.advance(1.0);
        while (p.status == TestSession::Status::Advanced);
        QCOMPARE(p.status, TestSession::Status::Waiting);
        QVERIFY(p.wait > 0.0 && p.wait <= 0.5);
        QCOMPARE(s.test().state(), HybridTest::State::Holding);
        QCOMPARE(resumes, 0);
        // An operator hold cancels the pending reconnect: the hold stands.
        s.hold("operator");
        QCOMPARE(s.advance(1.0).status, TestSession::Status::Held);
        QCOMPARE(resumes, 0);
    }

    // A limit hold is never resumed automatically.
    void limitHoldIsNotResumed() {
        int resumes = 0;
        SafetyLimits limits;
        limits.maxDeformation = 1e-5; // m: exceeded within a few steps
        SessionOptions o;
        o.reconnect = {5, 0.0, 0.0};
        TestSession s(sdof({}, &resumes, limits), o);
        QVERIFY(s.prepare());
        QCOMPARE(s.runToEnd(), TestSession::Status::Held);
        QCOMPARE(resumes, 0);
        QCOMPARE(s.test().alarms().back().kind, AlarmKind::LimitExceeded);
    }

    // emergencyHold() from another thread holds the test before its next step.
    void emergencyHoldFromAnotherThread() {
        int resumes = 0;
        TestSession s(sdof({}, &resumes), {});
        QVERIFY(s.prepare());
        QCOMPARE(s.advance(0.0).status, TestSession::Status::Advanced); // one step
        std::thread t([&s] { s.emergencyHold("stop now"); });
        t.join();
        QVERIFY(s.emergencyHoldPending());
        QCOMPARE(s.advance(1.0).status, TestSession::Status::Held);
        QCOMPARE(s.test().currentStep(), 1);
        QCOMPARE(s.test().alarms().back().kind, AlarmKind::OperatorHold);
        const std::string message = s.test().alarms().back().message;
        QVERIFY2(message.find("test held") == 0 && message.find("stop now") != std::string::npos,
                 message.c_str());
        QVERIFY(!s.emergencyHoldPending());
    }

    // The record: step 0 (committed before the record opened) is in it, and a note added
    // while held reaches the file through tick() alone (no state change, no finish).
    void noteWhileHeldReachesTheFile() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath("run/record.h5").toStdString();
        int resumes = 0;
        SessionOptions o;
        o.recordPath = path;
        o.recordStart = RecordStart{"{}", "sdof", {}, 0.01};
        TestSession s(sdof({}, &resumes), o);
        QVERIFY(s.prepare()); // step 0, before the record exists
        QVERIFY(s.openRecord());
        for (int i = 0; i < 5; ++i)
            QCOMPARE(s.advance(0.0).status, TestSession::Status::Advanced);
        s.hold("paused for a look");
        QVERIFY(s.addNote("crack at the base"));
        // Flushed by tick() once RecordWriter::kFlushInterval has passed (polled, 5 s at most).
        QVERIFY(s.record() != nullptr);
        const int before = s.record()->notesFlushed();
        for (int i = 0; i < 100 && s.record()->notesFlushed() == before; ++i) {
            s.tick();
            if (s.record()->notesFlushed() == before)
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        QCOMPARE(s.record()->notesFlushed(), before + 1);
        QVERIFY(s.finish());
        const RecordReader reader(path);
        QCOMPARE(reader.rows(), 6); // steps 0..5
        QCOMPARE(reader.data().steps.front(), 0);
        QCOMPARE(reader.data().notes.back().text, std::string("crack at the base"));
    }
};

QTEST_APPLESS_MAIN(TestTestSession)
#include "TestTestSession.moc"
