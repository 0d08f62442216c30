// `hsmu replay --identify`, `hsmu replay --import`, `hsmu export` and the records of
// `hsmu compare` (the real binary via QProcess, its files read back with core's reader):
// - a recorded `hsmu run` (paper-condition-3, 3 s, UKF) re-identified offline gives the
//   online final parameters to 1e-9 relative (summary.json and parameters.csv);
// - export writes the documented CSVs whose values equal the record's datasets;
// - compare writes three readable records (reference, initial, updated);
// - imported CSVs: a good one identifies (Nelder-Mead, with a settings override); a malformed
//   one and a file that is not a record are clear errors (exit 1); (replay without --identify
//   opens the replay window: TestReplayWindow);
// - lab units: export --units and import --columns round trip, and their errors;
// - --method all on the Gill column (../shared/data; QSKIP where absent): the table's and
//   comparison's NRMSEs equal those of the three single-method runs;
// - an interrupted replay (SIGINT once its progress line is on stderr) ends with exit code 2
//   and a partial summary (samples done, the parameters at that point).

#include "CliTestSupport.h"

#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/BoucWenPinching.h"
#include "core/record/RecordReader.h"

#include <QJsonArray>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

#include <signal.h>

using namespace clitest;

namespace {

QString path(const QTemporaryDir& dir, const char* name) {
    return dir.filePath(QString::fromLatin1(name));
}

void writeText(const QString& file, const QByteArray& text) {
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
}

double relative(double a, double b) {
    return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300});
}

} // namespace

class TestReplayCommand : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void offlineUkfEqualsOnline();
    void exportWritesTheDatasets();
    void compareWritesThreeRecords();
    void importIdentifies();
    void pinchingModelIsCalibratedByDefault();
    void errorsAreClear();
    void calibrationFitsAForceOffset();
    void labUnitsOutAndBackIn();
    void methodAllEqualsTheSingleRuns();
    void interruptedReplayWritesAPartialSummary();

private:
    QTemporaryDir m_dir;
    QString m_record; // a recorded hsmu run (3 s of condition 3)
};

void TestReplayCommand::initTestCase() {
    QVERIFY(m_dir.isValid());
    const QString out = path(m_dir, "run");
    const Result r = clitest::hsmu({QStringLiteral("run"), QStringLiteral("paper-condition-3"),
                                    QStringLiteral("--duration"), QStringLiteral("3"),
                                    QStringLiteral("--out"), out});
    QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
    m_record = out + QStringLiteral("/record.h5");
}

void TestReplayCommand::offlineUkfEqualsOnline() {
    const QString out = path(m_dir, "identified");
    const Result r = clitest::hsmu({QStringLiteral("replay"), m_record,
                                    QStringLiteral("--identify"), QStringLiteral("--out"), out});
    QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
    QVERIFY2(r.out.contains(QStringLiteral("UKF identification of")), qPrintable(r.out));
    QVERIFY2(r.out.contains(QStringLiteral("online")), qPrintable(r.out));

    const hsmu::RecordReader reader(m_record.toStdString());
    const hsmu::RecordData& d = reader.data();
    const QJsonObject summary = readJson(out + QStringLiteral("/summary.json"));
    QCOMPARE(summary.value(QStringLiteral("method")).toString(), QStringLiteral("UKF"));
    QCOMPARE(summary.value(QStringLiteral("samples")).toInt(), d.rows() - 1);
    const QJsonObject params = summary.value(QStringLiteral("parameters")).toObject();
    const auto& names = d.layout.updating->parameters;
    QCOMPARE(params.size(), qsizetype(names.size()));
    for (std::size_t j = 0; j < names.size(); ++j) {
        const QJsonObject p = params.value(QString::fromStdString(names[j])).toObject();
        const double online = d.parameters(d.rows() - 1, Eigen::Index(j));
        QVERIFY2(relative(p.value(QStringLiteral("final")).toDouble(), online) <= 1e-9,
                 names[j].c_str());
        QCOMPARE(p.value(QStringLiteral("online")).toDouble(), online);
        QCOMPARE(p.value(QStringLiteral("initial")).toDouble(), d.parameters(0, Eigen::Index(j)));
    }
    // The parameter history: a header and one row per committed step, the last = online.
    const QStringList lines = readLines(out + QStringLiteral("/parameters.csv"));
    QCOMPARE(lines.size(), d.rows());
    QVERIFY(lines[0].startsWith(QStringLiteral("time [s],deformation [rad],force [kN m],"
                                               "auxiliary_force [kN m],fit_error [-],k0 [-]")));
    const QStringList last = lines.back().split(QLatin1Char(','));
    QCOMPARE(last.size(), 5 + 2 * int(names.size()));
    for (std::size_t j = 0; j < names.size(); ++j)
        QVERIFY(relative(last[int(5 + j)].toDouble(),
                         d.parameters(d.rows() - 1, Eigen::Index(j))) <= 1e-9);
}

