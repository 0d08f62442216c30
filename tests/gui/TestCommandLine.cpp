// The hsmu executable as a user runs it: `hsmu run` (outputs, exit codes 0 / 1 / 2, messages,
// online model updating in the outputs, a controller over TCP) and `hsmu material`. Each case
// starts the real binary with QProcess; the TCP cases also a real hsmu-controller.

#include "CliTestSupport.h"

#include <QColor>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSet>

#include <cmath>
#include <QTemporaryDir>
#include <QtTest>

using namespace clitest;

namespace {

QJsonObject preset(const QString& id) {
    return readJson(QStringLiteral(HSMU_SOURCE_DIR "/resources/presets/") + id +
                    QStringLiteral(".json"));
}

QString writeJson(const QTemporaryDir& dir, const QString& name, const QJsonObject& doc) {
    const QString path = dir.filePath(name);
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(QJsonDocument(doc).toJson());
    return path;
}

} // namespace

class TestCommandLine : public QObject {
    Q_OBJECT
private slots:
    // Issue 25 item 22: on a machine without a display or XDG_RUNTIME_DIR, `hsmu run --plots`
    // printed Qt's "QStandardPaths: XDG_RUNTIME_DIR not set" and "This plugin does not support
    // propagateSizeHints()": a headless command prints only its own messages.
    void headlessPlotsPrintOnlyTheirOwnMessages() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char* name : {"XDG_RUNTIME_DIR", "DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
            env.remove(QString::fromLatin1(name));
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(HSMU_EXE),
                {QStringLiteral("run"), QStringLiteral("sdof-bouc-wen"), QStringLiteral("--out"),
                 dir.filePath(QStringLiteral("out")), QStringLiteral("--plots"),
                 QStringLiteral("--duration"), QStringLiteral("1")});
        QVERIFY(p.waitForFinished(120000));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitCode(), 0);
        for (const QString& noise :
             {QStringLiteral("QStandardPaths"), QStringLiteral("XDG_RUNTIME_DIR"),
              QStringLiteral("propagateSizeHints"), QStringLiteral("qt.")})
            QVERIFY2(!err.contains(noise), qPrintable(err));
        QVERIFY2(err.contains(QStringLiteral("100 %")), qPrintable(err)); // its own progress
        QVERIFY(QFile::exists(dir.filePath(QStringLiteral("out/hysteresis.png"))));
    }

    // Issue 25 item 18: a valid one-column record (values only) was refused for want of its
    // own sample step, with no way to give it. --record-dt gives it; the integration step
    // (--dt, 0.01 s) is a different thing. 51 values: 0.5 s at 0.01 s, 1.0 s at 0.02 s, so
    // the whole-record run takes 50 or 100 steps of 0.01 s.
    void oneColumnRecordTakesItsOwnSampleStep() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString values = dir.filePath(QStringLiteral("values.txt"));
        {
            QFile f(values);
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Text));
            for (int i = 0; i <= 50; ++i)
                f.write(QByteArray::number(0.002 * i) + '\n');
        }
        const QStringList base{QStringLiteral("run"), QStringLiteral("sdof-bouc-wen"),
                               QStringLiteral("--ground-motion"), values, QStringLiteral("--dt"),
                               QStringLiteral("0.01")};
        Result r = hsmu(base + QStringList{QStringLiteral("--out"), dir.filePath("a")});
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("values.txt")) &&
                     r.err.contains(QStringLiteral("needs the time step")),
                 qPrintable(r.err));
        r = hsmu(base + QStringList{QStringLiteral("--record-dt"), QStringLiteral("-1"),
                                    QStringLiteral("--out"), dir.filePath("b")});
        QVERIFY2(r.exitCode != 0 && r.err.contains(QStringLiteral("--record-dt")),
                 qPrintable(report(r)));
        for (const auto& [recordDt, steps] :
             {std::pair{QStringLiteral("0.01"), 50}, std::pair{QStringLiteral("0.02"), 100}}) {
            r = hsmu(base + QStringList{QStringLiteral("--record-dt"), recordDt,
                                        QStringLiteral("--out"), dir.filePath("c" + recordDt)});
            QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
            const QString expected = QStringLiteral("steps: %1 of %1").arg(steps);
            QVERIFY2(r.out.contains(expected), qPrintable(expected + QStringLiteral("\n") + r.out));
        }
    }

    void runPresetWritesOutputsAndPlots() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString out = dir.filePath(QStringLiteral("out"));
        const Result r = hsmu({QStringLiteral("run"), QStringLiteral("paper-condition-3"),
                               QStringLiteral("--out"), out, QStringLiteral("--plots"),
                               QStringLiteral("--duration"), QStringLiteral("3")});
        QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("100 %")), qPrintable(r.err)); // progress
        QVERIFY2(r.out.contains(QStringLiteral("DOF 1: ")) &&
                     r.out.contains(QStringLiteral(" kN m")),
                 qPrintable(r.out));

        const QJsonObject summary = readJson(out + QStringLiteral("/summary.json"));
        QCOMPARE(summary.value(QStringLiteral("steps")).toInt(), 300);
        QCOMPARE(summary.value(QStringLiteral("test_time_s")).toDouble(), 3.0);
        QCOMPARE(summary.value(QStringLiteral("state")).toString(), QStringLiteral("finished"));
        QVERIFY(summary.value(QStringLiteral("peak_displacement_m"))
                    .toObject()
                    .value(QStringLiteral("DOF 1"))
                    .toDouble() > 0.0);
        QCOMPARE(summary.value(QStringLiteral("peak_force"))
                     .toObject()
                     .value(QStringLiteral("Element 1"))
                     .toObject()
                     .value(QStringLiteral("unit"))
                     .toString(),
                 QStringLiteral("kN m"));

        const QStringList lines = readLines(out + QStringLiteral("/steps.csv"));
        QCOMPARE(lines.size(), 302); // header + steps 0..300
        const QStringList header = lines.front().split(QLatin1Char(','));
        QCOMPARE(header.front(), QStringLiteral("time_s"));
        QVERIFY(header.contains(QStringLiteral("DOF 1_u_m")));
        QVERIFY(header.contains(QStringLiteral("Element 1_deformation_rad")));
        QVERIFY(header.contains(QStringLiteral("Element 1_force_kNm")));
        QVERIFY(header.contains(QStringLiteral("Element 3_force_kN")));
        QCOMPARE(lines.back().split(QLatin1Char(',')).size(), header.size());
        QCOMPARE(lines.back().split(QLatin1Char(',')).front().toDouble(), 3.0);

        const QStringList pngs = {
            QStringLiteral("hysteresis_Element_1.png"), QStringLiteral("hysteresis_Element_2.png"),
            QStringLiteral("displacement.png"), QStringLiteral("ground_motion.png"),
            QStringLiteral("parameters.png")}; // updating runs: the identified parameters
        for (const QString& name : pngs) {
            QImage image(out + QLatin1Char('/') + name);
            QVERIFY2(!image.isNull(), qPrintable(name));
            QVERIFY(image.width() >= 400 && image.height() >= 300);
            QSet<QRgb> colours;
            qsizetype inked = 0;
            for (int y = 0; y < image.height(); y += 2)
                for (int x = 0; x < image.width(); x += 2) {
                    const QRgb c = image.pixel(x, y);
                    colours.insert(c & 0xF0F0F0); // coarse: ignore antialiasing shades
                    inked += c != qRgb(255, 255, 255);
                }
            QVERIFY2(colours.size() >= 4, qPrintable(name));
            QVERIFY2(inked > image.width() * image.height() / 400, qPrintable(name));
        }
        // Element 3 is elastic: no hysteresis plot for it.
        QVERIFY(!QFile::exists(out + QStringLiteral("/hysteresis_Element_3.png")));
    }

    // Issue 27 item 2: steps.csv only up to 200 values a row unless --csv all (none: never);
    // --compress writes a smaller record holding the same values (hsmu export of both).
    void csvModesAndCompressedRecord() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const auto run = [&](const QString& name, const QStringList& extra) {
            return hsmu(QStringList{QStringLiteral("run"), QStringLiteral("shear-building-40"),
                                    QStringLiteral("--duration"), QStringLiteral("0.05"),
                                    QStringLiteral("--out"), dir.filePath(name)} +
                        extra);
        };
        // 40 storeys: 2 + 3 x 40 DOF + 2 x 40 element values = 202 a row.
        const Result automatic = run(QStringLiteral("auto"), {});
        QVERIFY2(automatic.exitCode == 0, qPrintable(report(automatic)));
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("auto/steps.csv"))));
        QVERIFY2(automatic.err.contains(QStringLiteral("202 columns")),
                 qPrintable(automatic.err));
        const Result all = run(QStringLiteral("all"), {QStringLiteral("--csv"),
                                                       QStringLiteral("all")});
        QVERIFY2(all.exitCode == 0, qPrintable(report(all)));
        const QStringList lines = readLines(dir.filePath(QStringLiteral("all/steps.csv")));
        QCOMPARE(lines.size(), 52); // header + steps 0..50
        QCOMPARE(lines.front().split(QLatin1Char(',')).size(), 202);
        const Result none = hsmu({QStringLiteral("run"), QStringLiteral("sdof-bouc-wen"),
                                  QStringLiteral("--duration"), QStringLiteral("0.5"),
                                  QStringLiteral("--csv"), QStringLiteral("none"),
                                  QStringLiteral("--out"), dir.filePath(QStringLiteral("none"))});
        QVERIFY2(none.exitCode == 0, qPrintable(report(none)));
        QVERIFY(!QFile::exists(dir.filePath(QStringLiteral("none/steps.csv"))));
        QVERIFY(QFile::exists(dir.filePath(QStringLiteral("none/record.h5"))));

        const Result packed = run(QStringLiteral("packed"), {QStringLiteral("--compress"),
                                                             QStringLiteral("4")});
        QVERIFY2(packed.exitCode == 0, qPrintable(report(packed)));
        const qint64 plain = QFileInfo(dir.filePath(QStringLiteral("auto/record.h5"))).size();
        const qint64 small = QFileInfo(dir.filePath(QStringLiteral("packed/record.h5"))).size();
        QVERIFY2(small < plain, qPrintable(QStringLiteral("%1 vs %2").arg(small).arg(plain)));
        for (const QString& name : {QStringLiteral("auto"), QStringLiteral("packed")}) {
            const Result e = hsmu({QStringLiteral("export"),
                                   dir.filePath(name + QStringLiteral("/record.h5")),
                                   QStringLiteral("--csv"), dir.filePath(name + "-csv")});
            QVERIFY2(e.exitCode == 0, qPrintable(report(e)));
        }
        for (const QString& file : {QStringLiteral("dofs.csv"), QStringLiteral("elements.csv")}) {
            const QStringList a = readLines(dir.filePath(QStringLiteral("auto-csv/") + file));
            QVERIFY(a.size() == 52);
            QCOMPARE(readLines(dir.filePath(QStringLiteral("packed-csv/") + file)), a);
        }

        for (const QStringList& bad : {QStringList{QStringLiteral("--csv"), QStringLiteral("some")},
                                       QStringList{QStringLiteral("--compress"),
                                                   QStringLiteral("12")}}) {
            const Result r = run(QStringLiteral("bad"), bad);
            QCOMPARE(r.exitCode, 1);
            QVERIFY2(r.err.contains(bad.front() + QStringLiteral(": expected")), qPrintable(r.err));
        }
    }

    void malformedConfigNamesFileAndField() {
        QTemporaryDir dir;
        QJsonObject doc = preset(QStringLiteral("paper-condition-3"));
        QVERIFY(!doc.isEmpty());
        QJsonObject structure = doc.value(QStringLiteral("structure")).toObject();
        QJsonArray elements = structure.value(QStringLiteral("elements")).toArray();
        QJsonObject e2 = elements.at(1).toObject();
        e2.insert(QStringLiteral("heigth"), e2.take(QStringLiteral("height")));
        elements.replace(1, e2);
        structure.insert(QStringLiteral("elements"), elements);
        doc.insert(QStringLiteral("structure"), structure);
        const QString path = writeJson(dir, QStringLiteral("typo.json"), doc);
        const Result r = hsmu({QStringLiteral("run"), path, QStringLiteral("--out"),
                               dir.filePath(QStringLiteral("out"))});
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("typo.json")), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("heigth")), qPrintable(r.err));
        QVERIFY(!r.err.contains(QStringLiteral("internal error")));
    }

    void tinySpecimenLimitHoldsWithExitCode2() {
        QTemporaryDir dir;
        QJsonObject doc = preset(QStringLiteral("paper-condition-3"));
        QJsonObject structure = doc.value(QStringLiteral("structure")).toObject();
        QJsonArray elements = structure.value(QStringLiteral("elements")).toArray();
        QJsonObject e1 = elements.at(0).toObject();
        QJsonObject limits = e1.value(QStringLiteral("limits")).toObject();
        limits.insert(QStringLiteral("deformation"), 0.0005);
        e1.insert(QStringLiteral("limits"), limits);
        elements.replace(0, e1);
        structure.insert(QStringLiteral("elements"), elements);
        doc.insert(QStringLiteral("structure"), structure);
        const QString path = writeJson(dir, QStringLiteral("tiny.json"), doc);
        const QString out = dir.filePath(QStringLiteral("out"));
        const Result r = hsmu({QStringLiteral("run"), path, QStringLiteral("--out"), out});
        QVERIFY2(r.exitCode == 2, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("Element 1")), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("target deformation")), qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("limit 0.0005")), qPrintable(r.err));
        // Outputs hold every committed step.
        const QJsonObject summary = readJson(out + QStringLiteral("/summary.json"));
        const int steps = summary.value(QStringLiteral("steps")).toInt();
        QVERIFY(steps > 0 && steps < summary.value(QStringLiteral("total_steps")).toInt());
        QCOMPARE(summary.value(QStringLiteral("state")).toString(), QStringLiteral("holding"));
        QVERIFY(summary.value(QStringLiteral("hold_reason"))
                    .toString()
                    .contains(QStringLiteral("target deformation")));
        QCOMPARE(readLines(out + QStringLiteral("/steps.csv")).size(), steps + 2);
    }

    // Issue 23 item 5: the summary reports each specimen's tracking. A pure 20 ms delay of the
    // virtual actuator (2 steps at dt 0.01 s): J1 and the frequency evaluation index's delay
    // find it (within 1 ms: the parabola and the band's phase), J2 and J3 equal the formulas
    // computed here from steps.csv's own columns; the ideal actuator tracks exactly.
    void summaryReportsEachSpecimensTracking() {
        QTemporaryDir dir;
        QJsonObject doc = preset(QStringLiteral("paper-condition-3"));
        QJsonObject structure = doc.value(QStringLiteral("structure")).toObject();
        QJsonArray elements = structure.value(QStringLiteral("elements")).toArray();
        QJsonObject e1 = elements.at(0).toObject();
        QJsonObject specimen = e1.value(QStringLiteral("specimen")).toObject();
        specimen.insert(QStringLiteral("actuator"),
                        QJsonObject{{QStringLiteral("type"), QStringLiteral("delay")}, {QStringLiteral("delay"), 0.02}});
        e1.insert(QStringLiteral("specimen"), specimen);
        elements.replace(0, e1);
        structure.insert(QStringLiteral("elements"), elements);
        doc.insert(QStringLiteral("structure"), structure);
        const QString path = writeJson(dir, QStringLiteral("delay.json"), doc);
        const QString out = dir.filePath(QStringLiteral("out"));
        Result r = hsmu({QStringLiteral("run"), path, QStringLiteral("--duration"), QStringLiteral("5"),
                         QStringLiteral("--out"), out});
        QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
        QVERIFY2(r.out.contains(QStringLiteral("tracking of Element 1")), qPrintable(r.out));
        const QJsonObject t = readJson(out + QStringLiteral("/summary.json"))
                                  .value(QStringLiteral("tracking")).toObject()
                                  .value(QStringLiteral("Element 1")).toObject();
        QVERIFY2(std::abs(t.value(QStringLiteral("J1_ms")).toDouble() - 20.0) < 1.0,
                 qPrintable(QString::number(t.value(QStringLiteral("J1_ms")).toDouble())));
        const double feiDelay = t.value(QStringLiteral("frequency_evaluation")).toObject()
                                    .value(QStringLiteral("delay_ms")).toDouble();
        QVERIFY2(std::abs(feiDelay - 20.0) < 1.0, qPrintable(QString::number(feiDelay)));
        QCOMPARE(t.value(QStringLiteral("tracking_indicator")).toObject().value(QStringLiteral("unit")).toString(),
                 QStringLiteral("rad^2"));
        const QStringList lines = readLines(out + QStringLiteral("/steps.csv"));
        const QStringList head = lines.front().split(QLatin1Char(','));
        const auto yCol = head.indexOf(QStringLiteral("Element 1_commanded_rad"));
        const auto xCol = head.indexOf(QStringLiteral("Element 1_deformation_rad"));
        QVERIFY(yCol > 0 && xCol > 0);
        double se = 0, sy = 0, pe = 0, py = 0;
        for (int i = 2; i < lines.size(); ++i) { // row 1 is the initial state (step 0)
            const QStringList v = lines[i].split(QLatin1Char(','));
            const double y = v[yCol].toDouble(), x = v[xCol].toDouble();
            se += (x - y) * (x - y);
            sy += y * y;
            pe = std::max(pe, std::abs(x - y));
            py = std::max(py, std::abs(y));
        }
        const double j2 = 100 * std::sqrt(se / sy), j3 = 100 * pe / py;
        QVERIFY(j2 > 1.0);
        QVERIFY2(std::abs(t.value(QStringLiteral("J2_percent")).toDouble() - j2) <= 1e-9 * j2,
                 qPrintable(QStringLiteral("%1 against %2").arg(t.value(QStringLiteral("J2_percent")).toDouble(), 0, 'g', 17).arg(j2, 0, 'g', 17)));
        QVERIFY(std::abs(t.value(QStringLiteral("J3_percent")).toDouble() - j3) <= 1e-9 * j3);

        const QString ideal = dir.filePath(QStringLiteral("ideal"));
        r = hsmu({QStringLiteral("run"), QStringLiteral("paper-condition-3"), QStringLiteral("--duration"),
                  QStringLiteral("2"), QStringLiteral("--csv"), QStringLiteral("none"), QStringLiteral("--out"), ideal});
        QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
        const QJsonObject exact = readJson(ideal + QStringLiteral("/summary.json"))
                                      .value(QStringLiteral("tracking")).toObject()
                                      .value(QStringLiteral("Element 1")).toObject();
        QCOMPARE(exact.value(QStringLiteral("J2_percent")).toDouble(), 0.0);
        QCOMPARE(exact.value(QStringLiteral("J1_ms")).toDouble(), 0.0);
    }

    void unstableStepIsRefused() {
        QTemporaryDir dir;
        const Result r = hsmu({QStringLiteral("run"), QStringLiteral("paper-condition-3"),
                               QStringLiteral("--out"), dir.path(), QStringLiteral("--dt"),
                               QStringLiteral("0.5")});
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("omega_max dt")), qPrintable(r.err));
    }

    void unknownPresetOrRecordIsAnError() {
        QTemporaryDir dir;
        Result r = hsmu({QStringLiteral("run"), QStringLiteral("no-such-preset"),
                         QStringLiteral("--out"), dir.path()});
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY(r.err.contains(QStringLiteral("paper-condition-3"))); // lists the presets
        r = hsmu({QStringLiteral("run"), QStringLiteral("sdof-bouc-wen"), QStringLiteral("--out"),
                  dir.path(), QStringLiteral("--ground-motion"),
                  dir.filePath(QStringLiteral("missing.AT2"))});
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("missing.AT2")), qPrintable(r.err));
    }

    void consoleScreenshotShowsTheRunningTest() {
        QTemporaryDir dir;
        const QString png = dir.filePath(QStringLiteral("console.png"));
        const Result r =
            hsmu({QStringLiteral("--start"), QStringLiteral("sdof-bouc-wen"),
                  QStringLiteral("--speed"), QStringLiteral("5"), QStringLiteral("--screenshot"),
                  png, QStringLiteral("--screenshot-after"), QStringLiteral("1.5")});
        QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
        const QImage image(png);
        QVERIFY(!image.isNull());
        QVERIFY(image.width() >= 800 && image.height() >= 500);
        // The specimen's loop is drawn in the first series colour (31, 119, 180).
        qsizetype blue = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                blue += std::abs(c.red() - 31) < 40 && std::abs(c.green() - 119) < 40 &&
                        std::abs(c.blue() - 180) < 40;
            }
        QVERIFY2(blue > 300, qPrintable(QString::number(blue)));
    }

    void materialElasticIsExact() {
        QTemporaryDir dir;
        const QString history = dir.filePath(QStringLiteral("history.csv"));
        QFile f(history);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("deformation\n0\n0.1\n-0.3333333333333333\n1e-7\n12.625\n-4.1\n");
        f.close();
        const Result r = hsmu({QStringLiteral("material"), QStringLiteral("--law"),
                               QStringLiteral("elastic"), QStringLiteral("--param"),
                               QStringLiteral("k=2"), QStringLiteral("--history"), history});
        QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
        QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 7);
        QCOMPARE(lines.front(), QStringLiteral("deformation,force,tangent"));
        const QList<double> expected{0, 0.1, -0.3333333333333333, 1e-7, 12.625, -4.1};
        for (int i = 1; i < lines.size(); ++i) {
            const QStringList v = lines[i].split(QLatin1Char(','));
            QCOMPARE(v.size(), 3);
            const double d = v[0].toDouble(), force = v[1].toDouble();
            QVERIFY(d == expected[i - 1]);
            QVERIFY2(force == 2.0 * d, qPrintable(lines[i]));
            QVERIFY(v[2].toDouble() == 2.0);
        }
        // --out writes the same CSV to a file.
        const QString csv = dir.filePath(QStringLiteral("out.csv"));
        const Result r2 =
            hsmu({QStringLiteral("material"), QStringLiteral("--law"), QStringLiteral("elastic"),
                  QStringLiteral("--param"), QStringLiteral("k=2"), QStringLiteral("--history"),
                  history, QStringLiteral("--out"), csv});
        QVERIFY2(r2.exitCode == 0, qPrintable(report(r2)));
        QCOMPARE(readLines(csv), lines);
    }

    void materialRateDependentLaw() {
        // mrDamper with the hysteresis off: force = c0 c1 / (c0 + c1) v + k1 u, the velocity
        // from --dt (or the history's time column); without either, an error naming the law.
        QTemporaryDir dir;
        const QString history = dir.filePath(QStringLiteral("h.csv"));
        QFile f(history);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("0.001\n0.003\n0.002\n");
        f.close();
        const QStringList law{QStringLiteral("material"), QStringLiteral("--law"),
                              QStringLiteral("mrDamper"), QStringLiteral("--param"),
                              QStringLiteral("alpha=0"), QStringLiteral("--param"),
                              QStringLiteral("c0=3"), QStringLiteral("--param"),
                              QStringLiteral("c1=6"), QStringLiteral("--param"),
                              QStringLiteral("k1=10"), QStringLiteral("--history"), history};
        Result r = hsmu(law);
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("mrDamper is rate-dependent")), qPrintable(r.err));
        r = hsmu(law + QStringList{QStringLiteral("--dt"), QStringLiteral("0.01")});
        QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
        const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 4);
        const QList<double> expected{10.0 * 0.001, 2.0 * 0.002 / 0.01 + 10.0 * 0.003,
                                     2.0 * -0.001 / 0.01 + 10.0 * 0.002};
        for (int i = 1; i < lines.size(); ++i) {
            const double force = lines[i].split(QLatin1Char(','))[1].toDouble();
            QVERIFY2(std::abs(force - expected[i - 1]) < 1e-12, qPrintable(lines[i]));
        }
        r = hsmu(law + QStringList{QStringLiteral("--dt"), QStringLiteral("-1")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("--dt")), qPrintable(r.err));
    }

    void materialErrorsAreClear() {
        QTemporaryDir dir;
        const QString history = dir.filePath(QStringLiteral("h.csv"));
        QFile f(history);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("0\n0.1\n");
        f.close();
        Result r = hsmu({QStringLiteral("material"), QStringLiteral("--law"),
                         QStringLiteral("bilinear"), QStringLiteral("--param"),
                         QStringLiteral("fyy=2"), QStringLiteral("--history"), history});
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        QVERIFY2(r.err.contains(QStringLiteral("fyy")), qPrintable(r.err));
        r = hsmu({QStringLiteral("material"), QStringLiteral("--law"), QStringLiteral("elastic"),
                  QStringLiteral("--param"), QStringLiteral("k"), QStringLiteral("--history"),
                  history});
        QCOMPARE(r.exitCode, 1);
        r = hsmu({QStringLiteral("material"), QStringLiteral("--law"), QStringLiteral("elastic"),
                  QStringLiteral("--history"), dir.filePath(QStringLiteral("nope.csv"))});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("nope.csv")), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCommandLine)
#include "TestCommandLine.moc"
