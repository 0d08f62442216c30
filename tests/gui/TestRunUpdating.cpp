// `hsmu run` with online model updating (the real binary via QProcess): summary.json's
// "updating" block, the identified-parameter columns of steps.csv, the human summary, and
// --approval overriding the configuration's headless decision.

#include "CliTestSupport.h"

#include <QJsonArray>
#include <QTemporaryDir>

#include "core/record/RecordReader.h"
#include <QtTest>

#include <cmath>

using namespace clitest;

namespace {

const QStringList kParameters{QStringLiteral("k0"),      QStringLiteral("alpha"),
                              QStringLiteral("n"),       QStringLiteral("beta"),
                              QStringLiteral("gamma"),   QStringLiteral("deltaNu"),
                              QStringLiteral("deltaEta")};

/// paper-condition-3 with the reporter's onApproval policy, written into dir.
QString onApprovalConfig(const QTemporaryDir& dir) {
    QJsonObject doc =
        readJson(QStringLiteral(HSMU_SOURCE_DIR "/resources/presets/paper-condition-3.json"));
    QJsonObject updating = doc.value(QStringLiteral("updating")).toObject();
    QJsonObject reporter = updating.value(QStringLiteral("reporter")).toObject();
    reporter.insert(QStringLiteral("policy"), QStringLiteral("onApproval"));
    updating.insert(QStringLiteral("reporter"), reporter);
    doc.insert(QStringLiteral("updating"), updating);
    const QString path = dir.filePath(QStringLiteral("approval.json"));
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        f.write(QJsonDocument(doc).toJson());
    return path;
}

QJsonObject updatingBlock(const QString& outDir) {
    return readJson(outDir + QStringLiteral("/summary.json"))
        .value(QStringLiteral("updating"))
        .toObject();
}

} // namespace

class TestRunUpdating : public QObject {
    Q_OBJECT
private slots:
    void summaryAndCsvCarryTheIdentifiedParameters() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString out = dir.filePath(QStringLiteral("out"));
        const Result r =
            clitest::hsmu({QStringLiteral("run"), QStringLiteral("paper-condition-3"),
                  QStringLiteral("--duration"), QStringLiteral("3"), QStringLiteral("--out"), out});
        QVERIFY2(r.exitCode == 0, qPrintable(report(r)));

        const QJsonObject u = updatingBlock(out);
        QVERIFY2(!u.isEmpty(), "summary.json has no updating block");
        QCOMPARE(u.value(QStringLiteral("specimen")).toString(), QStringLiteral("Element 1"));
        QVERIFY(!u.value(QStringLiteral("method")).toString().isEmpty());
        const QJsonObject params = u.value(QStringLiteral("parameters")).toObject();
        const QJsonObject stddev = u.value(QStringLiteral("standard_deviations")).toObject();
        QCOMPARE(params.size(), 7);
        QCOMPARE(stddev.size(), 7);
        for (const QString& p : kParameters) {
            QVERIFY2(params.value(p).isDouble(), qPrintable(p));
            QVERIFY2(stddev.value(p).toDouble(-1.0) >= 0.0, qPrintable(p));
        }
        QVERIFY(u.value(QStringLiteral("applied_updates")).toInt() > 0);
        QCOMPARE(u.value(QStringLiteral("pending_proposals")).toInt(-1), 0);

        // The HDF5 record holds every step, and its final estimate is the summary's.
        hsmu::RecordReader record((out + QStringLiteral("/record.h5")).toStdString());
        QCOMPARE(record.rows(), 301);
        const auto& rd = record.data();
        QVERIFY(rd.layout.updating.has_value());
        QCOMPARE(int(rd.parameters.cols()), 7);
        for (int i = 0; i < 7; ++i) {
            const QString name = QString::fromStdString(rd.layout.updating->parameters.at(i));
            QVERIFY2(std::abs(rd.parameters(300, i) - params.value(name).toDouble()) <=
                         1e-12 * std::abs(rd.parameters(300, i)),
                     qPrintable(name));
        }
        QVERIFY(std::isfinite(u.value(QStringLiteral("final_fit_error")).toDouble(NAN)));
        QVERIFY(readJson(out + QStringLiteral("/summary.json"))
                    .value(QStringLiteral("alarms"))
                    .isArray());