void TestReplayCommand::exportWritesTheDatasets() {
    const QString out = path(m_dir, "csv");
    const Result r =
        clitest::hsmu({QStringLiteral("export"), m_record, QStringLiteral("--csv"), out});
    QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
    const hsmu::RecordReader reader(m_record.toStdString());
    const hsmu::RecordData& d = reader.data();
    for (const char* f : {"steps.csv", "dofs.csv", "elements.csv", "updating.csv",
                          "update_events.csv", "alarms.csv", "notes.csv"})
        QVERIFY2(r.out.contains(QString::fromLatin1(f)), f);
    const QStringList steps = readLines(out + QStringLiteral("/steps.csv"));
    QCOMPARE(steps.size(), d.rows() + 1);
    QCOMPARE(steps[0], QStringLiteral("step,time [s],ground_acceleration [m/s^2]"));
    for (int i = 0; i < d.rows(); ++i) {
        const QStringList row = steps[i + 1].split(QLatin1Char(','));
        QCOMPARE(row[0].toInt(), d.steps[std::size_t(i)]);
        QCOMPARE(row[1].toDouble(), d.time[i]);
        QCOMPARE(row[2].toDouble(), d.groundAcceleration[i]);
    }
    const QStringList elements = readLines(out + QStringLiteral("/elements.csv"));
    QCOMPARE(elements.size(), d.rows() + 1);
    const QStringList row = elements[100].split(QLatin1Char(','));
    QCOMPARE(row[3].toDouble(), d.force(99, 0)); // Element 1 force at row 99
}

void TestReplayCommand::compareWritesThreeRecords() {
    const QString out = path(m_dir, "compare");
    const Result r = clitest::hsmu({QStringLiteral("compare"), QStringLiteral("paper-condition-3"),
                                    QStringLiteral("--duration"), QStringLiteral("2"),
                                    QStringLiteral("--out"), out});
    QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
    const QJsonObject cmp = readJson(out + QStringLiteral("/compare.json"));
    QVERIFY(!cmp.isEmpty());
    for (const char* run : {"reference", "initial", "updated"}) {
        const QString file =
            out + QLatin1Char('/') + QLatin1String(run) + QStringLiteral("/record.h5");
        const hsmu::RecordReader reader(file.toStdString());
        const hsmu::RecordData& d = reader.data();
        QCOMPARE(d.meta.run, std::string(run));
        QCOMPARE(d.rows(), 201);
        QCOMPARE(d.time[200], 2.0);
        // Only the updated run identifies; the reference has Element 2 as a specimen.
        QCOMPARE(d.layout.updating.has_value(), std::string(run) == "updated");
        QCOMPARE(d.layout.elements[1].experimental, std::string(run) == "reference");
    }
    // The updated record's Element 2 force equals compare's updated-run history.
    const hsmu::RecordReader updated((out + QStringLiteral("/updated/record.h5")).toStdString());
    QVERIFY(updated.data().appliedUpdates.back() > 0);
}

