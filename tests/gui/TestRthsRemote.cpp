// `hsmu rths CONFIG --controller tcp://HOST:PORT` (docs/rths.md, "The loop on the controller"):
// the console monitors the loop a real `hsmu-controller --rths CONFIG` runs. At the fast pace
// its summary.json has the local `hsmu rths CONFIG` run's J1..J9, peaks and ticks exactly (the
// same loop code; JSON carries doubles to their shortest round-trip text), and telemetry.csv
// one row every 8th tick (the default at 1024 Hz) with the local steps.csv's measured
// displacement (to steps.csv's 9 significant digits). SIGINT holds the controller's loop
// (real-time pace, a 30 s record, sent after the first progress line): exit 2, the hold named
// in the summary. `--update T:NAME=VALUE,...` sends the damper twin's new values when the
// telemetry reaches T: the one inside the box is applied before a tick the summary names, the
// one outside it is refused with the reason, and the run goes to its end; without
// --controller the option is refused.
#include "CliTestSupport.h"
#include "../comms/ControllerProcess.h"

#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>
#include <cmath>

namespace {

/// The configuration with an MR damper in the specimen and its twin on floor 2 (N, m).
QString writeDamperConfig(const QString& dir, const QString& motion) {
    const QString path = dir + QStringLiteral("/damper.json");
    QFile f(path);
    f.open(QIODevice::WriteOnly | QIODevice::Text);
    f.write(QStringLiteral(R"({"name": "damper on case 1", "rths": {"rate": 1024,
      "structure": {"benchmarkCase": 1, "specimenDof": 0},
      "compensation": {"type": "none", "lead": {"enabled": true}},
      "holdAfterMisses": 0,
      "damper": {"specimen": {"alpha": 72.1, "c0": 0.0236, "c1": 3.29, "beta": 2.41, "gamma": 8.96,
                              "n": 0.521, "uRef": 0.0054, "fRef": 320},
                 "twinDof": 1, "bounds": {"alpha": [0, 500]}},
      "groundMotion": {"file": "%1", "scale": 1.0, "unit": "m/s^2"}}})").arg(motion).toUtf8());
    return path;
}

QString writeConfig(const QString& dir, double seconds) {
    const QString motion = dir + QStringLiteral("/sine.txt");
    QFile m(motion);
    m.open(QIODevice::WriteOnly | QIODevice::Text);
    QString text;
    for (int i = 0; i <= int(std::lround(seconds * 100)); ++i) {
        const double t = 0.01 * i;
        text += QStringLiteral("%1 %2\n").arg(t, 0, 'g', 17).arg(0.8 * std::sin(2 * M_PI * 2.0 * t), 0, 'g', 17);
    }
    m.write(text.toUtf8());
    const QString path = dir + QStringLiteral("/rths.json");
    QFile f(path);
    f.open(QIODevice::WriteOnly | QIODevice::Text);
    f.write(QStringLiteral(R"({"name": "sine on case 1", "rths": {"rate": 1024,
      "structure": {"benchmarkCase": 1, "specimenDof": 0},
      "sensors": {"noise": true, "seed": 3},
      "compensation": {"type": "ats", "lead": {"enabled": true}, "fitToLoop": true},
      "holdAfterMisses": 0,
      "groundMotion": {"file": "%1", "scale": 1.0, "unit": "m/s^2"}}})").arg(motion).toUtf8());
    return path;
}

} // namespace

