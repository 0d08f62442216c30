// Revocation by the CA's CRL (issue 26 item 3; docs/security.md "Rotation and revocation"),
// against real hsmu-controller processes: a certificate the lab CA revoked with
// scripts/hsmu-certs.sh revoke is refused by a controller started with --tls-crl once SIGHUP
// re-read the CRL (no restart; another certificate of the CA still admitted), a CRL of
// another CA refuses every certificate of the lab CA (no CRL of its issuer: fail closed), the
// console's "crl" refuses a revoked controller certificate, and bad --tls-crl files stop the
// controller at start with the reason. SIGHUP to a controller without TLS changes nothing and
// says so (it used to end the process).
#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "TlsFixture.h"

#include <QFile>
#include <QtTest>

#include <csignal>
#include <fstream>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;
using namespace tlsfixture;

class TestTlsCrl : public QObject {
    Q_OBJECT
    TlsFixture m_tls;
    QTemporaryDir m_dir;
    QString m_config, m_token;

    QStringList args(const QStringList& tls) const {
        return QStringList{"--config",     m_config, "--pace",         "fast",
                           "--token-file", m_token,  "--no-state-file"} +
               tls;
    }
    QStringList withCrl(const QString& crl) const {
        return args(m_tls.controllerArgs() << "--tls-crl" << crl);
    }
    /// scripts/hsmu-certs.sh with args; QVERIFY-style failure text in *out.
    static bool certs(const QStringList& a, QString* out) { return TlsFixture::certs(a, out); }

    static void expectAdmitted(ControllerProcess& ctl, int sessions) {
        ctl.stop();
        QVERIFY2(ctl.log().contains(QStringLiteral("%1 sessions admitted").arg(sessions)),
                 qPrintable(ctl.log()));
    }

    /// hsmu-controller with these arguments exits at once: its exit code and output.
    static std::pair<int, QString> startFails(const QStringList& a) {
        QProcess p;
        p.setProcessChannelMode(QProcess::MergedChannels);
        p.start(QStringLiteral(HSMU_CONTROLLER_EXE), a + QStringList{"--port", "0"});
        if (!p.waitForFinished(20000)) {
            p.kill();
            p.waitForFinished(5000);
            return {-1, QStringLiteral("still running")};
        }
        return {p.exitCode(), QString::fromUtf8(p.readAll())};
    }

private slots:
    void initTestCase() {
        QString log;
        QVERIFY2(m_tls.make(&log), qPrintable(log));
        QVERIFY(m_dir.isValid());
        m_config = QString::fromStdString(writeConfig(m_dir.path(), "c3.json", condition3(0.5)));
        m_token = m_dir.filePath("token");
        std::ofstream(m_token.toStdString()) << kToken << "\n";
        QFile::setPermissions(m_token, QFile::ReadOwner | QFile::WriteOwner);
    }

    void revokedByCrlAfterSighup() {
        QString out;
        // A laptop's certificate of the lab CA, and the CA's CRL with nothing revoked yet.
        QVERIFY2(certs({"issue", "laptop", "--ca", m_tls.path("ca"), "--out", m_tls.path("certs")},
                       &out),
                 qPrintable(out));
        QVERIFY2(certs({"crl", "--ca", m_tls.path("ca")}, &out), qPrintable(out));
        QVERIFY2(out.contains("0 revoked"), qPrintable(out));
        const QString crl = m_tls.path("ca/crl.pem");
        ControllerProcess ctl(withCrl(crl));
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const Attempt before = helloOver("127.0.0.1", ctl.port(), m_tls.console("laptop"));
        QVERIFY2(before.admitted, qPrintable(before.error + "\n" + ctl.log()));

        QVERIFY2(certs({"revoke", m_tls.cert("laptop"), "--ca", m_tls.path("ca")}, &out),
                 qPrintable(out));
        QVERIFY2(out.contains("1 revoked"), qPrintable(out));
        // Before SIGHUP the controller still holds the old CRL: admitted (the reload is what
        // makes the revocation count, so the test sees the CRL's effect, not a stale file).
        const Attempt stale = helloOver("127.0.0.1", ctl.port(), m_tls.console("laptop"));
        QVERIFY2(stale.admitted, qPrintable(stale.error + "\n" + ctl.log()));
        QCOMPARE(::kill(pid_t(ctl.pid()), SIGHUP), 0);
        QVERIFY2(ctl.waitForLog("SIGHUP: TLS files reloaded (0 pins, 0 revoked, CRL " + crl + ")",
                                20000),
                 qPrintable(ctl.log()));

        const Attempt after = helloOver("127.0.0.1", ctl.port(), m_tls.console("laptop"));
        QVERIFY(!after.admitted);
        QVERIFY2(after.error.contains("ended the TLS session") && after.error.contains("revoked"),
                 qPrintable(after.error));
        QVERIFY2(ctl.waitForLog("(its certificate: certificate revoked)", 20000),
                 qPrintable(ctl.log()));
        // Another certificate of the same CA, not in the CRL: still admitted.
        const Attempt other = helloOver("127.0.0.1", ctl.port(), m_tls.console());
        QVERIFY2(other.admitted, qPrintable(other.error + "\n" + ctl.log()));
        expectAdmitted(ctl, 3);
    }