void TestReplayCommand::importIdentifies() {
    // A bilinear specimen (k0 1000 kN/m, fy 2.8 kN, b 0.1) under a growing sine, in mm and N.
    QByteArray csv = "time [s], deformation [mm], force [N]\n";
    const double k0 = 1000.0, fy = 2.8, b = 0.1;
    double u = 0.0, f = 0.0;
    for (int k = 1; k <= 600; ++k) {
        const double t = 0.01 * k;
        const double uNew = 0.012 * (t / 6.0) * std::sin(2.0 * M_PI * t);
        // Kinematic hardening: elastic trial, then return to the bounds fy +- b k0 u.
        double trial = f + k0 * (uNew - u);
        const double upper = fy * (1.0 - b) + b * k0 * uNew;
        const double lower = -fy * (1.0 - b) + b * k0 * uNew;
        f = std::clamp(trial, lower, upper);
        u = uNew;
        csv += QByteArray::number(t, 'g', 17) + ", " + QByteArray::number(u * 1e3, 'g', 17) + ", " +
               QByteArray::number(f * 1e3, 'g', 17) + "\n";
    }
    const QString data = path(m_dir, "bilinear.csv");
    writeText(data, csv);
    const QString settings = path(m_dir, "bilinear.json");
    writeText(settings, R"({"model": {"law": "bilinear", "k0": 700, "fy": 2.0, "b": 0.2},
        "updating": {"bounds": {"k0": [500, 1500], "fy": [1, 5], "b": [0, 0.3]},
                     "nelderMead": {"maxEvaluations": 400}}})");
    const QString out = path(m_dir, "imported");
    const Result r =
        clitest::hsmu({QStringLiteral("replay"), QStringLiteral("--import"), data,
                       QStringLiteral("--method"), QStringLiteral("nelder-mead"),
                       QStringLiteral("--config"), settings, QStringLiteral("--out"), out});
    QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
    const QJsonObject p = readJson(out + QStringLiteral("/summary.json"))
                              .value(QStringLiteral("parameters"))
                              .toObject();
    const auto final = [&](const char* name) {
        return p.value(QLatin1String(name)).toObject().value(QStringLiteral("final")).toDouble();
    };
    // The law generated the data exactly: the fit recovers it to 1 % (k0, fy) and 0.01 (b).
    QVERIFY2(relative(final("k0"), k0) < 0.01, qPrintable(r.out));
    QVERIFY2(relative(final("fy"), fy) < 0.01, qPrintable(r.out));
    QVERIFY2(std::abs(final("b") - b) < 0.01, qPrintable(r.out));
}

// A boucWenPinching model without --method: only the calibration runs (docs/cli.md); with
// --method ukf the pinching UKF does.
void TestReplayCommand::pinchingModelIsCalibratedByDefault() {
    hsmu::BoucWenPinchingParameters p;
    p.boucWen.uRef = 0.01;
    p.boucWen.fRef = 10.0;
    hsmu::BoucWenPinching law(p);
    QByteArray csv = "time [s], deformation [m], force [kN]\n";
    for (int k = 1; k <= 300; ++k) {
        const double t = 0.01 * k;
        const double u = 0.04 * (t / 3.0) * std::sin(2.0 * M_PI * t);
        law.setTrialDeformation(u);
        law.commit();
        csv += QByteArray::number(t, 'g', 17) + ", " + QByteArray::number(u, 'g', 17) + ", " +
               QByteArray::number(law.committedForce(), 'g', 17) + "\n";
    }
    const QString data = path(m_dir, "pinching.csv");
    writeText(data, csv);
    const QString settings = path(m_dir, "pinching.json");
    writeText(settings, R"({"model": {"law": "boucWenPinching"}})");
    const auto method = [&](const QStringList& extra) {
        const QString out = path(m_dir, extra.isEmpty() ? "pinchingDefault" : "pinchingUkf");
        const Result r = clitest::hsmu(QStringList{QStringLiteral("replay"),
                                                   QStringLiteral("--import"), data,
                                                   QStringLiteral("--config"), settings,
                                                   QStringLiteral("--out"), out} +
                                       extra);
        return r.exitCode == 0
                   ? readJson(out + QStringLiteral("/summary.json"))
                         .value(QStringLiteral("method"))
                         .toString()
                   : report(r);
    };
    QCOMPARE(method({}), QStringLiteral("calibration"));
    QCOMPARE(method({QStringLiteral("--method"), QStringLiteral("ukf")}),
             QStringLiteral("UKF (pinching)"));
}

