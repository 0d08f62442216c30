// `hsmu rths` leaves its run in an HDF5 run record (docs/rths.md, "Outputs"): every tick, as
// steps.csv has it (to its 9 significant digits), read back with core's RecordReader; a hold
// is in the record's alarms with every tick before it. A synthetic record (a 2 Hz sine) on a
// 1024 Hz loop keeps the runs short and independent of ../shared.

#include "CliTestSupport.h"

#include "core/record/RecordReader.h"
#include "core/rths/TrackingMetrics.h"

#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace hsmu;

namespace {

QString writeSine(const QString& dir)
{
    const QString path = dir + QStringLiteral("/sine.txt");
    QFile f(path);
    f.open(QIODevice::WriteOnly | QIODevice::Text);
    QString text;
    for (int i = 0; i <= 300; ++i) {
        const double t = 0.01 * i;
        text += QStringLiteral("%1 %2\n").arg(t, 0, 'g', 17).arg(0.8 * std::sin(2 * M_PI * 2.0 * t), 0, 'g', 17);
    }
    f.write(text.toUtf8());
    return path;
}

QString writeConfig(const QString& dir, const QString& motion, double stroke)
{
    const QString path = dir + QStringLiteral("/rths.json");
    QFile f(path);
    f.open(QIODevice::WriteOnly | QIODevice::Text);
    f.write(QStringLiteral(R"({"name": "sine on case 1", "rths": {"rate": 1024,
      "structure": {"benchmarkCase": 1, "specimenDof": 0},
      "limits": {"stroke": %1, "force": 8900, "velocity": 0.3},
      "sensors": {"noise": true, "seed": 3},
      "controller": {"kp": 2.0, "ki": 95.0},
      "compensation": {"type": "none", "lead": {"enabled": true}},
      "groundMotion": {"file": "%2", "scale": 1.0, "unit": "m/s^2"}}})")
                .arg(stroke, 0, 'g', 17).arg(motion).toUtf8());
    return path;
}

/// steps.csv as numbers: rows of time, desired, command, measured, force, floors, references.
std::vector<std::vector<double>> readSteps(const QString& path)
{
    std::vector<std::vector<double>> rows;
    const QStringList lines = clitest::readLines(path);
    for (int i = 1; i < lines.size(); ++i) {
        std::vector<double> row;
        for (const QString& v : lines[i].split(QLatin1Char(',')))
            row.push_back(v.toDouble());
        rows.push_back(row);
    }
    return rows;
}

/// Equal to the CSV's 9 significant digits (%.9g: relative rounding <= 5e-10 of the value).
bool sameAsCsv(double recorded, double csv)
{
    return std::abs(recorded - csv) <= 1e-8 * std::abs(recorded) + 1e-300;
}

} // namespace