    void crlOfAnotherCaRefusesEveryone() {
        QString out;
        QVERIFY2(certs({"crl", "--ca", m_tls.path("rogue")}, &out), qPrintable(out));
        ControllerProcess ctl(withCrl(m_tls.path("rogue/crl.pem")));
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const Attempt a = helloOver("127.0.0.1", ctl.port(), m_tls.console());
        QVERIFY(!a.admitted);
        QVERIFY2(a.error.contains("ended the TLS session"), qPrintable(a.error));
        QVERIFY2(ctl.waitForLog("unable to get certificate CRL", 20000), qPrintable(ctl.log()));
        expectAdmitted(ctl, 0);
    }

    void consoleCrlRefusesARevokedController() {
        // A second controller certificate, revoked by the CA: the console's "crl" refuses it.
        QString out;
        QVERIFY2(certs({"issue", "old-controller", "--ca", m_tls.path("ca"), "--ip", "127.0.0.1",
                        "--out", m_tls.path("certs")},
                       &out),
                 qPrintable(out));
        QVERIFY2(certs({"revoke", m_tls.cert("old-controller"), "--ca", m_tls.path("ca")}, &out),
                 qPrintable(out));
        QStringList a = m_tls.controllerArgs();
        a[a.indexOf("--tls-certificate") + 1] = m_tls.cert("old-controller");
        a[a.indexOf("--tls-key") + 1] = m_tls.key("old-controller");
        ControllerProcess ctl(args(a));
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        TlsSpec console = m_tls.console();
        // Without the CRL the console trusts it (the CA signed it) ...
        const Attempt trusting = helloOver("127.0.0.1", ctl.port(), console);
        QVERIFY2(trusting.admitted, qPrintable(trusting.error + "\n" + ctl.log()));
        // ... with it, refused before any hello.
        console.crl = m_tls.path("ca/crl.pem").toStdString();
        const Attempt refused = helloOver("127.0.0.1", ctl.port(), console);
        QVERIFY(!refused.admitted);
        QVERIFY2(refused.error.contains("certificate revoked"), qPrintable(refused.error));
        expectAdmitted(ctl, 1);
    }

    void badCrlFilesStopTheStart() {
        // Not a CRL (a certificate): exit 1, as a CA file that does not load; a missing file
        // and a CRL without a CA to check it with: exit 2, refused options.
        auto [code, out] = startFails(withCrl(m_tls.cert("console")));
        QCOMPARE(code, 1);
        QVERIFY2(out.contains("no CRL in the file"), qPrintable(out));
        std::tie(code, out) = startFails(withCrl(m_tls.path("nothing.pem")));
        QCOMPARE(code, 2);
        QVERIFY2(out.contains("nothing.pem: cannot read the file"), qPrintable(out));
        QString fp;
        QVERIFY2(certs({"fingerprint", m_tls.cert("console")}, &fp), qPrintable(fp));
        const QString pins = m_dir.filePath("pins.txt");
        std::ofstream(pins.toStdString()) << fp.toStdString() << "\n";
        std::tie(code, out) = startFails(args(
            {"--tls-certificate", m_tls.cert("controller"), "--tls-key", m_tls.key("controller"),
             "--tls-pins", pins, "--tls-crl", m_tls.path("ca/crl.pem")}));
        QCOMPARE(code, 2);
        QVERIFY2(out.contains("needs the CA that signs it"), qPrintable(out));
    }

    void sighupWithoutTlsChangesNothing() {
        ControllerProcess ctl(args({}));
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        QCOMPARE(::kill(pid_t(ctl.pid()), SIGHUP), 0);
        // Sent right after the "listening" line: the handler is in place by then.
        QVERIFY2(ctl.waitForLog("SIGHUP: no TLS files to reload", 20000), qPrintable(ctl.log()));
        QVERIFY(ctl.running());
        const Attempt a = helloOver("127.0.0.1", ctl.port(), std::nullopt);
        QVERIFY2(a.admitted, qPrintable(a.error + "\n" + ctl.log()));
        expectAdmitted(ctl, 1);
    }
};

QTEST_GUILESS_MAIN(TestTlsCrl)
#include "TestTlsCrl.moc"