void TestReplayCommand::errorsAreClear() {
    const QString bad = path(m_dir, "bad.csv");
    writeText(bad, "time [s], deformation [mm], force [kN]\n0, 0, 0\n0.01, x, 1\n");
    Result r = clitest::hsmu({QStringLiteral("replay"), QStringLiteral("--import"), bad,
                              QStringLiteral("--out"), path(m_dir, "bad")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(bad + QStringLiteral(": line 3: column 2 (deformation): 'x' is not a "
                                                 "number")),
             qPrintable(r.err));

    r = clitest::hsmu({QStringLiteral("replay"), m_record, QStringLiteral("--identify")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("missing --out DIR")), qPrintable(r.err));

    r = clitest::hsmu({QStringLiteral("export"), bad, QStringLiteral("--csv"), path(m_dir, "x")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("not an HSMU record (not an HDF5 file)")),
             qPrintable(r.err));

    r = clitest::hsmu({QStringLiteral("replay"), m_record, QStringLiteral("--identify"),
                       QStringLiteral("--method"), QStringLiteral("simplex"),
                       QStringLiteral("--out"), path(m_dir, "x")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("expected ukf, nelder-mead, calibration or all")), qPrintable(r.err));
}

// A bilinear specimen whose load cell reads 5 % of its peak force at rest (written in mm and
// N, read in m and kN): the calibration (offsets auto by default) keeps a force offset, gives
// it back within 1 % with its unit and interval in the table and in summary.json; --offsets off fits none; a bad
// --offsets value is a clear error.
void TestReplayCommand::calibrationFitsAForceOffset() {
    const double k0 = 1000.0, fy = 2.8, b = 0.1; // kN/m, kN, -
    std::vector<double> us, fs;
    double u = 0.0, f = 0.0, peak = 0.0;
    for (int k = 1; k <= 600; ++k) {
        const double uNew = 0.012 * (0.01 * k / 6.0) * std::sin(2.0 * M_PI * 0.01 * k);
        const double upper = fy * (1.0 - b) + b * k0 * uNew;
        const double lower = -fy * (1.0 - b) + b * k0 * uNew;
        f = std::clamp(f + k0 * (uNew - u), lower, upper);
        u = uNew;
        us.push_back(u);
        fs.push_back(f);
        peak = std::max(peak, std::abs(f));
    }
    const double offset = 0.05 * peak * 1e3; // N
    QByteArray csv = "time [s], deformation [mm], force [N]\n";
    for (std::size_t k = 0; k < us.size(); ++k)
        csv += QByteArray::number(0.01 * double(k + 1), 'g', 17) + ", " +
               QByteArray::number(us[k] * 1e3, 'g', 17) + ", " +
               QByteArray::number(fs[k] * 1e3 + offset, 'g', 17) + "\n";
    const QString data = path(m_dir, "offset.csv");
    writeText(data, csv);
    const QString settings = path(m_dir, "offset.json");
    writeText(settings, R"({"model": {"law": "bilinear"}})");
    const auto run = [&](const QString& out, const QStringList& extra) {
        return clitest::hsmu(QStringList{QStringLiteral("replay"), QStringLiteral("--import"), data,
                                         QStringLiteral("--method"), QStringLiteral("calibration"),
                                         QStringLiteral("--config"), settings,
                                         QStringLiteral("--out"), out} +
                             extra);
    };
    const QString out = path(m_dir, "offset");
    Result r = run(out, {});
    QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
    QVERIFY2(r.out.contains(QStringLiteral("offsets fitted")), qPrintable(r.out));
    QVERIFY2(QRegularExpression(QStringLiteral("forceOffset +kN +[-0-9.e]+ +\\+- "))
                 .match(r.out)
                 .hasMatch(),
             qPrintable(r.out));
    const QJsonObject cal =
        readJson(out + QStringLiteral("/summary.json")).value(QStringLiteral("calibration")).toObject();
    QVERIFY(cal.value(QStringLiteral("offsets")).toObject().value(QStringLiteral("used")).toBool());
    const QJsonObject f0 = cal.value(QStringLiteral("parameters"))
                               .toObject()
                               .value(QStringLiteral("forceOffset"))
                               .toObject();
    QVERIFY2(relative(f0.value(QStringLiteral("value")).toDouble(), offset / 1e3) < 0.01,
             qPrintable(r.out));
    QCOMPARE(f0.value(QStringLiteral("ci95")).toArray().size(), qsizetype(2));
    QCOMPARE(readJson(out + QStringLiteral("/summary.json"))
                 .value(QStringLiteral("parameterUnits"))
                 .toObject()
                 .value(QStringLiteral("forceOffset"))
                 .toString(),
             QStringLiteral("kN"));

    r = run(path(m_dir, "offsetOff"), {QStringLiteral("--offsets"), QStringLiteral("off")});
    QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
    QVERIFY2(!r.out.contains(QStringLiteral("forceOffset")), qPrintable(r.out));

    r = run(path(m_dir, "offsetBad"), {QStringLiteral("--offsets"), QStringLiteral("maybe")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("--offsets: expected auto, on or off, found 'maybe'")),
             qPrintable(r.err));
}

void TestReplayCommand::labUnitsOutAndBackIn() {
    // `hsmu export --units` writes in, kip, deg, kip in, ms; `hsmu replay --import --columns`
    // reads Element 1 back (the header gives the units) to the record's values. Only the
    // calibration runs: the units are the point here, and the default robust UKF takes over a
    // minute on this history on a loaded machine (issue 12, its per-step cost).
    const QString out = path(m_dir, "lab-csv");
    Result r = clitest::hsmu({QStringLiteral("export"), m_record, QStringLiteral("--csv"), out,
                              QStringLiteral("--units"),
                              QStringLiteral("length=in,force=kip,rotation=deg,moment=kip*in,"
                                             "time=ms")});
    QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
    const hsmu::RecordReader reader(m_record.toStdString());
    const hsmu::RecordData& d = reader.data();
    const QStringList elements = readLines(out + QStringLiteral("/elements.csv"));
    QVERIFY2(elements[0].startsWith(QStringLiteral("step,time [ms],Element 1 deformation [deg],"
                                                   "Element 1 force [kip in]")),
             qPrintable(elements[0]));
    const QStringList row = elements[100].split(QLatin1Char(','));
    const double kipIn = 4.4482216152605 * 0.0254;
    QVERIFY(std::abs(row[3].toDouble() * kipIn - d.force(99, 0)) <=
            1e-14 * std::abs(d.force(99, 0)));
    const QString back = path(m_dir, "lab-back");
    r = clitest::hsmu({QStringLiteral("replay"), QStringLiteral("--import"),
                       out + QStringLiteral("/elements.csv"), QStringLiteral("--columns"),
                       QStringLiteral("2,3,4"), QStringLiteral("--method"),
                       QStringLiteral("calibration"), QStringLiteral("--out"), back});
    QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
    const QJsonObject summary = readJson(back + QStringLiteral("/summary.json"));
    QCOMPARE(summary.value(QStringLiteral("samples")).toInt(), d.rows());
    QCOMPARE(summary.value(QStringLiteral("units")).toObject().value(QStringLiteral("force")).toString(),
             QStringLiteral("kN m"));

    r = clitest::hsmu({QStringLiteral("export"), m_record, QStringLiteral("--csv"), out,
                       QStringLiteral("--units"), QStringLiteral("length=yd")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("--units: unknown length unit 'yd' (expected m, cm, "
                                           "mm, in, ft)")),
             qPrintable(r.err));
    r = clitest::hsmu({QStringLiteral("replay"), m_record, QStringLiteral("--identify"),
                       QStringLiteral("--columns"), QStringLiteral("1,2,3"),
                       QStringLiteral("--out"), path(m_dir, "x")});
    QCOMPARE(r.exitCode, 1);
    QVERIFY2(r.err.contains(QStringLiteral("--columns applies to --import only")),
             qPrintable(r.err));
}

void TestReplayCommand::methodAllEqualsTheSingleRuns() {
    const QString data = QStringLiteral(HSMU_SHARED_DATA_DIR) +
                         QStringLiteral("/rc-column-gill1979/rc_column_force_disp.txt");
    if (!QFile::exists(data))
        QSKIP("shared record absent (a fresh machine has no ../shared/data)");
    const QString out = path(m_dir, "gill-all");
    const Result r = clitest::hsmu({QStringLiteral("replay"), QStringLiteral("--import"), data,
                                    QStringLiteral("--method"), QStringLiteral("all"),
                                    QStringLiteral("--out"), out},
                                   600000);
    QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
    qInfo("%s", qPrintable(r.out));
    QVERIFY2(r.out.contains(QStringLiteral("recommended: ")), qPrintable(r.out));
    const QJsonArray rows = readJson(out + QStringLiteral("/summary.json"))
                                .value(QStringLiteral("comparison"))
                                .toArray();
    QCOMPARE(rows.size(), 3);
    const QStringList csv = readLines(out + QStringLiteral("/comparison.csv"));
    QCOMPARE(csv.size(), 4);
    for (int i = 0; i < 3; ++i) {
        const QJsonObject row = rows[i].toObject();
        const QString method = row.value(QStringLiteral("method")).toString();
        QVERIFY(row.value(QStringLiteral("ok")).toBool());
        const QString single = path(m_dir, qPrintable(QStringLiteral("gill-") + method));
        const Result one = clitest::hsmu({QStringLiteral("replay"), QStringLiteral("--import"),
                                          data, QStringLiteral("--method"), method,
                                          QStringLiteral("--out"), single},
                                         600000);
        QVERIFY2(one.exitCode == 0, qPrintable(report(one)));
        const double expected = readJson(single + QStringLiteral("/summary.json"))
                                    .value(QStringLiteral("finalNrmse"))
                                    .toDouble();
        QCOMPARE(row.value(QStringLiteral("nrmse")).toDouble(), expected);
        // the CSV row and the printed table (in %, two decimals) say the same
        QCOMPARE(csv[i + 1].section(QLatin1Char(','), 1, 1).toDouble(), expected);
        const QString percent = QString::number(100.0 * expected, 'f', 2);
        QVERIFY2(r.out.contains(QRegularExpression(QStringLiteral("\\n  %1 +%2 ")
                                                       .arg(method, QRegularExpression::escape(percent)))),
                 qPrintable(method + QStringLiteral(" ") + percent));
        QVERIFY(QFile::exists(out + QLatin1Char('/') + method + QStringLiteral("/summary.json")));
    }
}

void TestReplayCommand::interruptedReplayWritesAPartialSummary() {
    // A long synthetic Bouc-Wen record (mm, kN): 200,000 samples of growing cycles, long
    // enough for the progress line (after 3 s of work) on any machine.
    hsmu::BoucWenParameters bw;
    bw.k0 = 2.0;
    bw.alpha = 0.05;
    bw.beta = 0.6;
    bw.gamma = 0.4;
    hsmu::BoucWen law(bw);
    QByteArray csv = "time [s], deformation [mm], force [kN]\n";
    const int samples = 200000;
    for (int k = 1; k <= samples; ++k) {
        const double t = 0.01 * k;
        const double u = 4.0 * (0.2 + 0.8 * double(k) / samples) * std::sin(2.0 * M_PI * t);
        QCOMPARE(law.setTrialDeformation(u), hsmu::LawStatus::Ok);
        law.commit();
        csv += QByteArray::number(t, 'g', 10) + ", " + QByteArray::number(u, 'g', 10) + ", " +
               QByteArray::number(law.committedForce(), 'g', 10) + "\n";
    }
    const QString data = path(m_dir, "long.csv");
    writeText(data, csv);
    const QString out = path(m_dir, "interrupted");
    QProcess p;
    p.setReadChannel(QProcess::StandardError);
    p.start(QStringLiteral(HSMU_EXE), {QStringLiteral("replay"), QStringLiteral("--import"), data,
                                       QStringLiteral("--out"), out});
    QVERIFY(p.waitForStarted());
    QByteArray err;
    while (!err.contains("hsmu replay: ")) { // synchronised on the progress line
        if (!p.waitForReadyRead(600000))
            QFAIL(qPrintable(QStringLiteral("no progress line; stderr: ") + QString::fromUtf8(err)));
        err += p.readAllStandardError();
    }
    QCOMPARE(::kill(pid_t(p.processId()), SIGINT), 0);
    QVERIFY(p.waitForFinished(600000));
    const QString stdoutText = QString::fromUtf8(p.readAllStandardOutput());
    err += p.readAllStandardError();
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QVERIFY2(p.exitCode() == 2, qPrintable(stdoutText + QString::fromUtf8(err)));
    QVERIFY2(stdoutText.contains(QStringLiteral("interrupted (SIGINT received)")),
             qPrintable(stdoutText));
    const QJsonObject summary = readJson(out + QStringLiteral("/summary.json"));
    QCOMPARE(summary.value(QStringLiteral("interrupted")).toString(),
             QStringLiteral("SIGINT received"));
    QCOMPARE(summary.value(QStringLiteral("samples")).toInt(), samples);
    const int done = summary.value(QStringLiteral("samplesDone")).toInt();
    QVERIFY2(done > 0 && done < samples, qPrintable(QString::number(done)));
    QCOMPARE(summary.value(QStringLiteral("phase")).toString(), QStringLiteral("online"));
    const QJsonObject parameters = summary.value(QStringLiteral("parameters")).toObject();
    QVERIFY(parameters.contains(QStringLiteral("k0")));
    const double k0 = parameters.value(QStringLiteral("k0"))
                          .toObject()
                          .value(QStringLiteral("current"))
                          .toDouble();
    QVERIFY(std::isfinite(k0) && k0 > 0.0);
    QVERIFY2(stdoutText.contains(QStringLiteral("parameters after sample %1:").arg(done)),
             qPrintable(stdoutText));
}

QTEST_GUILESS_MAIN(TestReplayCommand)
#include "TestReplayCommand.moc"
