// The console's RTHS view (gui/app/RthsPanel; docs/rths.md, "The console's RTHS view"), offscreen:
// a short fast-pace run of benchmark case 1's partition on a 2 Hz sine ground motion at 1024 Hz
// (written by the test, no shared data) fills the synchronization plot with every sample, the
// delay / amplitude plot with one estimate every 0.1 s once the 1 s window is full, and a
// threshold set low raises its alarm in the alarm list; Hold and Emergency hold hold the running
// loop; a stroke limit the run exceeds holds it with the channel named in the panel and a
// critical alarm. As the monitor of a real `hsmu-controller --rths` (RthsLink, the protocol of
// `hsmu rths --controller`): every telemetry frame reaches the plot and the end's J1 equals the
// local runRths' bit for bit; Hold holds the controller's loop.
#include "../comms/ControllerProcess.h"
#include "core/config/RthsConfig.h"
#include "core/rths/RthsBenchmark.h"
#include "gui/app/AlarmList.h"
#include "gui/app/RthsPanel.h"
#include "gui/plots/RthsPlots.h"

#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace hsmu;
using namespace hsmu::gui;

namespace {

/// A case-1 RTHS configuration at 1024 Hz over `seconds` of a 2 Hz sine (0.8 m/s^2); extra:
/// more members of the "rths" object (e.g. limits).
RthsConfig sineConfig(const QString& dir, double seconds, const QString& extra = {})
{
    const QString motion = dir + QStringLiteral("/sine.txt");
    QFile m(motion);
    m.open(QIODevice::WriteOnly | QIODevice::Text);
    QString text;
    for (int i = 0; i <= int(std::lround(seconds * 100)); ++i) {
        const double t = 0.01 * i;
        text += QStringLiteral("%1 %2\n").arg(t, 0, 'g', 17).arg(0.8 * std::sin(2 * M_PI * 2.0 * t), 0, 'g', 17);
    }
    m.write(text.toUtf8());
    m.close();
    const QString path = dir + QStringLiteral("/rths.json");
    QFile f(path);
    f.open(QIODevice::WriteOnly | QIODevice::Text);
    f.write(QStringLiteral(R"({"name": "sine on case 1", "rths": {"rate": 1024,
      "structure": {"benchmarkCase": 1, "specimenDof": 0},
      "sensors": {"noise": true, "seed": 3}, %2
      "holdAfterMisses": 0,
      "groundMotion": {"file": "%1", "scale": 1.0, "unit": "m/s^2"}}})").arg(motion, extra).toUtf8());
    f.close();
    return loadRthsConfig(path.toStdString());
}

GroundMotion motionOf(const RthsConfig& cfg)
{
    return loadRthsGroundMotion(cfg, std::string(), cfg.groundMotionScale);
}

/// Rows of the alarm list of this kind and severity (as the list shows them).
int rows(const AlarmList& list, AlarmKind kind, AlarmSeverity severity)
{
    int n = 0;
    for (int i = 0; i < list.topLevelItemCount(); ++i) {
        const QTreeWidgetItem* it = list.topLevelItem(i);
        n += it->text(AlarmList::Kind) == AlarmList::describe(kind) &&
             it->text(AlarmList::Severity) == AlarmList::describe(severity);
    }
    return n;
}

} // namespace