        const QStringList lines = readLines(out + QStringLiteral("/steps.csv"));
        QCOMPARE(lines.size(), 302);
        const QStringList header = lines.front().split(QLatin1Char(','));
        for (const QString& p : kParameters) {
            QVERIFY2(header.contains(QStringLiteral("param_") + p), qPrintable(p));
            QVERIFY2(header.contains(QStringLiteral("std_") + p), qPrintable(p));
        }
        QVERIFY(header.contains(QStringLiteral("aux_force_kNm")));
        QCOMPARE(header.back(), QStringLiteral("fit_error"));
        const QStringList last = lines.back().split(QLatin1Char(','));
        QCOMPARE(last.size(), header.size());
        // The last row's parameters are the summary's final values.
        for (const QString& p : kParameters) {
            const double csv = last[header.indexOf(QStringLiteral("param_") + p)].toDouble();
            QVERIFY(std::abs(csv - params.value(p).toDouble()) <=
                    1e-8 * std::max(1.0, std::abs(csv)));
        }

        // The human summary: the identified parameters with their standard deviations.
        QVERIFY2(r.out.contains(QStringLiteral("identified parameters of Element 1")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("k0")) && r.out.contains(QStringLiteral("±")),
                 qPrintable(r.out));
    }

    void runWithoutUpdatingHasNoBlock() {
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("out"));
        const Result r =
            clitest::hsmu({QStringLiteral("run"), QStringLiteral("paper-condition-2"),
                  QStringLiteral("--duration"), QStringLiteral("1"), QStringLiteral("--out"), out});
        QVERIFY2(r.exitCode == 0, qPrintable(report(r)));
        QVERIFY(
            !readJson(out + QStringLiteral("/summary.json")).contains(QStringLiteral("updating")));
        const QString header = readLines(out + QStringLiteral("/steps.csv")).value(0);
        QVERIFY2(!header.contains(QStringLiteral("param_")), qPrintable(header));
    }

    void approvalOverridesTheConfiguration() {
        QTemporaryDir dir;
        const QString config = onApprovalConfig(dir);
        auto run = [&](const QString& mode) {
            const QString out = dir.filePath(mode);
            QStringList args{QStringLiteral("run"),        config,
                             QStringLiteral("--duration"), QStringLiteral("2"),
                             QStringLiteral("--out"),      out};
            if (!mode.isEmpty())
                args << QStringLiteral("--approval") << mode;
            const Result r = clitest::hsmu(args);
            return std::make_pair(r, updatingBlock(out));
        };
        const auto [manual, m] = run(QStringLiteral("manual"));
        QVERIFY2(manual.exitCode == 0, qPrintable(report(manual)));
        QCOMPARE(m.value(QStringLiteral("applied_updates")).toInt(-1), 0);
        QVERIFY(m.value(QStringLiteral("pending_proposals")).toInt() > 0);

        const auto [approve, a] = run(QStringLiteral("approveAll"));
        QVERIFY2(approve.exitCode == 0, qPrintable(report(approve)));
        QVERIFY(a.value(QStringLiteral("applied_updates")).toInt() > 0);
        QCOMPARE(a.value(QStringLiteral("pending_proposals")).toInt(-1), 0);

        const auto [reject, x] = run(QStringLiteral("rejectAll"));
        QVERIFY2(reject.exitCode == 0, qPrintable(report(reject)));
        QCOMPARE(x.value(QStringLiteral("applied_updates")).toInt(-1), 0);
        QCOMPARE(x.value(QStringLiteral("pending_proposals")).toInt(-1), 0);

        const Result bad = clitest::hsmu({QStringLiteral("run"), config, QStringLiteral("--out"),
                                 dir.filePath(QStringLiteral("bad")), QStringLiteral("--approval"),
                                 QStringLiteral("sometimes")});
        QVERIFY2(bad.exitCode == 1, qPrintable(report(bad)));
        QVERIFY2(bad.err.contains(QStringLiteral("--approval")), qPrintable(bad.err));
    }
};

QTEST_GUILESS_MAIN(TestRunUpdating)
#include "TestRunUpdating.moc"
