// The hsmu executable on malformed inputs (issue 14): each case ends with exit code 1 and a
// message on stderr naming the file (and the field or line), never std::bad_alloc, a crash,
// a hang, raw binary bytes or a "finished" run of 0 steps. The library-level corpus is
// test_config_malformed_inputs; this checks the CLI's error paths end to end.
#include "CliTestSupport.h"

#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

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
};

QTEST_GUILESS_MAIN(TestMalformedCli)
#include "TestMalformedCli.moc"
