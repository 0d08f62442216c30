// The hsmu executable on malformed inputs (issue 14): each case ends with exit code 1 and a
// message on stderr naming the file (and the field or line), never std::bad_alloc, a crash,
// a hang, raw binary bytes or a "finished" run of 0 steps. The library-level corpus is
// test_config_malformed_inputs; this checks the CLI's error paths end to end.
#include "CliTestSupport.h"

#include <QTemporaryDir>
#include <QtTest>

#include <QDir>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <random>

using namespace clitest;

namespace {

QString preset() {
    return QStringLiteral(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json";
}

QString write(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
    const QString path = dir.filePath(name);
    std::ofstream(path.toStdString(), std::ios::binary) << bytes.toStdString();
    return path;
}

QByteArray readAll(const QString& path) {
    QFile f(path);
    f.open(QIODevice::ReadOnly);
    return f.readAll();
}

/// Every CSV file of an export folder, by name.
QMap<QString, QByteArray> exportedFiles(const QString& dir) {
    QMap<QString, QByteArray> files;
    for (const QString& name : QDir(dir).entryList({"*.csv"}, QDir::Files))
        files[name] = readAll(QDir(dir).filePath(name));
    return files;
}

QByteArray presetText() {
    QFile f(preset());
    f.open(QIODevice::ReadOnly);
    return f.readAll();
}

} // namespace

class TestMalformedCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void cases_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("expected"); // comma-separated parts of stderr
        const QString out = m_dir.filePath("out");
        QByteArray overflow = presetText();
        overflow.replace("\"dt\": 0.01", "\"dt\": 1e999");
        const QString huge = write(m_dir, "huge.json", overflow);
        QTest::newRow("1e999") << QStringList{"run", huge, "--out", out} << "huge.json line";
        QTest::newRow("--dt 1e-300")
            << QStringList{"run", preset(), "--out", out, "--dt", "1e-300"} << "steps";
        const QString at2 =
            write(m_dir, "big.AT2", "PEER\nrecord\nUNITS OF G\nNPTS= 3, DT= 1e300 SEC\n0 1 0\n");
        QTest::newRow("AT2 DT 1e300")
            << QStringList{"run", preset(), "--out", out, "--ground-motion", at2}
            << "big.AT2 line 4,DT";
        const QString bin = write(m_dir, "bin.AT2", QByteArray("PEER\n\x00\xff\x1b[2J\n", 11));
        QTest::newRow("binary AT2")
            << QStringList{"run", preset(), "--out", out, "--ground-motion", bin}
            << "bin.AT2,not a text file";
        QTest::newRow("record /dev/zero")
            << QStringList{"export", "/dev/zero", "--csv", out} << "/dev/zero";
        const QString bad = write(m_dir, "bad.h5", QByteArray(4096, '\xff'));
        QTest::newRow("record of 0xff") << QStringList{"export", bad, "--csv", out} << "bad.h5";
    }
    void cases() {
        QFETCH(QStringList, args);
        QFETCH(QString, expected);
        const Result r = hsmu(args, 60000);
        QVERIFY2(r.exitCode == 1, qPrintable(report(r)));
        for (const QString& part : expected.split(','))
            QVERIFY2(r.err.contains(part), qPrintable(report(r) + "\nlacks " + part));
        QVERIFY2(!r.err.contains("bad_alloc") && !r.err.contains("\x1b"), qPrintable(report(r)));
    }

    // The record fuzz of test_record_bad_files, end to end through `hsmu export`: truncated,
    // byte-flipped and zeroed (64-byte block) copies of a real record at seeded offsets. Each
    // ends with exit 1 and a message naming the copy, or (damage in bytes the record does not
    // use) exit 0 with exactly the original's CSV files. Never a crash, a hang (the runner's
    // 60 s bound) or different data.
    void damagedRecordCopies() {
        const QString run = m_dir.filePath("fuzz-run");
        const Result made = hsmu({"run", preset(), "--out", run, "--duration", "0.5"});
        QVERIFY2(made.exitCode == 0, qPrintable(report(made)));
        const QString good = run + "/record.h5";
        const QString goodCsv = m_dir.filePath("fuzz-good");
        const Result exported = hsmu({"export", good, "--csv", goodCsv});
        QVERIFY2(exported.exitCode == 0, qPrintable(report(exported)));
        const QMap<QString, QByteArray> original = exportedFiles(goodCsv);
        QVERIFY(!original.isEmpty());
        const QByteArray bytes = readAll(good);
        std::mt19937_64 rng(1416);
        std::uniform_int_distribution<qsizetype> offset(0, bytes.size() - 1);
        const char* classes[] = {"truncated", "flipped", "zeroed"};
        int failed[3] = {0, 0, 0};
        for (int k = 0; k < 18; ++k) {
            const int c = k % 3;
            QByteArray b = bytes;
            const qsizetype at = offset(rng);
            if (c == 0)
                b.truncate(at);
            else if (c == 1)
                b[at] = char(b[at] ^ (1 << (k % 8)));
            else
                std::memset(b.data() + at, 0, std::min<qsizetype>(64, b.size() - at));
            const QString copy = write(m_dir, QStringLiteral("fuzz-%1.h5").arg(k), b);
            const QString csv = m_dir.filePath(QStringLiteral("fuzz-csv-%1").arg(k));
            const Result r = hsmu({"export", copy, "--csv", csv}, 60000);
            const QString what = QStringLiteral("%1 at byte %2: ").arg(classes[c]).arg(at);
            if (r.exitCode == 0) {
                QVERIFY2(exportedFiles(csv) == original,
                         qPrintable(what + "exit 0 with different CSV files"));
            } else {
                QVERIFY2(r.exitCode == 1, qPrintable(what + report(r)));
                QVERIFY2(r.err.contains(QStringLiteral("fuzz-%1.h5").arg(k)),
                         qPrintable(what + report(r)));
                ++failed[c];
            }
        }
        QCOMPARE(failed[0], 6); // every truncation is noticed
    }
};

QTEST_GUILESS_MAIN(TestMalformedCli)
#include "TestMalformedCli.moc"
