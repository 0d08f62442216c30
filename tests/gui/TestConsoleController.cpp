// The console's controller object drives a real HybridTest on its worker thread: single
// steps, the operator's updating decisions (approve / reject a pending update, bounds and
// locks effective on the next step), an emergency hold from a pause, and a worker that keeps
// stepping while the GUI thread is blocked.

#include "gui/PresetLibrary.h"
#include "gui/app/TestController.h"

#include <QSignalSpy>
#include <QThread>
#include <QtTest>

#include <cmath>

using namespace hsmu;
using namespace hsmu::gui;

namespace {

TestConfig preset(const QString& id, double duration) {
    TestConfig cfg = PresetLibrary::load(id);
    cfg.analysis.duration = duration;
    return cfg;
}

/// The paper's condition 3 (UKF on Element 1, Element 2 its updated twin).
TestConfig updatingPreset(ReporterPolicy policy) {
    TestConfig cfg = preset(QStringLiteral("paper-condition-3"), 20.0);
    cfg.updating.policy = policy;
    cfg.updating.approval = "manual";
    return cfg;
}

struct Rows {
    std::vector<StepRecord> rows;
    void attach(TestController& c) {
        QObject::connect(&c, &TestController::recordsArrived, &c,
                         [this](const std::vector<StepRecord>& r) {
                             rows.insert(rows.end(), r.begin(), r.end());
                         });
    }
};

/// Run at `speed` until at least `steps` rows arrived, then pause.
void runThenPause(TestController& c, const Rows& rx, std::size_t steps) {
    c.start();
    QTRY_VERIFY_WITH_TIMEOUT(rx.rows.size() >= steps, 20000);
    c.pause();
    QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Paused, 5000);
}

double valueOf(const UpdatingSnapshot& s, const std::string& name) {
    const ParameterState* p = s.parameter(name);
    return p ? p->value : std::nan("");
}

} // namespace

