// `hsmu compare`: the paper's protocol from the command line (the real binary via QProcess):
// compare.json with both runs' metrics, the table on stdout, the figure PNGs; a configuration
// without updating is a clear error.

#include "CliTestSupport.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace clitest;

class TestCompareCommand : public QObject {
    Q_OBJECT
private slots:
    void condition3UpdatedBeatsInitial() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString out = dir.filePath(QStringLiteral("cmp"));
        const Result r = hsmu({QStringLiteral("compare"), QStringLiteral("paper-condition-3"),
                               QStringLiteral("--out"), out, QStringLiteral("--duration"),
                               QStringLiteral("8"), QStringLiteral("--plots")},
                              300000);
        QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("reference")), qPrintable(r.err)); // progress

        const QJsonObject j = readJson(out + QStringLiteral("/compare.json"));
        QVERIFY(!j.isEmpty());
        QCOMPARE(j.value(QStringLiteral("element")).toString(), QStringLiteral("Element 2"));
        QCOMPARE(j.value(QStringLiteral("dof")).toString(), QStringLiteral("DOF 2"));
        QCOMPARE(j.value(QStringLiteral("force_unit")).toString(), QStringLiteral("kN m"));
        QCOMPARE(j.value(QStringLiteral("steps")).toInt(), 800);
        QVERIFY(j.value(QStringLiteral("config")).toObject().contains(QStringLiteral("name")));
        const QJsonObject runs = j.value(QStringLiteral("runs")).toObject();
        const QStringList keys{QStringLiteral("force_nrmse"), QStringLiteral("force_peak_error"),
                               QStringLiteral("displacement_nrmse"),
                               QStringLiteral("displacement_peak_error")};
        for (const QString& run : {QStringLiteral("initial"), QStringLiteral("updated")}) {
            const QJsonObject m = runs.value(run).toObject();
            for (const QString& k : keys) {
                const QJsonValue v = m.value(k);
                QVERIFY2(v.isDouble() && std::isfinite(v.toDouble()) && v.toDouble() >= 0.0,
                         qPrintable(run + QLatin1Char('.') + k));
            }
            QCOMPARE(m.value(QStringLiteral("final_state")).toString(), QStringLiteral("finished"));
            // Issue 23 item 5: each run's specimens' tracking (the ideal virtual actuator: exact).
            const QJsonObject t = m.value(QStringLiteral("tracking")).toObject();
            QCOMPARE(t.keys(), QStringList{QStringLiteral("Element 1")});
            QCOMPARE(t.value(QStringLiteral("Element 1")).toObject().value(QStringLiteral("J2_percent")).toDouble(), 0.0);
            // Issue 26: how each site was reached (compare's runs are in-process).
            QCOMPARE(m.value(QStringLiteral("link_security")).toObject(),
                     (QJsonObject{{QStringLiteral("controller"), QStringLiteral("builtin")}}));
        }
        QCOMPARE(j.value(QStringLiteral("reference")).toObject().value(QStringLiteral("link_security")).toObject(),
                 (QJsonObject{{QStringLiteral("controller"), QStringLiteral("builtin")}}));
        // The reference run has the compared element as a specimen too.
        QCOMPARE(j.value(QStringLiteral("reference")).toObject().value(QStringLiteral("tracking")).toObject().keys(),
                 (QStringList{QStringLiteral("Element 1"), QStringLiteral("Element 2")}));
        const double initial =
            runs.value(QStringLiteral("initial")).toObject().value(keys[0]).toDouble();
        const double updated =
            runs.value(QStringLiteral("updated")).toObject().value(keys[0]).toDouble();
        QVERIFY2(
            updated < initial,
            qPrintable(
                QStringLiteral("updated force NRMSE %1, initial %2").arg(updated).arg(initial)));
        QVERIFY(initial > 0.0);
        const QJsonObject params = j.value(QStringLiteral("final_parameters")).toObject();
        QCOMPARE(params.size(), 7);
        for (auto it = params.begin(); it != params.end(); ++it)
            QVERIFY2(it.value().isDouble(), qPrintable(it.key()));
        QVERIFY(j.value(QStringLiteral("applied_updates")).toInt() > 0);

        // The table on stdout: both rows, units, percentages.
        QVERIFY2(r.out.contains(QStringLiteral("initial")) &&
                     r.out.contains(QStringLiteral("updated")) &&
                     r.out.contains(QStringLiteral("[kN m]")) &&
                     r.out.contains(QStringLiteral(" %")),
                 qPrintable(r.out));

        for (const QString& png :
             {QStringLiteral("parameters.png"), QStringLiteral("hysteresis_Element_2.png"),
              QStringLiteral("force_Element_2.png"), QStringLiteral("displacement_DOF_2.png")}) {
            const QString why = blankReason(out + QLatin1Char('/') + png);
            QVERIFY2(why.isEmpty(), qPrintable(why));
        }
    }

    // Issue 24: a link2d specimen (two-actuator-column-frame with its shear DOF identified and
    // Column R's updated): the table and compare.json carry each basic DOF and actuator with
    // their units (the metrics themselves: test_session_link2d_comparison).
    void link2dSpecimenPerBasicDofAndActuator() {
        QTemporaryDir dir;
        QFile preset(QStringLiteral(HSMU_SOURCE_DIR "/resources/presets/two-actuator-column-frame.json"));
        QVERIFY(preset.open(QIODevice::ReadOnly));
        QJsonObject doc = QJsonDocument::fromJson(preset.readAll()).object();
        QJsonObject law{{QStringLiteral("law"), QStringLiteral("boucWen")}, {QStringLiteral("k0"), 1.0},
                        {QStringLiteral("alpha"), 0.15}, {QStringLiteral("n"), 1.5},
                        {QStringLiteral("beta"), 1.5}, {QStringLiteral("gamma"), 2.0},
                        {QStringLiteral("A0"), 1.0}, {QStringLiteral("uRef"), 0.01},
                        {QStringLiteral("fRef"), 100.0}};
        doc.insert(QStringLiteral("updating"),
                   QJsonObject{{QStringLiteral("specimen"), QStringLiteral("Column L")},
                               {QStringLiteral("basicDof"), QStringLiteral("shear")},
                               {QStringLiteral("model"), law},
                               {QStringLiteral("reporter"),
                                QJsonObject{{QStringLiteral("targets"),
                                             QJsonArray{QJsonObject{{QStringLiteral("element"),
                                                                     QStringLiteral("Column R")}}}}}}});
        const QString config = dir.filePath(QStringLiteral("frame.json"));
        QFile f(config);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QJsonDocument(doc).toJson());
        f.close();
        const QString out = dir.filePath(QStringLiteral("cmp"));
        const Result r = hsmu({QStringLiteral("compare"), config, QStringLiteral("--out"), out,
                               QStringLiteral("--duration"), QStringLiteral("3")});
        QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
        QVERIFY2(r.out.contains(QStringLiteral("Per basic DOF against the reference run:")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QRegularExpression(QStringLiteral("updated +Column R +rotation .* rad .* kN m"))),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QRegularExpression(QStringLiteral("initial +Column L +lateral +displacement "))),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QRegularExpression(QStringLiteral("reference +Column R +vertical +force "))),
                 qPrintable(r.out));
        const QJsonObject j = readJson(out + QStringLiteral("/compare.json"));
        QCOMPARE(j.value(QStringLiteral("force_unit")).toString(), QStringLiteral("kN"));
        const QJsonObject updated = j.value(QStringLiteral("runs")).toObject().value(QStringLiteral("updated")).toObject();
        QCOMPARE(updated.value(QStringLiteral("basic_dofs")).toArray().size(), 9);
        QCOMPARE(updated.value(QStringLiteral("actuators")).toArray().size(), 2);
        QCOMPARE(j.value(QStringLiteral("reference")).toObject().value(QStringLiteral("actuators")).toArray().size(), 4);
    }

    void configWithoutUpdatingIsAnError() {
        QTemporaryDir dir;
        const Result r = hsmu({QStringLiteral("compare"), QStringLiteral("paper-condition-2"),
                               QStringLiteral("--out"), dir.filePath(QStringLiteral("cmp"))});
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("updating")), qPrintable(r.err));
        QVERIFY(!r.err.contains(QStringLiteral("internal error")));
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("cmp/compare.json"))));
    }

    void unknownElementIsAnError() {
        QTemporaryDir dir;
        const Result r =
            hsmu({QStringLiteral("compare"), QStringLiteral("paper-condition-3"),
                  QStringLiteral("--out"), dir.path(), QStringLiteral("--duration"),
                  QStringLiteral("1"), QStringLiteral("--element"), QStringLiteral("Element 9")});
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("Element 9")), qPrintable(r.err));
    }

    void missingOutIsAnError() {
        const Result r = hsmu({QStringLiteral("compare"), QStringLiteral("paper-condition-3")});
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("--out")), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCompareCommand)
#include "TestCompareCommand.moc"