class TestRthsRemote : public QObject {
    Q_OBJECT
private slots:
    void theControllersRunIsTheLocalRun() {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 3.0);
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("fast")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const QString remote = dir.path() + QStringLiteral("/remote"), local = dir.path() + QStringLiteral("/local");
        const auto r = clitest::hsmu({QStringLiteral("rths"), cfg, QStringLiteral("--controller"),
                                      QStringLiteral("tcp://127.0.0.1:%1").arg(ctl.port()), QStringLiteral("--out"), remote});
        QVERIFY2(r.exitCode == 0, qPrintable(clitest::report(r) + ctl.log()));
        const auto l = clitest::hsmu({QStringLiteral("rths"), cfg, QStringLiteral("--out"), local});
        QVERIFY2(l.exitCode == 0, qPrintable(clitest::report(l)));
        const QJsonObject a = clitest::readJson(remote + QStringLiteral("/summary.json"));
        const QJsonObject b = clitest::readJson(local + QStringLiteral("/summary.json"));
        QCOMPARE(a.value(QStringLiteral("ticks")).toInt(), 3073);
        QCOMPARE(a.value(QStringLiteral("ticks")).toInt(), b.value(QStringLiteral("ticks")).toInt());
        const QJsonObject ca = a.value(QStringLiteral("criteria")).toObject(), cb = b.value(QStringLiteral("criteria")).toObject();
        QCOMPARE(ca.keys().size(), 9);
        for (const QString& key : cb.keys())
            QVERIFY2(ca.value(key).toDouble() == cb.value(key).toDouble(), qPrintable(key));
        QVERIFY(a.value(QStringLiteral("peaks")).toObject() == b.value(QStringLiteral("peaks")).toObject());
        QCOMPARE(a.value(QStringLiteral("hold")).toString(), QString());
        QCOMPARE(a.value(QStringLiteral("telemetry")).toObject().value(QStringLiteral("received")).toInt(), 385);
        QCOMPARE(a.value(QStringLiteral("telemetry")).toObject().value(QStringLiteral("dropped")).toInt(), 0);
        // telemetry.csv: ticks 0, 8, ..., 3072, measured as in the local steps.csv.
        const QStringList tel = clitest::readLines(remote + QStringLiteral("/telemetry.csv"));
        const QStringList steps = clitest::readLines(local + QStringLiteral("/steps.csv"));
        QCOMPARE(tel.size(), 1 + 385);
        for (int i = 1; i < tel.size(); ++i) {
            const QStringList t = tel[i].split(QLatin1Char(','));
            QCOMPARE(t[0].toInt(), 8 * (i - 1));
            const QStringList s = steps[1 + t[0].toInt()].split(QLatin1Char(','));
            const double measured = t[4].toDouble(), csv = s[3].toDouble();
            QVERIFY2(std::abs(measured - csv) <= 1e-8 * std::abs(measured) + 1e-300, qPrintable(tel[i] + QStringLiteral(" / ") + steps[1 + t[0].toInt()]));
        }
    }

    void updatesReachTheControllersLoop() {
        QTemporaryDir dir;
        writeConfig(dir.path(), 3.0); // its sine.txt
        const QString cfg = writeDamperConfig(dir.path(), dir.path() + QStringLiteral("/sine.txt"));
        const QString out = dir.path() + QStringLiteral("/out");
        const auto refused = clitest::hsmu({QStringLiteral("rths"), cfg, QStringLiteral("--out"), out,
                                            QStringLiteral("--update"), QStringLiteral("1:alpha=80")});
        QCOMPARE(refused.exitCode, 1);
        QVERIFY2(refused.err.contains(QStringLiteral("--update needs --controller")), qPrintable(clitest::report(refused)));
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("realtime")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const auto r = clitest::hsmu({QStringLiteral("rths"), cfg, QStringLiteral("--controller"),
                                      QStringLiteral("tcp://127.0.0.1:%1").arg(ctl.port()), QStringLiteral("--out"), out,
                                      QStringLiteral("--update"), QStringLiteral("1:alpha=80,c0=0.03"),
                                      QStringLiteral("--update"), QStringLiteral("1.5:alpha=900")});
        QVERIFY2(r.exitCode == 0, qPrintable(clitest::report(r) + ctl.log()));
        QVERIFY2(r.out.contains(QStringLiteral("damper twin updated before tick ")), qPrintable(clitest::report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("alpha = 900 is outside the parameter box [0, 500]")), qPrintable(clitest::report(r)));
        const QJsonObject summary = clitest::readJson(out + QStringLiteral("/summary.json"));
        QCOMPARE(summary.value(QStringLiteral("ticks")).toInt(), 3073);
        const QJsonArray updates = summary.value(QStringLiteral("twin")).toObject().value(QStringLiteral("updates")).toArray();
        QCOMPARE(updates.size(), 2);
        const QJsonObject applied = updates[0].toObject();
        QVERIFY(applied.value(QStringLiteral("applied")).toBool());
        QVERIFY(applied.value(QStringLiteral("tick")).toInt() >= 1024); // sent at t >= 1 s
        QCOMPARE(applied.value(QStringLiteral("parameters")).toObject().value(QStringLiteral("alpha")).toDouble(), 80.0);
        QVERIFY(!updates[1].toObject().value(QStringLiteral("applied")).toBool());
    }

    void sigintHoldsTheControllersLoop() {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 30.0);
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("realtime")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const QString out = dir.path() + QStringLiteral("/out");
        QProcess p;
        p.start(QStringLiteral(HSMU_EXE), {QStringLiteral("rths"), cfg, QStringLiteral("--controller"),
                                           QStringLiteral("tcp://127.0.0.1:%1").arg(ctl.port()), QStringLiteral("--out"), out});
        QString seen;
        for (int i = 0; i < 300 && !seen.contains(QStringLiteral("t = ")); ++i) {
            p.waitForReadyRead(100);
            seen += QString::fromUtf8(p.readAllStandardOutput());
        }
        QVERIFY2(seen.contains(QStringLiteral("t = ")), qPrintable(seen));
        ::kill(pid_t(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(60000));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitCode(), 2);
        const QJsonObject summary = clitest::readJson(out + QStringLiteral("/summary.json"));
        const QString hold = summary.value(QStringLiteral("hold")).toString();
        QVERIFY2(hold.startsWith(QStringLiteral("console hold (SIGINT received by hsmu rths) before tick ")), qPrintable(hold + err));
        QVERIFY(summary.value(QStringLiteral("ticks")).toInt() < 30 * 1024);
        QVERIFY(ctl.waitForLog(QStringLiteral("RTHS run ended")));
    }
};

QTEST_GUILESS_MAIN(TestRthsRemote)
#include "TestRthsRemote.moc"