class TestRthsPanel : public QObject {
    Q_OBJECT
private slots:
    void aFastRunFillsThePlotsAndALowThresholdRaisesItsAlarm()
    {
        QTemporaryDir dir;
        const RthsConfig cfg = sineConfig(dir.path(), 4.0);
        AlarmList alarms;
        RthsPanel panel(&alarms);
        // The sample controller leaves ~4.6 ms of delay and ~10 % error: J1 over a 0.5 ms
        // warning (critical far above), J2 over a 1 % critical.
        panel.setLimits({0.5, 1000.0, 0.5, 1.0});
        QCOMPARE(panel.limits().j2Critical, 1.0);
        QSignalSpy ended(&panel, &RthsPanel::runFinished);
        QSignalSpy criteria(panel.session(), &RthsSession::finished);
        QVERIFY(panel.startRun(cfg, motionOf(cfg), RthsSession::Pace::Fast, 2.0));
        QVERIFY(panel.running());
        QVERIFY(ended.wait(60000));
        QCOMPARE(ended.at(0).at(0).toString(), QString());
        const long ticks = criteria.at(0).at(2).value<long>();
        QCOMPARE(ticks, 2049L); // t = 0 .. 2 s at 1024 Hz, both ends
        // Every tick is a sample at 1024 Hz (decimation 1): the synchronization plot has them all.
        QCOMPARE(panel.synchronizationPlot()->points(), int(ticks));
        // Estimates from sample 1023 (a full 1 s window) every 102 samples (0.1 s).
        QCOMPARE(panel.historyPlot()->points(), int((ticks - 1 - 1023) / 102 + 1));
        // The live window's delay against the whole run's J1 (M1 over 2 s, the same loop):
        // within 0.5 ms; its amplitude near 1 (the controller keeps the amplitude, within 5 %).
        const double j1 = criteria.at(0).at(1).value<rths::BenchmarkCriteria>().j[0];
        QVERIFY2(j1 > 2.0, qPrintable(QString::number(j1)));
        QVERIFY2(std::abs(panel.window().last().delay - j1) < 0.5,
                 qPrintable(QStringLiteral("%1 vs %2").arg(panel.window().last().delay).arg(j1)));
        QVERIFY(std::abs(panel.window().last().amplitudeError) < 5.0);
        // J1 past 0.5 ms: one warning; J2 past 1 %: one critical (straight past the warning).
        QCOMPARE(rows(alarms, AlarmKind::TrackingError, AlarmSeverity::Warning), 1);
        QCOMPARE(rows(alarms, AlarmKind::TrackingError, AlarmSeverity::Critical), 1);
        QVERIFY(alarms.rowsText(QLatin1Char('\t'), false).contains(QStringLiteral("over the critical threshold 1.00 %")));
        QVERIFY(panel.statusText().contains(QStringLiteral("2049 ticks")));
    }

    void holdAndEmergencyHoldHoldTheRunningLoop()
    {
        QTemporaryDir dir;
        const RthsConfig cfg = sineConfig(dir.path(), 60.0);
        for (const bool emergency : {false, true}) {
            AlarmList alarms;
            RthsPanel panel(&alarms);
            QSignalSpy batches(panel.session(), &RthsSession::samples);
            QSignalSpy ended(&panel, &RthsPanel::runFinished);
            QVERIFY(panel.startRun(cfg, motionOf(cfg), RthsSession::Pace::Fast, 0.0));
            QVERIFY(batches.wait(60000));
            auto* button = panel.findChild<QPushButton*>(emergency ? QStringLiteral("rthsEmergencyHold") : QStringLiteral("rthsHold"));
            QVERIFY(button->isEnabled());
            QTest::mouseClick(button, Qt::LeftButton);
            QVERIFY(ended.wait(60000));
            const QString hold = ended.at(0).at(0).toString();
            QVERIFY2(hold.startsWith(emergency ? QStringLiteral("emergency hold") : QStringLiteral("console hold")),
                     qPrintable(hold));
            QVERIFY(hold.contains(QStringLiteral("before tick")));
            // Held well before the 60 s record's end (the fast pace waits for the plots).
            QVERIFY(panel.synchronizationPlot()->points() < 60 * 1024);
            QCOMPARE(rows(alarms, AlarmKind::OperatorHold, emergency ? AlarmSeverity::Critical : AlarmSeverity::Warning), 1);
            QVERIFY(!panel.running());
            QVERIFY(!button->isEnabled());
        }
    }

    void aLimitHoldNamesTheChannelValueAndTick()
    {
        // A 0.1 mm stroke limit: the loop holds at the first tick the command passes it.
        QTemporaryDir dir;
        const RthsConfig cfg = sineConfig(dir.path(), 4.0, QStringLiteral(R"("limits": {"stroke": 1e-4},)"));
        AlarmList alarms;
        RthsPanel panel(&alarms);
        QSignalSpy ended(&panel, &RthsPanel::runFinished);
        QVERIFY(panel.startRun(cfg, motionOf(cfg), RthsSession::Pace::Fast, 0.0));
        QVERIFY(ended.wait(60000));
        const QString hold = ended.at(0).at(0).toString();
        QVERIFY2(hold.contains(QStringLiteral("stroke")) && hold.contains(QStringLiteral("tick")), qPrintable(hold));
        QVERIFY(panel.statusText().contains(hold));
        QCOMPARE(rows(alarms, AlarmKind::LimitExceeded, AlarmSeverity::Critical), 1);
    }

