// Issue 25 item 2: the approval policy at 100 steps/s on paper-condition-3 (dt = 0.01 s, real
// time). It queued a proposal per step, the queue was full after a second and only the oldest
// could be approved: approving #1 at step 1421 set the twin's k0 to 1.3 while the estimate was
// 0.998. Now one proposal per target is renewed every proposal interval and supersedes the
// one before; the operator clicks Approve on what the panel shows, several times during the
// run, and every approval the record holds applied an estimate made less than one proposal
// interval before the approval (the live estimate then, within that interval); an approval
// that came too late is refused, naming the proposal that replaced it.

#include "core/record/RecordReader.h"
#include "gui/app/AlarmList.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/MainWindow.h"
#include "gui/app/PendingUpdatesPanel.h"
#include "gui/app/TestController.h"

#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

using namespace hsmu;
using namespace hsmu::gui;

class TestApprovalAtSpeed : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        ConsoleSettings::setControllerAddress(QString());
    }

    void everyApprovalAppliesAnEstimateWithinOneInterval() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        nlohmann::json j;
        {
            std::ifstream in(std::string(HSMU_SOURCE_DIR) +
                             "/resources/presets/paper-condition-3.json");
            j = nlohmann::json::parse(in);
        }
        j["updating"]["reporter"]["policy"] = "onApproval";
        j["analysis"]["duration"] = 18.0;
        const QString config = dir.filePath(QStringLiteral("approval.json"));
        std::ofstream(config.toStdString()) << j.dump(2);

        ConsoleSettings::setRecordDirectory(dir.filePath(QStringLiteral("runs")));
        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(1.0); // dt = 0.01 s: 100 steps/s
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(config));
        TestController& c = window.controller();
        const double interval = c.config().updating.proposalInterval;
        QVERIFY(interval > 0.0);
        auto* pending = window.findChild<PendingUpdatesPanel*>();
        QVERIFY(pending);
        window.startTest();
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Running, 10000);

        // The operator approves what the panel shows, every 1.3 s of wall time; once, the
        // proposal is renewed between the press and the release of Approve (the race an
        // operator meets at speed): that approval is refused, naming its successor.
        int clicks = 0, mostShown = 0, raced = 0;
        QElapsedTimer rate;
        rate.start();
        while (c.state() == RunState::Running && clicks < 9) {
            QElapsedTimer wait;
            wait.start();
            while (wait.elapsed() < 1300 && c.state() == RunState::Running) {
                QTest::qWait(20);
                mostShown = std::max(mostShown, int(pending->shownProposals().size()));
            }
            const QList<int> shown = pending->shownProposals();
            if (shown.isEmpty())
                continue;
            auto* approve =
                pending->findChild<QPushButton*>(QStringLiteral("approve%1").arg(shown.front()));
            if (!approve || !approve->isEnabled())
                continue;
            if (clicks == 4 && raced == 0) {
                QTest::mousePress(approve, Qt::LeftButton);
                QTRY_VERIFY_WITH_TIMEOUT(pending->shownProposals().value(0) != shown.front(),
                                         5000); // renewed under the mouse
                QTest::mouseRelease(approve, Qt::LeftButton);
                ++raced;
            } else {
                QTest::mouseClick(approve, Qt::LeftButton);
            }
            ++clicks;
        }
        const double stepsPerSecond = c.updating().step / (rate.elapsed() * 1e-3);
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Finished, 60000);
        QVERIFY2(stepsPerSecond > 60.0, qPrintable(QString::number(stepsPerSecond)));
        QVERIFY2(clicks >= 6, qPrintable(QString::number(clicks)));
        QCOMPARE(mostShown, 1); // one target, one proposal: never a queue to work through

        const RecordData data = RecordReader(c.recordPath().toStdString()).data();
        int applied = 0, superseded = 0;
        for (const RecordedUpdate& e : data.updateEvents) {
            QVERIFY2(e.decision != "notQueued", "an offer was not queued");
            superseded += e.decision == "superseded";
            if (e.decision != "applied")
                continue;
            ++applied;
            // The step whose estimate it applied: the latest row <= the approval equal to it.
            int made = -1;
            for (int s = e.step; s >= 0 && made < 0; --s) {
                bool same = true;
                for (std::size_t k = 0; k < e.values.size() && same; ++k)
                    same = std::isnan(e.values[k]) ||
                           e.values[k] == data.parameters(s, Eigen::Index(k));
                if (same)
                    made = s;
            }
            QVERIFY2(made >= 0, "the applied values are no estimate of the run");
            const double age = e.time - data.time[made];
            QVERIFY2(age >= 0.0 && age < interval,
                     qPrintable(QStringLiteral("proposal #%1 approved at step %2 applied the "
                                               "estimate of step %3: %4 s old (interval %5 s)")
                                    .arg(e.proposal).arg(e.step).arg(made).arg(age)
                                    .arg(interval)));
            // ... so within what the estimator moved in one interval of the live estimate.
            const auto& names = data.layout.updating->parameters;
            const auto k0 = Eigen::Index(std::find(names.begin(), names.end(), "k0") - names.begin());
            double moved = 0.0;
            for (int s = made; s <= e.step; ++s)
                moved = std::max(moved, std::abs(data.parameters(s, k0) - data.parameters(e.step, k0)));
            QVERIFY(std::abs(e.values[std::size_t(k0)] - data.parameters(e.step, k0)) <= moved);
        }
        QVERIFY2(applied >= clicks / 2, qPrintable(QStringLiteral("%1 of %2 approvals applied")
                                                       .arg(applied).arg(clicks)));
        qInfo("%.0f steps/s, %d clicks: %d applied, %d refused as replaced; %d superseded",
              stepsPerSecond, clicks, applied,
              int(window.findChild<AlarmList*>()
                      ->findItems(QStringLiteral("replaced it"), Qt::MatchContains,
                                  AlarmList::Message)
                      .size()),
              superseded);
        QCOMPARE(raced, 1);
        QVERIFY2(superseded >= 1, qPrintable(QString::number(superseded))); // the raced one
        // Each click the worker refused names the proposal that replaced the one clicked.
        auto* alarms = window.findChild<AlarmList*>();
        const int refused =
            int(alarms->findItems(QStringLiteral("replaced it"), Qt::MatchContains,
                                  AlarmList::Message).size());
        QVERIFY2(refused >= 1 && applied + refused >= clicks - 1 && applied + refused <= clicks,
                 qPrintable(QStringLiteral("%1 applied, %2 refused as replaced, %3 clicks (the "
                                           "last may meet the end)")
                                .arg(applied).arg(refused).arg(clicks)));
        ConsoleSettings::setRecordDirectory(QString());
    }
};

QTEST_MAIN(TestApprovalAtSpeed)
#include "TestApprovalAtSpeed.moc"