class TestConsoleController : public QObject {
    Q_OBJECT
private slots:
    void singleStepAdvancesExactlyOneStep() {
        TestController c;
        Rows rx;
        rx.attach(c);
        c.setSpeed(5.0);
        c.load(preset(QStringLiteral("sdof-bouc-wen"), 4.0));
        // From a loaded test: prepared (step 0) plus one step, then paused.
        c.singleStep();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Paused, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(rx.rows.size(), std::size_t(2), 5000);
        for (int i = 0; i < 3; ++i)
            c.singleStep();
        QTRY_COMPARE_WITH_TIMEOUT(rx.rows.size(), std::size_t(5), 5000);
        QCOMPARE(rx.rows.back().step, 4);
        QCOMPARE(c.recordsCommitted(), qint64(5));
        QCOMPARE(c.state(), RunState::Paused);
        // Resume runs on to the end from where the steps left it.
        c.resume();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Finished, 20000);
        QCOMPARE(rx.rows.size(), std::size_t(401));
        for (std::size_t i = 0; i < rx.rows.size(); ++i)
            QCOMPARE(rx.rows[i].step, int(i));
    }

    void approvingChangesTheTwinAndRejectingDoesNot() {
        TestController c;
        Rows rx;
        rx.attach(c);
        c.setSpeed(5.0);
        TestConfig cfg = updatingPreset(ReporterPolicy::OnApproval);
        cfg.updating.proposalInterval = 0.2; // 20 steps
        c.load(cfg);
        runThenPause(c, rx, 100);
        QTRY_VERIFY_WITH_TIMEOUT(c.updating().step == rx.rows.back().step, 5000);
        UpdatingSnapshot s = c.updating();
        QVERIFY(s.enabled);
        QCOMPARE(s.policy, ReporterPolicy::OnApproval);
        QCOMPARE(s.proposalInterval, 0.2);
        // One proposal for the one target, renewed: less than one interval old.
        QCOMPARE(s.pending.size(), std::size_t(1));
        QVERIFY2(s.pending.front().step > s.step - 20,
                 qPrintable(QStringLiteral("made at step %1, now %2")
                                .arg(s.pending.front().step).arg(s.step)));
        QVERIFY(!s.stale(s.pending.front()));
        QVERIFY(std::isfinite(s.pending.front().fitError)); // the fit error when proposed
        QCOMPARE(s.latest.at("Element 2").size(), s.pending.front().proposed.size());
        QCOMPARE(s.appliedUpdates, 0);
        const ParameterValues initial = s.targets.at("Element 2");

        // Reject it: the twin keeps its parameters.
        c.rejectUpdate(s.pending.front().id);
        QTRY_VERIFY_WITH_TIMEOUT(c.updating().pending.empty(), 5000);
        QVERIFY(c.updating().targets.at("Element 2") == initial);
        QCOMPARE(c.updating().appliedUpdates, 0);

        // The next one comes after one interval of running; approving applies exactly it.
        c.resume();
        QTRY_VERIFY_WITH_TIMEOUT(!c.updating().pending.empty(), 10000);
        c.pause();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Paused, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(c.updating().step == rx.rows.back().step, 5000);
        const UpdateProposal proposal = c.updating().pending.front();
        for (std::size_t j = 0; j < proposal.parameters.size(); ++j)
            QCOMPARE(proposal.current[j], initial.at(proposal.parameters.name(j)));
        c.approveUpdate(proposal.id);
        QTRY_COMPARE_WITH_TIMEOUT(c.updating().appliedUpdates, 1, 5000);
        const ParameterValues applied = c.updating().targets.at("Element 2");
        QCOMPARE(applied.size(), proposal.proposed.size());
        bool changed = false;
        for (std::size_t j = 0; j < proposal.parameters.size(); ++j) {
            const std::string& name = proposal.parameters.name(j);
            const double v = proposal.proposed[j];
            QCOMPARE(applied.at(name), v); // exactly the proposed value
            changed |= std::abs(v - initial.at(name)) > 1e-9 * std::abs(initial.at(name));
        }
        QVERIFY2(changed, "the identified values should differ from the wrong initial ones");
        QVERIFY(c.updating().pending.empty());
    }

    void editedBoundTakesEffectOnTheNextStep() {
        TestController c;
        Rows rx;
        rx.attach(c);
        c.setSpeed(5.0);
        c.load(updatingPreset(ReporterPolicy::EveryStep));
        runThenPause(c, rx, 100);
        QTRY_VERIFY_WITH_TIMEOUT(c.updating().step == rx.rows.back().step, 5000);
        const double k0 = valueOf(c.updating(), "k0");
        QVERIFY(std::isfinite(k0));
        // A band that excludes the current estimate, inside Table III's [0.7, 1.4].
        const double lower = k0 < 1.2 ? 1.3 : 0.75;
        const double upper = k0 < 1.2 ? 1.4 : 0.85;
        c.setParameterBounds(QStringLiteral("k0"), lower, upper);
        QTRY_COMPARE_WITH_TIMEOUT(c.updating().parameter("k0")->bounds.lower, lower, 5000);
        QCOMPARE(c.updating().parameter("k0")->bounds.upper, upper); // read back from the UKF
        QCOMPARE(valueOf(c.updating(), "k0"), k0);                   // not before the next step

        const std::size_t rowsBefore = rx.rows.size();
        c.singleStep();
        QTRY_COMPARE_WITH_TIMEOUT(rx.rows.size(), rowsBefore + 1, 5000);
        const StepRecord& next = rx.rows.back();
        QVERIFY(next.hasUpdating);
        const double k0Next = next.updating.parameters.at(0); // k0 is the first identified
        QVERIFY2(k0Next >= lower - 1e-12 && k0Next <= upper + 1e-12,
                 qPrintable(
                     QStringLiteral("k0 = %1 outside [%2, %3]").arg(k0Next).arg(lower).arg(upper)));

        // An inadmissible bound is refused with a reason and changes nothing.
        QSignalSpy refused(&c, &TestController::commandRefused);
        c.setParameterBounds(QStringLiteral("k0"), 2.0, 1.0);
        QTRY_COMPARE_WITH_TIMEOUT(refused.count(), 1, 5000);
        QVERIFY(refused.at(0).at(0).toString().contains(QStringLiteral("k0")));
        QCOMPARE(c.updating().parameter("k0")->bounds.lower, lower);
    }

    void lockedParameterStaysPut() {
        TestController c;
        Rows rx;
        rx.attach(c);
        c.setSpeed(5.0);
        c.load(updatingPreset(ReporterPolicy::EveryStep));
        runThenPause(c, rx, 50);
        QVERIFY(c.updating().canLock);
        c.setParameterLocked(QStringLiteral("alpha"), true);
        QTRY_VERIFY_WITH_TIMEOUT(c.updating().parameter("alpha")->locked, 5000);
        const double alpha = valueOf(c.updating(), "alpha");
        const std::size_t at = rx.rows.size();
        c.resume();
        QTRY_VERIFY_WITH_TIMEOUT(rx.rows.size() >= at + 50, 20000);
        c.pause();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Paused, 5000);
        for (std::size_t i = at; i < rx.rows.size(); ++i) {
            QCOMPARE(rx.rows[i].updating.parameters.at(1), alpha); // alpha: second identified
            QCOMPARE(rx.rows[i].updating.stddev.at(1), 0.0);
        }
    }

    void workerKeepsSteppingWhileTheGuiThreadIsBusy() {
        TestController c;
        Rows rx;
        rx.attach(c);
        c.setSpeed(1.0); // real time: ~100 steps/s, the test lasts 20 s
        c.load(preset(QStringLiteral("sdof-bouc-wen"), 20.0));
        c.start();
        QTRY_VERIFY_WITH_TIMEOUT(rx.rows.size() >= 5, 10000);
        const qint64 committed = c.recordsCommitted();
        const qint64 delivered = c.recordsDelivered();
        QThread::msleep(600); // the GUI thread does nothing else: no event is processed
        const qint64 committedAfter = c.recordsCommitted();
        QCOMPARE(c.recordsDelivered(), delivered);
        QVERIFY2(committedAfter > committed + 10,
                 qPrintable(QStringLiteral("%1 -> %2").arg(committed).arg(committedAfter)));
        // Once the GUI is free again, every committed row arrives.
        QTRY_VERIFY_WITH_TIMEOUT(c.recordsDelivered() >= committedAfter, 5000);
        c.stop();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Stopped, 5000);
    }

    void emergencyHoldFromAPauseReachesASafeHold() {
        TestController c;
        Rows rx;
        rx.attach(c);
        std::vector<Alarm> alarms;
        connect(&c, &TestController::alarmRaised, this,
                [&alarms](const Alarm& a) { alarms.push_back(a); });
        c.setSpeed(5.0);
        c.load(preset(QStringLiteral("sdof-bouc-wen"), 4.0));
        runThenPause(c, rx, 20);
        c.emergencyHold();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Holding, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(!alarms.empty(), 5000);
        QCOMPARE(alarms.back().kind, AlarmKind::OperatorHold);
        QCOMPARE(alarms.back().severity, AlarmSeverity::Critical);
        const std::size_t atHold = rx.rows.size();
        QCOMPARE(c.recordsCommitted(), qint64(atHold));
        c.singleStep(); // a hold is left only by resume
        c.start();
        QTest::qWait(200);
        QCOMPARE(c.state(), RunState::Holding);
        QCOMPARE(c.recordsCommitted(), qint64(atHold));
        c.resume();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Finished, 20000);
        QCOMPARE(rx.rows.size(), std::size_t(401));
    }

    void preflightReportsStabilityAndLimits() {
        TestController c;
        QSignalSpy ready(&c, &TestController::preflightReady);
        c.load(preset(QStringLiteral("paper-condition-3"), 2.0));
        c.prepare();
        QTRY_COMPARE_WITH_TIMEOUT(ready.count(), 1, 5000);
        QVERIFY(c.preflight().has_value());
        const PreflightReport& r = *c.preflight();
        QCOMPARE(r.dt, 0.01);
        QCOMPARE(r.totalSteps, 200);
        // Explicit Newmark: omega_max dt against the limit 2 (docs/method.md, Hybrid
        // simulation).
        QCOMPARE(r.stability.limit, 2.0);
        QVERIFY(r.stability.stable);
        QVERIFY(std::abs(r.stability.omegaDt - r.stability.omegaMax * r.dt) < 1e-12);
        QVERIFY(r.startable());
        QCOMPARE(r.specimens.size(), std::size_t(1));
        QCOMPARE(r.specimens[0].element, std::string("Element 1"));
        const ElementSpec* spec = nullptr;
        for (const ElementSpec& e : c.config().elements)
            if (e.name == "Element 1")
                spec = &e;
        QVERIFY(spec);
        QCOMPARE(r.specimens[0].limits.maxDeformation, spec->limits.maxDeformation);
        QCOMPARE(r.specimens[0].limits.maxForce, spec->limits.maxForce);
        QCOMPARE(r.specimens[0].measuredDeformation, 0.0); // at rest before the first step
        QCOMPARE(c.state(), RunState::Ready);              // nothing moves before the confirmation
        QCOMPARE(c.recordsCommitted(), qint64(1));         // only the initial state
    }
};

QTEST_MAIN(TestConsoleController)
#include "TestConsoleController.moc"