    void monitorsTheControllersLoop()
    {
        QTemporaryDir dir;
        const RthsConfig cfg = sineConfig(dir.path(), 3.0);
        const QString path = dir.path() + QStringLiteral("/rths.json");
        ControllerProcess ctl({QStringLiteral("--rths"), path, QStringLiteral("--pace"), QStringLiteral("fast")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        AlarmList alarms;
        RthsPanel panel(&alarms);
        QSignalSpy ended(&panel, &RthsPanel::runFinished);
        QSignalSpy criteria(panel.session(), &RthsSession::finished);
        QVERIFY(panel.startRemoteRun(cfg, QStringLiteral("127.0.0.1"), ctl.port(), QString(), 0.0));
        QVERIFY(ended.wait(60000));
        QCOMPARE(ended.at(0).at(0).toString(), QString());
        QCOMPARE(criteria.size(), 1);
        QCOMPARE(criteria.at(0).at(2).value<long>(), 3073L);
        // One frame per tick at 1024 Hz (decimation 1), none dropped: all on the plot.
        QCOMPARE(panel.synchronizationPlot()->points(), 3073);
        QVERIFY(panel.historyPlot()->points() > 0);
        rths::RthsSettings s = cfg.settings;
        rths::fitToNominalLoop(s);
        const rths::RthsRun local = rths::runRths(cfg.partition(), motionOf(cfg), s);
        QVERIFY(criteria.at(0).at(1).value<rths::BenchmarkCriteria>().j[0] == local.criteria.j[0]);
    }

    void holdsTheControllersLoop()
    {
        QTemporaryDir dir;
        const RthsConfig cfg = sineConfig(dir.path(), 30.0);
        const QString path = dir.path() + QStringLiteral("/rths.json");
        ControllerProcess ctl({QStringLiteral("--rths"), path, QStringLiteral("--pace"), QStringLiteral("realtime")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        AlarmList alarms;
        RthsPanel panel(&alarms);
        QSignalSpy batches(panel.session(), &RthsSession::samples);
        QSignalSpy ended(&panel, &RthsPanel::runFinished);
        QVERIFY(panel.startRemoteRun(cfg, QStringLiteral("127.0.0.1"), ctl.port(), QString(), 0.0));
        QVERIFY(batches.wait(60000));
        QTest::mouseClick(panel.findChild<QPushButton*>(QStringLiteral("rthsHold")), Qt::LeftButton);
        QVERIFY(ended.wait(60000));
        const QString hold = ended.at(0).at(0).toString();
        QVERIFY2(hold.startsWith(QStringLiteral("console hold (operator at the console) before tick")), qPrintable(hold));
        QVERIFY(panel.synchronizationPlot()->points() < 30 * 1024);
        QVERIFY(panel.statusText().contains(hold));
    }

    void badInputIsRefusedWithAReason()
    {
        AlarmList alarms;
        RthsPanel panel(&alarms);
        // warning above critical: not applied, the last usable thresholds stay.
        panel.setLimits({9.0, 5.0, 5.0, 10.0});
        QCOMPARE(panel.limits().j1Warning, 2.0);
        // A configuration file that does not exist: the reason in the panel and the list.
        panel.findChild<QComboBox*>(QStringLiteral("rthsSource"))->setCurrentIndex(4);
        panel.findChild<QLineEdit*>(QStringLiteral("rthsFile"))->setText(QStringLiteral("/nonexistent/rths.json"));
        panel.start();
        QVERIFY(!panel.running());
        QVERIFY(panel.statusText().contains(QStringLiteral("/nonexistent/rths.json")));
        QCOMPARE(alarms.topLevelItemCount(), 1);
    }
};

QTEST_MAIN(TestRthsPanel)
#include "TestRthsPanel.moc"
