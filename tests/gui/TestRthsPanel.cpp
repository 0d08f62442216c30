// The console's RTHS view (gui/app/RthsPanel; docs/rths.md, "The console's RTHS view"), offscreen:
// a short fast-pace run of benchmark case 1's partition on a 2 Hz sine ground motion at 1024 Hz
// (written by the test, no shared data) fills the synchronization plot with every sample, the
// delay / amplitude plot with one estimate every 0.1 s once the 1 s window is full, and a
// threshold set low raises its alarm in the alarm list; Hold and Emergency hold hold the running
// loop; a stroke limit the run exceeds holds it with the channel named in the panel and a
// critical alarm. As the monitor of a real `hsmu-controller --rths` (RthsLink, the protocol of
// `hsmu rths --controller`): every telemetry frame reaches the plot and the end's J1 equals the
// local runRths' bit for bit; Hold holds the controller's loop; the view says where the
// controller records (or that it does not).
// The record (docs/rths.md, "The console's RTHS view"): a run from the view writes every tick to
// record.h5 in its record folder, equal to `hsmu rths` of the same configuration tick for tick
// (bit for bit: one loop, one RthsRecordFeed, one writer), readable by `hsmu export`; the next
// run to record-2.h5 (nothing overwritten); a held run keeps every tick before the hold (equal
// to the local runRths' ticks) with the hold as its last row's critical alarm.
// Resume (docs/rths.md, "Hold and resume"): a fast run held by Hold and resumed by Resume ends
// as the unheld runRths (J1..J9 bit for bit), every sample on the plot once, its record every
// tick once (bit for bit) with the hold's alarm and the resume's note; a stroke-limit hold's
// Resume is refused with the channel named and the run stays held.
#include "../comms/ControllerProcess.h"
#include "CliTestSupport.h"
#include "core/record/RecordReader.h"
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

