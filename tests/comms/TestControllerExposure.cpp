// hsmu-controller beyond loopback (issue 26, D3 and "safe defaults"): without TLS the native
// protocol is plaintext, so a non-loopback --bind is refused (exit 2, with the reason and TLS
// named as the way out; tests/comms/TestTlsRefusals.cpp starts one with TLS) unless
// --insecure-plaintext says the risk is taken, which is then said at start; the OpenFresco
// protocols (which carry no security at all) warn on a non-loopback address; a token file
// that other users can read is refused. Real processes throughout.
#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "RawClient.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;

namespace {

/// Run hsmu-controller to its exit (it must exit by itself); its exit code and its output.
std::pair<int, QString> runToExit(const QStringList& args) {
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(QStringLiteral(HSMU_CONTROLLER_EXE), args);
    if (!p.waitForFinished(20000)) {
        p.kill();
        p.waitForFinished(5000);
        return {-1, "did not exit: " + QString::fromUtf8(p.readAll())};
    }
    return {p.exitCode(), QString::fromUtf8(p.readAll())};
}

} // namespace

class TestControllerExposure : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_config;

    QString tokenFile(const QString& name, QFile::Permissions mode) {
        const QString path = m_dir.filePath(name);
        std::ofstream(path.toStdString()) << "a-long-random-token\n";
        QFile::setPermissions(path, mode);
        return path;
    }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_config = QString::fromStdString(writeConfig(m_dir.path(), "c3.json", condition3(0.2)));
    }

    void nonLoopbackNativeIsRefused() {
        for (const QString bind : {"0.0.0.0", "::"}) {
            const auto [code, out] =
                runToExit({"--config", m_config, "--port", "0", "--pace", "fast", "--bind", bind});
            QVERIFY2(code == 2, qPrintable(QString::number(code) + ": " + out));
            QVERIFY2(out.contains("not a loopback address") && out.contains("plaintext") &&
                         out.contains("--insecure-plaintext") &&
                         out.contains("Use TLS (--tls-certificate"),
                     qPrintable(out));
            QVERIFY2(!out.contains("listening on"), qPrintable(out));
        }
    }

    void insecurePlaintextStartsAndSaysSo() {
        ControllerProcess ctl({"--config", m_config, "--pace", "fast", "--bind", "0.0.0.0",
                               "--insecure-plaintext", "--token-file",
                               tokenFile("ok-token", QFile::ReadOwner | QFile::WriteOwner)});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c; // 0.0.0.0 includes the loopback interface
        QVERIFY(c.connect(ctl.port()));
        QVERIFY2(c.hello(5, "a-long-random-token"), qPrintable(ctl.log()));
        ctl.stop();
        QVERIFY2(ctl.log().contains("--insecure-plaintext") &&
                     ctl.log().contains("in clear on 0.0.0.0"),
                 qPrintable(ctl.log()));
    }

    void loopbackNeedsNoFlag() {
        for (const QString bind : {"127.0.0.1", "::1"}) {
            ControllerProcess ctl({"--config", m_config, "--pace", "fast", "--bind", bind});
            QVERIFY2(ctl.start(), qPrintable(ctl.log()));
            ctl.stop();
            QVERIFY2(!ctl.log().contains("plaintext"), qPrintable(ctl.log()));
        }
    }

    void openFrescoWarnsBeyondLoopback() {
        ControllerProcess ctl(
            {"--config", m_config, "--pace", "fast", "--protocol", "simapp", "--bind", "0.0.0.0"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        ctl.stop();
        QVERIFY2(ctl.log().contains("warning") && ctl.log().contains("no security") &&
                     ctl.log().contains("docs/security.md"),
                 qPrintable(ctl.log()));
    }

    void tokenFileReadableByOthersIsRefused() {
        for (const auto mode : {QFile::ReadOwner | QFile::WriteOwner | QFile::ReadOther,
                                QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup}) {
            const QString path = tokenFile("open-token", mode);
            const auto [code, out] = runToExit(
                {"--config", m_config, "--port", "0", "--pace", "fast", "--token-file", path});
            QVERIFY2(code != 0 && out.contains("readable by other users") &&
                         out.contains("chmod 600"),
                     qPrintable(QString::number(code) + ": " + out));
            QVERIFY2(!out.contains("listening on"), qPrintable(out));
        }
    }
};

QTEST_GUILESS_MAIN(TestControllerExposure)
#include "TestControllerExposure.moc"