class TestRthsCommand : public QObject {
    Q_OBJECT
private slots:
    void theRecordHoldsEveryTickOfTheRun()
    {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), writeSine(dir.path()), 0.007);
        const QString out = dir.path() + QStringLiteral("/out");
        const auto r = clitest::hsmu({QStringLiteral("rths"), cfg, QStringLiteral("--out"), out});
        QVERIFY2(r.exitCode == 0, qPrintable(clitest::report(r)));
        QVERIFY2(r.out.contains(QStringLiteral("record.h5")), qPrintable(r.out));

        const auto steps = readSteps(out + QStringLiteral("/steps.csv"));
        const RecordReader reader((out + QStringLiteral("/record.h5")).toStdString());
        const RecordData& d = reader.data();
        QCOMPARE(d.rows(), int(steps.size()));
        QCOMPARE(d.rows(), 3073); // 3 s at 1024 Hz, ticks 0 .. 3072
        QCOMPARE(d.meta.configName, std::string("sine on case 1"));
        QVERIFY(std::abs(d.meta.dt - 1.0 / 1024) < 1e-15);
        QVERIFY(d.meta.configuration.find("\"benchmarkCase\":1") != std::string::npos);
        QCOMPARE(d.layout.dofNames.size(), std::size_t(6));
        QCOMPARE(d.layout.dofNames[3], std::string("reference floor 1"));
        QCOMPARE(d.layout.elements.size(), std::size_t(1));
        QVERIFY(d.layout.elements[0].experimental);
        QCOMPARE(d.layout.elements[0].units.force, std::string("N"));
        QVERIFY(d.alarms.empty());

        std::vector<double> desired, measured;
        for (int k = 0; k < d.rows(); ++k) {
            const auto& s = steps[std::size_t(k)];
            QCOMPARE(d.steps[std::size_t(k)], k);
            const double expected[] = {d.time(k), d.commanded(k, 0), d.actuatorCommanded(k, 0),
                                       d.deformation(k, 0), d.force(k, 0), d.u(k, 0), d.u(k, 1),
                                       d.u(k, 2), d.u(k, 3), d.u(k, 4), d.u(k, 5)};
            QCOMPARE(s.size(), std::size_t(11));
            for (std::size_t c = 0; c < s.size(); ++c)
                QVERIFY2(sameAsCsv(expected[c], s[c]),
                         qPrintable(QStringLiteral("tick %1 column %2: record %3, steps.csv %4").arg(k).arg(c)
                                        .arg(expected[c], 0, 'g', 17).arg(s[c], 0, 'g', 17)));
            QCOMPARE(d.actuatorMeasured(k, 0), d.deformation(k, 0));
            QVERIFY(std::isnan(d.v(k, 0)));
            desired.push_back(d.commanded(k, 0));
            measured.push_back(d.deformation(k, 0));
        }
        // The ground acceleration the loop used: the sine at the tick's time (linear
        // interpolation of a 0.01 s sampled sine: within 0.8 (2 pi 2 0.01)^2 / 8 of it).
        for (int k = 0; k < d.rows(); k += 97)
            QVERIFY(std::abs(d.groundAcceleration(k) - 0.8 * std::sin(2 * M_PI * 2.0 * d.time(k))) < 2e-3);
        // Full precision in the record: J2 from its columns equals the summary's to 1e-12.
        const QJsonObject summary = clitest::readJson(out + QStringLiteral("/summary.json"));
        const double j2 = summary.value(QStringLiteral("criteria")).toObject().value(QStringLiteral("J2_percent")).toDouble();
        QVERIFY(j2 > 1.0);
        QVERIFY2(std::abs(rths::normalizedRmsError(desired, measured) - j2) <= 1e-12 * j2,
                 qPrintable(QStringLiteral("%1 against %2").arg(rths::normalizedRmsError(desired, measured), 0, 'g', 17).arg(j2, 0, 'g', 17)));
    }

    void aHoldIsInTheRecordWithEveryTickBeforeIt()
    {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), writeSine(dir.path()), 2e-4);
        const QString out = dir.path() + QStringLiteral("/out");
        const auto r = clitest::hsmu({QStringLiteral("rths"), cfg, QStringLiteral("--out"), out});
        QVERIFY2(r.exitCode == 2, qPrintable(clitest::report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("stroke limit")), qPrintable(r.err));

        const auto steps = readSteps(out + QStringLiteral("/steps.csv"));
        const RecordReader reader((out + QStringLiteral("/record.h5")).toStdString());
        const RecordData& d = reader.data();
        QVERIFY(steps.size() > 10 && steps.size() < 3073);
        QCOMPARE(d.rows(), int(steps.size()));
        QCOMPARE(d.alarms.size(), std::size_t(1));
        const Alarm& a = d.alarms.front();
        QCOMPARE(a.severity, AlarmSeverity::Critical);
        QCOMPARE(a.kind, AlarmKind::LimitExceeded);
        QVERIFY2(a.message.find("stroke limit") != std::string::npos, a.message.c_str());
        QCOMPARE(a.step, d.rows() - 1);
        QVERIFY(std::abs(a.time - d.time(d.rows() - 1)) < 1e-12);
    }
};

QTEST_GUILESS_MAIN(TestRthsCommand)
#include "TestRthsCommand.moc"
