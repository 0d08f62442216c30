// The twins' offsets in the console (docs/console.md, "Offsets for the twins"): paper-condition-3
// with a virtual load cell biased by 3 kN m and updating.offsets auto, policy every step. The
// offsets appear as their own item of the pending-updates panel, with values, units and 95 %
// intervals; the every-step policy does not apply them; Approve offsets does, between steps,
// and the decision is an operator event in the event list and the record's /notes.

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
#include <QtTest>

#include <nlohmann/json.hpp>

#include <fstream>

using namespace hsmu;
using namespace hsmu::gui;

class TestOffsetApprovalGui : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        ConsoleSettings::setControllerAddress(QString());
    }

    void offsetsAreShownAndAppliedOnlyByTheOperator() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        nlohmann::json j;
        {
            std::ifstream in(std::string(HSMU_SOURCE_DIR) +
                             "/resources/presets/paper-condition-3.json");
            j = nlohmann::json::parse(in);
        }
        for (auto& e : j["structure"]["elements"])
            if (e["name"] == "Element 1")
                e["specimen"]["material"]["forceOffset"] = 3.0; // kN m: the load cell's bias
        j["updating"]["offsets"] = "auto";
        j["analysis"]["duration"] = 9.0;
        const QString config = dir.filePath(QStringLiteral("offsets.json"));
        std::ofstream(config.toStdString()) << j.dump(2);

        ConsoleSettings::setRecordDirectory(dir.filePath(QStringLiteral("runs")));
        MainWindow window;
        window.setConfirmBeforeStart(false);
        window.setSpeed(1.0); // 100 steps/s: the offsets come at step 450
        window.resize(1280, 720);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QVERIFY(window.loadConfiguration(config));
        TestController& c = window.controller();
        auto* panel = window.findChild<PendingUpdatesPanel*>();
        QVERIFY(panel);
        QVERIFY(!panel->offsetsBox()->isVisibleTo(panel)); // nothing pending before the run
        window.startTest();
        QTRY_VERIFY_WITH_TIMEOUT(panel->offsetsBox()->isVisibleTo(panel) ||
                                     c.state() == RunState::Finished,
                                 60000);
        QVERIFY2(panel->offsetsBox()->isVisibleTo(panel), "no offsets were offered");
        const QString text = panel->offsetsText()->text();
        qInfo("%s", qPrintable(text));
        // A look at the item (HSMU_TEST_SCREENSHOT=FILE.png, e.g. under xvfb-run).
        if (const QString shot = qEnvironmentVariable("HSMU_TEST_SCREENSHOT"); !shot.isEmpty())
            window.grab().save(shot);
        for (const char* part : {"Offsets #1", "u0 = ", " rad", "F0 = ", " kN m", "(95 %)"})
            QVERIFY2(text.contains(QLatin1String(part)), part);
        QVERIFY(panel->offsetsText()->toolTip().contains(QStringLiteral("only if you approve")));
        // Every step's policy applied updates meanwhile, not the offsets: the event list has no
        // offsets decision yet.
        auto* alarms = window.findChild<AlarmList*>();
        QCOMPARE(alarms->findItems(QStringLiteral("offsets #1"), Qt::MatchContains,
                                   AlarmList::Message).size(), 0);
        // The approval, between two steps (the run goes on).
        auto* approve = panel->findChild<QPushButton*>(QStringLiteral("approveOffsets"));
        QVERIFY(approve && approve->isEnabled());
        QTest::mouseClick(approve, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!panel->offsetsBox()->isVisibleTo(panel), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(alarms->findItems(QStringLiteral("offsets #1 approved"),
                                                   Qt::MatchContains, AlarmList::Message)
                                         .size() == 1,
                                 10000);
        QTRY_COMPARE_WITH_TIMEOUT(c.state(), RunState::Finished, 60000);

        const RecordData data = RecordReader(c.recordPath().toStdString()).data();
        int events = 0;
        for (const RecordNote& n : data.notes)
            if (n.text.find("action=approve-offsets") != std::string::npos) {
                ++events;
                QVERIFY2(n.text.find("old=#1 Element 2") != std::string::npos, n.text.c_str());
                QVERIFY2(n.text.find(" kN m (sd ") != std::string::npos, n.text.c_str());
            }
        QCOMPARE(events, 1);
        ConsoleSettings::setRecordDirectory(QString());
    }
};

QTEST_MAIN(TestOffsetApprovalGui)
#include "TestOffsetApproval.moc"