/// Every recorded column of rows 0 .. n-1 of a and b equal, bit for bit ("" when they are).
QString sameRows(const RecordData& a, const RecordData& b, int n)
{
    for (int k = 0; k < n; ++k) {
        const double x[] = {a.time(k), a.groundAcceleration(k), a.commanded(k, 0), a.actuatorCommanded(k, 0),
                            a.deformation(k, 0), a.force(k, 0), a.actuatorMeasured(k, 0)};
        const double y[] = {b.time(k), b.groundAcceleration(k), b.commanded(k, 0), b.actuatorCommanded(k, 0),
                            b.deformation(k, 0), b.force(k, 0), b.actuatorMeasured(k, 0)};
        for (int c = 0; c < 7; ++c)
            if (x[c] != y[c])
                return QStringLiteral("tick %1 column %2: %3 vs %4").arg(k).arg(c).arg(x[c], 0, 'g', 17).arg(y[c], 0, 'g', 17);
        for (int c = 0; c < a.u.cols(); ++c)
            if (a.u(k, c) != b.u(k, c))
                return QStringLiteral("tick %1 u %2").arg(k).arg(c);
        if (a.steps[std::size_t(k)] != b.steps[std::size_t(k)])
            return QStringLiteral("tick %1 step").arg(k);
    }
    return {};
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
        rths::RthsSettings s = cfg.settings;
        rths::fitToNominalLoop(s);
        const rths::RthsRun whole = rths::runRths(cfg.partition(), motionOf(cfg), s); // the 60 s, unheld
        for (const bool emergency : {false, true}) {
            AlarmList alarms;
            RthsPanel panel(&alarms);
            panel.setRecordFolder(dir.path() + (emergency ? QStringLiteral("/emergency") : QStringLiteral("/hold")));
            QSignalSpy criteria(panel.session(), &RthsSession::finished);
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
            // The record keeps every tick before the hold, the hold as the last row's alarm.
            const long ticks = criteria.at(0).at(2).value<long>();
            QVERIFY2(ticks > 0 && ticks < long(whole.time.size()), qPrintable(QString::number(ticks)));
            const RecordReader reader(panel.session()->recordPath().toStdString());
            const RecordData& d = reader.data();
            QCOMPARE(long(d.rows()), ticks);
            QVERIFY(panel.recordText().contains(QStringLiteral("Recorded %1 ticks").arg(ticks)));
            for (int k = 0; k < d.rows(); ++k) {
                const auto i = std::size_t(k);
                QVERIFY2(d.time(k) == whole.time[i] && d.commanded(k, 0) == whole.desired[i] &&
                             d.actuatorCommanded(k, 0) == whole.command[i] && d.deformation(k, 0) == whole.measured[i] &&
                             d.force(k, 0) == whole.force[i] && d.u(k, 0) == whole.hybrid(k, 0),
                         qPrintable(QStringLiteral("tick %1").arg(k)));
            }
            QCOMPARE(d.alarms.size(), std::size_t(1));
            QCOMPARE(d.alarms.front().kind, AlarmKind::OperatorHold);
            QCOMPARE(d.alarms.front().severity, AlarmSeverity::Critical);
            QCOMPARE(d.alarms.front().step, d.rows() - 1);
            QCOMPARE(QString::fromStdString(d.alarms.front().message), hold);
        }
    }

    void aRunFromTheViewRecordsWhatHsmuRthsRecords()
    {
        QTemporaryDir dir;
        const RthsConfig cfg = sineConfig(dir.path(), 3.0);
        const QString folder = dir.path() + QStringLiteral("/console/rths");
        AlarmList alarms;
        RthsPanel panel(&alarms);
        panel.setRecordFolder(folder);
        QSignalSpy ended(&panel, &RthsPanel::runFinished);
        QVERIFY(panel.startRun(cfg, motionOf(cfg), RthsSession::Pace::Fast, 0.0));
        const QString first = panel.session()->recordPath();
        QCOMPARE(first, folder + QStringLiteral("/record.h5"));
        QVERIFY(panel.recordText().contains(first));
        QVERIFY(ended.wait(60000));
        QCOMPARE(ended.at(0).at(0).toString(), QString());
        QVERIFY2(panel.recordText().contains(QStringLiteral("Recorded 3073 ticks to ") + first), qPrintable(panel.recordText()));

        const clitest::Result r = clitest::hsmu({QStringLiteral("rths"), dir.path() + QStringLiteral("/rths.json"),
                                                 QStringLiteral("--out"), dir.path() + QStringLiteral("/cli")});
        QVERIFY2(r.exitCode == 0, qPrintable(clitest::report(r)));
        {   // one reader of a file at a time in a process: HDF5 refuses a second open
            const RecordReader console(first.toStdString());
            const RecordReader cli((dir.path() + QStringLiteral("/cli/record.h5")).toStdString());
            QCOMPARE(console.rows(), 3073);
            QCOMPARE(cli.rows(), 3073);
            QCOMPARE(console.data().meta.configuration, cli.data().meta.configuration);
            QCOMPARE(console.data().meta.dt, cli.data().meta.dt);
            QCOMPARE(console.data().layout.dofNames, cli.data().layout.dofNames);
            const QString diff = sameRows(console.data(), cli.data(), 3073);
            QVERIFY2(diff.isEmpty(), qPrintable(diff));
            QVERIFY(console.data().alarms.empty());
        }
        // `hsmu export` reads it.
        const clitest::Result e = clitest::hsmu({QStringLiteral("export"), first, QStringLiteral("--csv"),
                                                 dir.path() + QStringLiteral("/csv")});
        QVERIFY2(e.exitCode == 0, qPrintable(clitest::report(e)));
        QCOMPARE(clitest::readLines(dir.path() + QStringLiteral("/csv/elements.csv")).size(), 3074); // header + rows

        // The next run: record-2.h5, the first one untouched.
        QVERIFY(panel.startRun(cfg, motionOf(cfg), RthsSession::Pace::Fast, 1.0));
        QCOMPARE(panel.session()->recordPath(), folder + QStringLiteral("/record-2.h5"));
        QVERIFY(ended.wait(60000));
        QCOMPARE(RecordReader(first.toStdString()).rows(), 3073);
        QCOMPARE(RecordReader((folder + QStringLiteral("/record-2.h5")).toStdString()).rows(), 1025);

        // No folder: not recorded, and said so.
        panel.setRecordFolder(QString());
        QVERIFY(panel.startRun(cfg, motionOf(cfg), RthsSession::Pace::Fast, 0.5));
        QVERIFY(panel.session()->recordPath().isEmpty());
        QVERIFY(panel.recordText().contains(QStringLiteral("Not recorded")));
        QVERIFY(ended.wait(60000));
        QVERIFY(!QFile::exists(folder + QStringLiteral("/record-3.h5")));
    }

    void resumeGoesOnFromTheHeldTick()
    {
        QTemporaryDir dir;
        const RthsConfig cfg = sineConfig(dir.path(), 10.0);
        rths::RthsSettings s = cfg.settings;
        rths::fitToNominalLoop(s);
        const rths::RthsRun whole = rths::runRths(cfg.partition(), motionOf(cfg), s);
        AlarmList alarms;
        RthsPanel panel(&alarms);
        panel.setRecordFolder(dir.path() + QStringLiteral("/resume"));
        QSignalSpy criteria(panel.session(), &RthsSession::finished);
        QSignalSpy batches(panel.session(), &RthsSession::samples);
        QSignalSpy ended(&panel, &RthsPanel::runFinished);
        auto* resume = panel.findChild<QPushButton*>(QStringLiteral("rthsResume"));
        QVERIFY(!resume->isEnabled());
        QVERIFY(panel.startRun(cfg, motionOf(cfg), RthsSession::Pace::Fast, 0.0));
        QVERIFY(batches.wait(60000));
        QTest::mouseClick(panel.findChild<QPushButton*>(QStringLiteral("rthsHold")), Qt::LeftButton);
        QVERIFY(ended.wait(60000));
        QVERIFY2(ended.at(0).at(0).toString().startsWith(QStringLiteral("console hold")), qPrintable(ended.at(0).at(0).toString()));
        const long held = criteria.at(0).at(2).value<long>();
        QVERIFY(held > 0 && held < long(whole.time.size()));
        QVERIFY(resume->isEnabled());
        QTest::mouseClick(resume, Qt::LeftButton);
        QVERIFY(panel.running());
        QVERIFY(!resume->isEnabled());
        QVERIFY(ended.wait(60000));
        QCOMPARE(ended.at(1).at(0).toString(), QString());
        QCOMPARE(criteria.at(1).at(2).value<long>(), long(whole.time.size())); // 10241
        QCOMPARE(panel.synchronizationPlot()->points(), int(whole.time.size()));
        QVERIFY(!resume->isEnabled());
        const RecordReader reader(panel.session()->recordPath().toStdString());
        const RecordData& d = reader.data();
        QCOMPARE(d.rows(), int(whole.time.size()));
        for (int k = 0; k < d.rows(); ++k) {
            const auto i = std::size_t(k);
            QVERIFY2(d.steps[i] == k && d.time(k) == whole.time[i] && d.deformation(k, 0) == whole.measured[i] &&
                         d.actuatorCommanded(k, 0) == whole.command[i] && d.u(k, 1) == whole.hybrid(k, 1),
                     qPrintable(QStringLiteral("tick %1").arg(k)));
        }
        QCOMPARE(d.alarms.size(), std::size_t(1));
        QCOMPARE(d.alarms.front().kind, AlarmKind::OperatorHold);
        QCOMPARE(d.alarms.front().step, int(held - 1));
        QCOMPARE(d.notes.size(), std::size_t(1));
        QCOMPARE(d.notes.front().step, int(held));
        QVERIFY(QString::fromStdString(d.notes.front().text).startsWith(QStringLiteral("resumed before tick %1").arg(held)));
        const rths::BenchmarkCriteria c = criteria.at(1).at(1).value<rths::BenchmarkCriteria>();
        const auto& j = c.j;
        for (int i = 0; i < 9; ++i)
            QVERIFY2(j[std::size_t(i)] == whole.criteria.j[std::size_t(i)], qPrintable(QStringLiteral("J%1: %2 vs %3").arg(i + 1).arg(j[std::size_t(i)], 0, 'g', 17).arg(whole.criteria.j[std::size_t(i)], 0, 'g', 17)));
    }

    void aLimitHoldNamesTheChannelValueAndTick()
    {
        // A 0.1 mm stroke limit: the loop holds at the first tick the command passes it.
        QTemporaryDir dir;
        const RthsConfig cfg = sineConfig(dir.path(), 4.0, QStringLiteral(R"("limits": {"stroke": 1e-4},)"));
        AlarmList alarms;
        RthsPanel panel(&alarms);
        panel.setRecordFolder(dir.path());
        QSignalSpy ended(&panel, &RthsPanel::runFinished);
        QVERIFY(panel.startRun(cfg, motionOf(cfg), RthsSession::Pace::Fast, 0.0));
        QVERIFY(ended.wait(60000));
        const QString hold = ended.at(0).at(0).toString();
        QVERIFY2(hold.contains(QStringLiteral("stroke")) && hold.contains(QStringLiteral("tick")), qPrintable(hold));
        const RecordReader reader((dir.path() + QStringLiteral("/record.h5")).toStdString());
        QCOMPARE(reader.data().alarms.size(), std::size_t(1));
        QCOMPARE(reader.data().alarms.front().kind, AlarmKind::LimitExceeded);
        QCOMPARE(reader.data().alarms.front().step, reader.rows() - 1);
        QVERIFY(panel.statusText().contains(hold));
        QCOMPARE(rows(alarms, AlarmKind::LimitExceeded, AlarmSeverity::Critical), 1);
        // Resume does not go on into the breach: refused, the channel named, still held.
        auto* resume = panel.findChild<QPushButton*>(QStringLiteral("rthsResume"));
        QVERIFY(resume->isEnabled());
        QTest::mouseClick(resume, Qt::LeftButton);
        QVERIFY(!panel.running());
        QVERIFY2(panel.statusText().startsWith(QStringLiteral("Not resumed: resume refused: ")) &&
                     panel.statusText().contains(QStringLiteral("stroke")),
                 qPrintable(panel.statusText()));
        QVERIFY(resume->isEnabled());
        QCOMPARE(ended.size(), 1);
    }

    void monitorsTheControllersLoop()
    {
        QTemporaryDir dir;
        const RthsConfig cfg = sineConfig(dir.path(), 3.0);
        const QString path = dir.path() + QStringLiteral("/rths.json");
        const QString controllerRecords = dir.path() + QStringLiteral("/on-the-controller");
        ControllerProcess ctl({QStringLiteral("--rths"), path, QStringLiteral("--pace"), QStringLiteral("fast"),
                               QStringLiteral("--record"), controllerRecords});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        AlarmList alarms;
        RthsPanel panel(&alarms);
        panel.setRecordFolder(dir.path() + QStringLiteral("/console")); // not used for a controller's run
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
        // Where the controller records, from its hello-ack; the console writes nothing.
        QVERIFY2(panel.recordText().contains(QStringLiteral("recording each run in ") + controllerRecords),
                 qPrintable(panel.recordText()));
        QVERIFY(!QFile::exists(dir.path() + QStringLiteral("/console")));
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
        QVERIFY2(panel.recordText().contains(QStringLiteral("no record on the controller")), qPrintable(panel.recordText()));
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
