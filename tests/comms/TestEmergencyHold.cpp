// The emergency hold out of band (docs/protocol.md "Emergency hold"): while the test's step
// is blocked on a site that read its target and went silent, HybridTest::emergencyHold()
// from another thread reaches the site (its Hold frame arrives while the step is still
// blocked), and the step returns promptly as held by the operator, not at its deadline
// (60 s here: a step that waited for it would fail the "emergency hold" assertions, never by
// a wall-time check). The site may acknowledge the hold (the link stays up and the test
// resumes, retrying the step) or not (the link is closed and the test still holds).
// The 50 ms latency figure is measured in hsmu_bench_link (docs/benchmarks.md).
#include "comms/link/ControlFactory.h"

#include "LinkFixture.h"
#include "SilentSite.h"

#include <QtTest>

#include <thread>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;

namespace {

constexpr double kWait = 30.0; // [s] bound of every wait (a loaded CI machine)

TcpControlOptions patient() {
    TcpControlOptions o;
    o.connectTimeout = kWait;
    o.stepDeadline = 60.0; // far beyond every wait below
    o.silenceTimeout = 120.0;
    o.reconnectAttempts = 1;
    return o;
}

/// Steps on a thread of its own until a step does not advance.
struct Stepper {
    HybridTest& test;
    std::atomic<bool> done{false};
    HybridTest::StepResult result = HybridTest::StepResult::NotReady;
    std::thread thread;
    explicit Stepper(HybridTest& t) : test(t) {
        thread = std::thread([this] {
            do
                result = test.step();
            while (result == HybridTest::StepResult::Advanced);
            done = true;
        });
    }
    ~Stepper() {
        if (thread.joinable())
            thread.join();
    }
};

} // namespace

class TestEmergencyHold : public QObject {
    Q_OBJECT
    TestConfig m_cfg;

    std::unique_ptr<HybridTest> build(std::uint16_t port) {
        return buildHybridTest(
            m_cfg, makeControlFactory(LinkAddress{LinkAddress::Kind::Tcp, "127.0.0.1", port},
                                      patient()));
    }

private slots:
    void initTestCase() {
        nlohmann::json j = condition3(0.3);
        auto& specimen = j["structure"]["elements"][0]["specimen"];
        specimen.erase("fracture");
        m_cfg = parseConfig(j, std::string(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json");
    }

    void holdReachesASilentSiteWhileTheStepIsBlocked() {
        SilentSite site(5, /*ackHolds=*/true);
        auto test = build(site.port());
        Recorder rec;
        test->addObserver(&rec);
        QVERIFY2(test->prepare(), test->lastError().c_str());
        Stepper stepper(*test);
        site.watch(&stepper.done);
        QVERIFY(site.waitSilent(kWait)); // step 6's target was read; no answer will come
        QVERIFY(!stepper.done);
        test->emergencyHold("operator pressed Ctrl+H");
        QVERIFY(site.waitHolds(1, kWait));
        QVERIFY2(!site.stepReturnedAtFirstHold(), "the hold waited for the step");
        stepper.thread.join();
        QCOMPARE(stepper.result, HybridTest::StepResult::Held);
        QCOMPARE(test->state(), HybridTest::State::Holding);
        QCOMPARE(test->currentStep(), 5);
        const Alarm& a = test->alarms().back();
        QCOMPARE(a.kind, AlarmKind::OperatorHold);
        QVERIFY2(a.message.find("emergency hold: operator pressed Ctrl+H") != std::string::npos,
                 a.message.c_str());
        QVERIFY2(a.message.find("no reply within") == std::string::npos, a.message.c_str());
        QCOMPARE(site.holds(), 1); // the test's own hold() took the ack, sent nothing more
        // The native measurement's actuator channels reach the step record (the site
        // reports the target as both positions, 0 held ticks, no flags).
        QCOMPARE(rec.records.size(), std::size_t(6));
        QVERIFY(std::isnan(rec.records[0].elements[0].actuator.commanded));
        for (std::size_t i = 1; i < rec.records.size(); ++i) {
            const ElementSample& e = rec.records[i].elements[0];
            QCOMPARE(e.actuator.commanded, e.commanded);
            QCOMPARE(e.actuator.measured, e.commanded);
            QCOMPARE(e.actuator.heldTicks, std::int64_t(0));
            QCOMPARE(e.actuator.flags, std::int64_t(0));
        }

        // The link stayed up: resume retries step 6, which the site now answers.
        test->resume();
        Stepper again(*test);
        again.thread.join();
        QCOMPARE(again.result, HybridTest::StepResult::Finished);
        QCOMPARE(test->currentStep(), test->totalSteps());
        QCOMPARE(site.targetsMeasured(), test->totalSteps());
    }

    void holdWithoutAnAcknowledgementStillHolds() {
        SilentSite site(3, /*ackHolds=*/false);
        auto test = build(site.port());
        QVERIFY2(test->prepare(), test->lastError().c_str());
        Stepper stepper(*test);
        site.watch(&stepper.done);
        QVERIFY(site.waitSilent(kWait));
        test->emergencyHold("SIGINT");
        QVERIFY(site.waitHolds(1, kWait));
        QVERIFY(!site.stepReturnedAtFirstHold());
        stepper.thread.join();
        QCOMPARE(stepper.result, HybridTest::StepResult::Held);
        QCOMPARE(test->currentStep(), 3);
        QCOMPARE(test->alarms().back().kind, AlarmKind::OperatorHold);
        QVERIFY(test->alarms().back().message.find("emergency hold: SIGINT") != std::string::npos);
    }

    void holdBetweenStepsHoldsTheNextStep() {
        SilentSite site(1000, /*ackHolds=*/true);
        auto test = build(site.port());
        QVERIFY2(test->prepare(), test->lastError().c_str());
        QCOMPARE(test->step(), HybridTest::StepResult::Advanced);
        test->emergencyHold("between steps");
        QVERIFY(site.waitHolds(1, kWait));
        QCOMPARE(test->step(), HybridTest::StepResult::Held);
        QCOMPARE(test->currentStep(), 1);
        QCOMPARE(site.targetsMeasured(), 1); // no target after the hold
        QCOMPARE(test->alarms().back().kind, AlarmKind::OperatorHold);
        test->resume();
        QCOMPARE(test->step(), HybridTest::StepResult::Advanced);
        QCOMPARE(test->currentStep(), 2);
    }

    void builtinSpecimenHoldsAtTheNextStep() {
        auto test = buildHybridTest(m_cfg, {});
        QVERIFY(test->prepare());
        QCOMPARE(test->step(), HybridTest::StepResult::Advanced);
        test->emergencyHold("builtin");
        QCOMPARE(test->step(), HybridTest::StepResult::Held);
        QCOMPARE(test->currentStep(), 1);
        QVERIFY(test->alarms().back().message.find("emergency hold: builtin") != std::string::npos);
        test->resume();
        QCOMPARE(test->step(), HybridTest::StepResult::Advanced);
    }
};

QTEST_APPLESS_MAIN(TestEmergencyHold)
#include "TestEmergencyHold.moc"
