// TestController: the test runs on the worker thread; pause / resume / hold / stop act between
// steps; the GUI thread receives every committed step exactly once, in order (steps + 1 rows
// with the initial state). Operator notes reach the HDF5 record with the step they were added
// at, through the worker (read back with the real RecordReader).

#include "core/record/RecordReader.h"
#include "core/experiment/HybridTest.h"
#include "gui/PresetLibrary.h"
#include "gui/app/TestController.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

using namespace hsmu;
using namespace hsmu::gui;

namespace {

TestConfig preset(const QString& id, double duration) {
    TestConfig cfg = PresetLibrary::load(id);
    cfg.analysis.duration = duration;
    return cfg;
}

/// Collects what the GUI thread receives.
struct Receiver {
    std::vector<int> steps;
    std::vector<RunState> states;
    std::vector<Alarm> alarms;
    Qt::HANDLE guiThread = QThread::currentThreadId();
    bool wrongThread = false;

    void attach(TestController& c) {
        QObject::connect(&c, &TestController::recordsArrived, &c,
                         [this](const std::vector<StepRecord>& rows) {
                             wrongThread |= QThread::currentThreadId() != guiThread;
                             for (const StepRecord& r : rows)
                                 steps.push_back(r.step);
                         });
        QObject::connect(&c, &TestController::stateChanged, &c,
                         [this](RunState s, const QString&) { states.push_back(s); });
        QObject::connect(&c, &TestController::alarmRaised, &c,
                         [this](const Alarm& a) { alarms.push_back(a); });
    }
    bool contiguousFromZero() const {
        for (std::size_t i = 0; i < steps.size(); ++i)
            if (steps[i] != int(i))
                return false;
        return true;
    }
};

} // namespace

