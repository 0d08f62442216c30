// The Qt-free `hsmu` (gui/cli/FastRun.h): a plain `hsmu run FILE` runs without mapping Qt (the
// dynamic loader's own list of what it loaded, LD_DEBUG=files), prints and writes the same
// bytes as hsmu-cli (the Qt Core front end) on the same run, and leaves to hsmu-cli what it
// does not read exactly (a preset name, a language other than English).
#include "CliTestSupport.h"

#include <QDir>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

namespace {

const QString kConfig = QStringLiteral(HSMU_SOURCE_DIR "/benchmarks/sdof-opensees.json");

/// hsmu-cli, the Qt Core front end, on the same arguments.
clitest::Result hsmuCli(const QStringList& args) {
    QProcess p;
    p.start(QStringLiteral(HSMU_CLI_EXE), args);
    clitest::Result r;
    if (!p.waitForFinished(120000)) {
        p.kill();
        p.waitForFinished();
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

QByteArray bytes(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

/// The text with the measured times (wall time, steps/s) blanked.
QString withoutTimes(QString s) {
    s.replace(QRegularExpression(QStringLiteral("wall time: [0-9.e+-]+ s")),
              QStringLiteral("wall time: * s"));
    s.replace(QRegularExpression(QStringLiteral("  [0-9]+ steps/s")),
              QStringLiteral("  * steps/s"));
    return s;
}

/// `hsmu run CONFIG --out OUT ARGS` by both front ends: the Qt-free hsmu (into fast), hsmu-cli
/// (into qt).
std::pair<clitest::Result, clitest::Result> bothFrontEnds(const QString& config,
                                                          const QString& fast, const QString& qt,
                                                          const QStringList& args) {
    const QStringList run{QStringLiteral("run"), config, QStringLiteral("--out")};
    return {clitest::hsmu(run + QStringList{fast} + args), hsmuCli(run + QStringList{qt} + args)};
}

/// summary.json without what is measured (wall time, timing).
QJsonObject summaryOf(const QString& path) {
    QJsonObject s = clitest::readJson(path);
    for (const QString& measured : {QStringLiteral("wall_time_s"), QStringLiteral("timing")})
        s.remove(measured);
    return s;
}

} // namespace

class TestFastRun : public QObject {
    Q_OBJECT
private slots:
    void plainRunLoadsNoQt() {
        QTemporaryDir dir;
        const auto r =
            clitest::hsmu({QStringLiteral("run"), kConfig, QStringLiteral("--out"),
                           dir.filePath(QStringLiteral("out")), QStringLiteral("--duration"),
                           QStringLiteral("2")},
                          120000, {{QStringLiteral("LD_DEBUG"), QStringLiteral("files")}});
        QVERIFY2(r.exitCode == 0, qPrintable(clitest::report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("file=libstdc++")), "LD_DEBUG listed no library");
        QVERIFY2(!r.err.contains(QStringLiteral("libQt6")), qPrintable(r.err.left(4000)));
        QVERIFY(r.out.contains(QStringLiteral("state: finished, steps: 2000 of 2000")));
        // what it hands on does load Qt Core: the check above can fail
        const auto preset =
            clitest::hsmu({QStringLiteral("run"), QStringLiteral("paper-condition-3"),
                           QStringLiteral("--out"), dir.filePath(QStringLiteral("preset")),
                           QStringLiteral("--duration"), QStringLiteral("0.2")},
                          120000, {{QStringLiteral("LD_DEBUG"), QStringLiteral("files")}});
        QVERIFY2(preset.exitCode == 0, qPrintable(clitest::report(preset)));
        QVERIFY(preset.err.contains(QStringLiteral("file=libQt6Core")));
    }

    void sameOutputsAsTheQtFrontEnd() {
        QTemporaryDir dir;
        const QStringList common{QStringLiteral("--duration"), QStringLiteral("3"),
                                 QStringLiteral("--scale=0.5"), QStringLiteral("--csv"),
                                 QStringLiteral("all")};
        const QString fast = dir.filePath(QStringLiteral("fast/"));
        const QString qt = dir.filePath(QStringLiteral("qt/"));
        const auto [a, b] = bothFrontEnds(kConfig, fast, qt, common);
        QVERIFY2(a.exitCode == 0, qPrintable(clitest::report(a)));
        QVERIFY2(b.exitCode == 0, qPrintable(clitest::report(b)));
        QCOMPARE(withoutTimes(a.out).replace(fast.chopped(1), QStringLiteral("DIR")),
                 withoutTimes(b.out).replace(qt.chopped(1), QStringLiteral("DIR")));
        QCOMPARE(withoutTimes(a.err), withoutTimes(b.err));
        QCOMPARE(a.err.count(QLatin1Char('\n')), 20); // every 5 %
        const QByteArray csv = bytes(fast + QStringLiteral("steps.csv"));
        QVERIFY(csv.size() > 3000 * 10);
        QCOMPARE(csv, bytes(qt + QStringLiteral("steps.csv")));
        QVERIFY(clitest::readJson(fast + QStringLiteral("summary.json"))
                    .contains(QStringLiteral("wall_time_s")));
        QCOMPARE(summaryOf(fast + QStringLiteral("summary.json")),
                 summaryOf(qt + QStringLiteral("summary.json")));
    }

    // --record-dofs / --record-every (issue 27): both front ends choose and decimate the same
    // DOFs, print and write the same, and refuse a specimen's channels with the same words.
    void recordDofOptionsAsTheQtFrontEnd() {
        QTemporaryDir dir;
        const QString config =
            QStringLiteral(HSMU_SOURCE_DIR "/resources/presets/paper-condition-3.json");
        const QStringList common{QStringLiteral("--duration"), QStringLiteral("2"),
                                 QStringLiteral("--record-dofs"), QStringLiteral("DOF 2"),
                                 QStringLiteral("--record-every=4")};
        const QString fast = dir.filePath(QStringLiteral("fast"));
        const QString qt = dir.filePath(QStringLiteral("qt"));
        const auto [a, b] = bothFrontEnds(config, fast, qt, common);
        QVERIFY2(a.exitCode == 0, qPrintable(clitest::report(a)));
        QVERIFY2(b.exitCode == 0, qPrintable(clitest::report(b)));
        QCOMPARE(withoutTimes(a.out).replace(fast, QStringLiteral("DIR")),
                 withoutTimes(b.out).replace(qt, QStringLiteral("DIR")));
        QVERIFY2(a.out.contains(QStringLiteral("  record: DOFs 1 (1 of 2), every 4 steps; "
                                               "elements, specimens and updating at every step")),
                 qPrintable(a.out));
        const QJsonObject sa = summaryOf(fast + QStringLiteral("/summary.json"));
        QCOMPARE(sa, summaryOf(qt + QStringLiteral("/summary.json")));
        const QJsonObject chosen = sa.value(QStringLiteral("record_dofs")).toObject();
        QCOMPARE(chosen.value(QStringLiteral("dofs")).toString(), QStringLiteral("1"));
        QCOMPARE(chosen.value(QStringLiteral("recorded")).toInt(), 1);
        QCOMPARE(chosen.value(QStringLiteral("of")).toInt(), 2);
        QCOMPARE(chosen.value(QStringLiteral("every")).toInt(), 4);
        // The two records' exports: every file the same bytes; dofs.csv of steps 0, 4, ... 200
        // (dt 0.01 s).
        for (const QString& out : {fast, qt}) {
            const auto e =
                clitest::hsmu({QStringLiteral("export"), out + QStringLiteral("/record.h5"),
                               QStringLiteral("--csv"), out + QStringLiteral("/csv")});
            QVERIFY2(e.exitCode == 0, qPrintable(clitest::report(e)));
        }
        for (const QString& file : QDir(fast + QStringLiteral("/csv")).entryList(QDir::Files))
            if (file != QLatin1String("sites.csv")) // measured round trips
                QCOMPARE(bytes(fast + QStringLiteral("/csv/") + file),
                         bytes(qt + QStringLiteral("/csv/") + file));
        const QList<QByteArray> dofs =
            bytes(fast + QStringLiteral("/csv/dofs.csv")).trimmed().split('\n');
        QCOMPARE(dofs.size(), 1 + 51);
        QCOMPARE(dofs[0], QByteArray("step,time [s],u DOF 2 [m],v DOF 2 [m/s],a DOF 2 [m/s^2]"));
        QVERIFY2(dofs[1].startsWith("0,0,") && dofs[2].startsWith("4,0.04") &&
                     dofs[51].startsWith("200,2"),
                 dofs[51].constData());
        QCOMPARE(bytes(fast + QStringLiteral("/csv/elements.csv")).count('\n'), 1 + 201);

        // A specimen's channels are never dropped: the same refusal from both.
        const QStringList specimen{QStringLiteral("--duration"), QStringLiteral("0.1"),
                                   QStringLiteral("--record-dofs"), QStringLiteral("0,Element 1")};
        const auto [c, d] =
            bothFrontEnds(config, fast + QStringLiteral("2"), qt + QStringLiteral("2"), specimen);
        QCOMPARE(c.exitCode, 1);
        QCOMPARE(d.exitCode, 1);
        QCOMPARE(c.err, d.err);
        QVERIFY2(c.err.contains(QStringLiteral("hsmu run: --record-dofs: 'Element 1' is a "
                                               "specimen (an experimental element): its channels "
                                               "(commanded, measured, force, actuators, basic "
                                               "DOFs) are always recorded in full at every step")),
                 qPrintable(c.err));
        const auto e = clitest::hsmu({QStringLiteral("run"), config, QStringLiteral("--out"),
                                      fast + QStringLiteral("3"), QStringLiteral("--record-every"),
                                      QStringLiteral("0")});
        QCOMPARE(e.exitCode, 1);
        QVERIFY2(e.err.contains(QStringLiteral(
                     "--record-every: expected a whole number from 1 to 1000000, found '0'")),
                 qPrintable(e.err));
    }

    void otherLanguagesGoToTheCatalogues() {
        QTemporaryDir dir;
        QDir(dir.path()).mkpath(QStringLiteral("config/HSMU"));
        QFile settings(dir.filePath(QStringLiteral("config/HSMU/hsmu.conf")));
        QVERIFY(settings.open(QIODevice::WriteOnly));
        settings.write("[General]\nlanguage=es\n");
        settings.close();
        const QStringList args{QStringLiteral("run"),        kConfig,
                               QStringLiteral("--out"),      dir.filePath(QStringLiteral("out")),
                               QStringLiteral("--duration"), QStringLiteral("0.1")};
        const auto bySettings = clitest::hsmu(
            args, 120000,
            {{QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("config"))}});
        QVERIFY2(bySettings.exitCode == 0, qPrintable(clitest::report(bySettings)));
        QVERIFY2(bySettings.out.contains(QStringLiteral("  desplazamiento máximo:")),
                 qPrintable(bySettings.out));
        QVERIFY(bySettings.err.contains(QStringLiteral("pasos/s")));
        const auto byLocale = clitest::hsmu(
            args, 120000,
            {{QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("none"))},
             {QStringLiteral("LC_ALL"), QString()},
             {QStringLiteral("LANGUAGE"), QStringLiteral("es")},
             {QStringLiteral("LANG"), QStringLiteral("es_ES.UTF-8")}});
        QVERIFY2(byLocale.exitCode == 0, qPrintable(clitest::report(byLocale)));
        QVERIFY2(byLocale.out.contains(QStringLiteral("  desplazamiento máximo:")),
                 qPrintable(byLocale.out));
        const auto english = clitest::hsmu(
            args, 120000,
            {{QStringLiteral("XDG_CONFIG_HOME"), dir.filePath(QStringLiteral("none"))},
             {QStringLiteral("LC_ALL"), QString()},
             {QStringLiteral("LANGUAGE"), QString()},
             {QStringLiteral("LANG"), QStringLiteral("en_GB.UTF-8")}});
        QVERIFY2(english.out.contains(QStringLiteral("  peak displacement:")),
                 qPrintable(english.out));
    }
};

QTEST_GUILESS_MAIN(TestFastRun)
#include "TestFastRun.moc"