class HybridTestControllerTest : public QObject {
    Q_OBJECT
private slots:
    void runsToTheEndWithPauseAndResume() {
        TestController controller;
        Receiver rx;
        rx.attach(controller);
        controller.setSpeed(5.0); // 6 s of test in ~1.2 s: slow enough to pause mid-way
        controller.load(preset(QStringLiteral("paper-condition-3"), 6.0));
        QCOMPARE(controller.state(), RunState::Ready);
        controller.start();
        QTRY_VERIFY_WITH_TIMEOUT(rx.steps.size() >= 50, 10000);
        controller.pause();
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Paused, 5000);
        const std::size_t atPause = rx.steps.size();
        QVERIFY(atPause < 601);
        QTest::qWait(300); // paused: no step may arrive
        QCOMPARE(rx.steps.size(), atPause);
        QCOMPARE(controller.recordsDelivered(), qint64(atPause));
        controller.resume();
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Finished, 20000);
        QCOMPARE(rx.steps.size(), std::size_t(600 + 1)); // steps + the initial state
        QCOMPARE(controller.recordsDelivered(), qint64(601));
        QVERIFY(rx.contiguousFromZero());
        QVERIFY(!rx.wrongThread);
        const std::vector<RunState> expected{RunState::Ready, RunState::Running, RunState::Paused,
                                             RunState::Running, RunState::Finished};
        QVERIFY(rx.states == expected);
    }

    void emergencyHoldThenResumeLosesNoStep() {
        TestController controller;
        Receiver rx;
        rx.attach(controller);
        controller.setSpeed(10.0);
        controller.load(preset(QStringLiteral("sdof-bouc-wen"), 4.0));
        controller.start();
        QTRY_VERIFY_WITH_TIMEOUT(rx.steps.size() >= 20, 10000);
        controller.emergencyHold(QStringLiteral("test hold"));
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Holding, 5000);
        QVERIFY(!rx.alarms.empty());
        QCOMPARE(rx.alarms.back().kind, AlarmKind::OperatorHold);
        QCOMPARE(rx.alarms.back().severity, AlarmSeverity::Critical);
        const std::size_t atHold = rx.steps.size();
        QTest::qWait(200);
        QCOMPARE(rx.steps.size(), atHold);
        controller.resume();
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Finished, 20000);
        QCOMPARE(rx.steps.size(), std::size_t(401));
        QVERIFY(rx.contiguousFromZero());
    }

    void stopEndsTheTestAndReloadStartsAfresh() {
        TestController controller;
        Receiver rx;
        rx.attach(controller);
        controller.setSpeed(5.0);
        controller.load(preset(QStringLiteral("paper-condition-3"), 20.0));
        controller.start();
        QTRY_VERIFY_WITH_TIMEOUT(rx.steps.size() >= 10, 10000);
        controller.stop();
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Stopped, 5000);
        const std::size_t atStop = rx.steps.size();
        QTest::qWait(200);
        QCOMPARE(rx.steps.size(), atStop);
        QVERIFY(atStop < 2001);

        // A new test replaces the old one; as fast as possible it runs to its end.
        rx.steps.clear();
        controller.setSpeed(0.0);
        controller.load(preset(QStringLiteral("paper-condition-1"), 2.0));
        QCOMPARE(controller.recordsDelivered(), qint64(0));
        controller.start();
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Finished, 20000);
        QCOMPARE(rx.steps.size(), std::size_t(201));
        QVERIFY(rx.contiguousFromZero());
    }

    void unstableTestFailsWithTheReason() {
        TestController controller;
        QSignalSpy states(&controller, &TestController::stateChanged);
        TestConfig cfg = preset(QStringLiteral("paper-condition-3"), 2.0);
        cfg.analysis.dt = 0.5;
        controller.load(cfg);
        controller.start();
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Failed, 5000);
        const QString message = states.last().at(1).toString();
        QVERIFY2(message.contains(QStringLiteral("omega_max dt")), qPrintable(message));
    }

    void notesAreRecordedWithTheirStep() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        TestController controller;
        Receiver rx;
        rx.attach(controller);
        controller.setRecordDirectory(dir.path());
        controller.setSpeed(5.0);
        const TestConfig cfg = preset(QStringLiteral("paper-condition-3"), 3.0);
        controller.load(cfg);
        QVERIFY(!controller.recordPath().isEmpty());
        controller.start();
        QTRY_VERIFY_WITH_TIMEOUT(rx.steps.size() >= 30, 10000);
        controller.pause();
        // Paused: every committed row was delivered before the state change, so the worker's
        // current step is the last one received.
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Paused, 5000);
        const int pausedAt = rx.steps.back();
        QVERIFY(pausedAt > 0 && pausedAt < 300);
        controller.addNote(QStringLiteral("crack at the base, east side"));
        controller.addNote(QStringLiteral("   ")); // blank: ignored
        controller.resume();
        QTRY_VERIFY_WITH_TIMEOUT(rx.steps.size() >= std::size_t(pausedAt + 30), 10000);
        const int runningFrom = rx.steps.back();
        controller.addNote(QStringLiteral("second note, while running"));
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Finished, 20000);
        const QString path = controller.recordPath();
        controller.load(cfg); // the old worker finishes its record
        const RecordReader reader(path.toStdString());
        RecordData d = reader.data();
        QCOMPARE(d.rows(), 301);
        // The operator's actions are notes too (OperatorEvent): start, pause, resume.
        std::vector<RecordNote> events;
        std::erase_if(d.notes, [&events](const RecordNote& n) {
            const bool event = n.text.rfind("operator-event ", 0) == 0;
            if (event)
                events.push_back(n);
            return event;
        });
        QCOMPARE(int(events.size()), 3);
        QVERIFY(events[0].text.find("action=start;") != std::string::npos);
        QVERIFY(events[1].text.find("action=pause;") != std::string::npos);
        QVERIFY(events[2].text.find("action=resume;") != std::string::npos);
        QCOMPARE(events[2].step, pausedAt);
        QCOMPARE(int(d.notes.size()), 2);
        QCOMPARE(d.notes[0].step, pausedAt);
        QCOMPARE(d.notes[0].text, std::string("crack at the base, east side"));
        QVERIFY(std::abs(d.notes[0].time - pausedAt * cfg.analysis.dt) <= 1e-9);
        QCOMPARE(d.notes[1].text, std::string("second note, while running"));
        QVERIFY(d.notes[1].step >= runningFrom && d.notes[1].step <= 300);
        QVERIFY(std::abs(d.notes[1].time - d.notes[1].step * cfg.analysis.dt) <= 1e-9);
    }

    void noteWithoutARecordIsRefused() {
        TestController controller;
        controller.setRecordDirectory(QString());
        controller.load(preset(QStringLiteral("paper-condition-3"), 1.0));
        QSignalSpy refused(&controller, &TestController::commandRefused);
        controller.addNote(QStringLiteral("lost?"));
        QTRY_COMPARE_WITH_TIMEOUT(refused.count(), 1, 5000);
        QVERIFY(refused.at(0).at(0).toString().contains(QStringLiteral("not recorded")));
    }

    void badConfigurationThrowsOnLoad() {
        TestController controller;
        TestConfig cfg = preset(QStringLiteral("paper-condition-3"), 2.0);
        cfg.groundMotion.file = "/nonexistent/record.AT2";
        QVERIFY_THROWS_EXCEPTION(std::exception, controller.load(cfg));
        QVERIFY(!controller.hasTest());
        QCOMPARE(controller.state(), RunState::Idle);
    }
};

QTEST_MAIN(HybridTestControllerTest)
#include "TestHybridTestController.moc"
