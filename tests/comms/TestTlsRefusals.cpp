// tls:// links refused (issue 26, "Acceptance"): against a real hsmu-controller started with
// TLS 1.3 and client certificates (certificates made by scripts/hsmu-certs.sh), the console's
// LinkClient (or, for a client with no certificate at all, a bare Asio TLS client) is refused
// with a clear message on both ends and nothing admitted ("0 sessions admitted" in the
// controller's final statistics line): no client certificate, a certificate from another CA,
// an expired one, one revoked and SIGHUP sent (an admitted session with it is closed too), a
// plaintext client on the TLS port, a TLS client on a plaintext port, the right certificate
// with a wrong token, a controller certificate that does not name the host dialled, a key
// file others can read. The right certificate (CA or pinned) is admitted, the control case.
#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "TlsFixture.h"

#include "comms/link/LinkClient.h"
#include "comms/protocol/FrameCodec.h"

#include <QFile>
#include <QtTest>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/asio/write.hpp>

#include <csignal>
#include <fstream>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;
using namespace tlsfixture;

namespace {

/// A TLS client with no certificate of its own (it trusts the lab CA): what the controller
/// answers to its hello, or the error that ended it.
QString helloWithoutCertificate(quint16 port, const std::string& ca) {
    namespace asio = boost::asio;
    asio::io_context io;
    asio::ssl::context ctx(asio::ssl::context::tls_client);
    ctx.load_verify_file(ca);
    ctx.set_verify_mode(asio::ssl::verify_peer);
    asio::ssl::stream<asio::ip::tcp::socket> s(io, ctx);
    boost::system::error_code ec;
    s.next_layer().connect({asio::ip::make_address("127.0.0.1"), port}, ec);
    if (!ec)
        s.handshake(asio::ssl::stream_base::client, ec);
    if (ec)
        return QString::fromStdString("handshake: " + ec.message());
    std::vector<std::uint8_t> hello;
    encodeFrame(HelloMsg{kProtocolVersion, 9, kToken, ""}, 1, hello);
    asio::write(s, asio::buffer(hello), ec);
    std::array<std::uint8_t, 512> buf{};
    const std::size_t n = s.read_some(asio::buffer(buf), ec); // TLS 1.3: the alert comes here
    return ec ? QString::fromStdString("read: " + ec.message())
              : QStringLiteral("read %1 bytes").arg(n);
}

} // namespace

class TestTlsRefusals : public QObject {
    Q_OBJECT
    TlsFixture m_tls;
    QTemporaryDir m_dir;
    QString m_config, m_token;

    QStringList args(bool tls = true) const {
        QStringList a{"--config",     m_config, "--pace",         "fast",
                      "--token-file", m_token,  "--no-state-file"};
        return tls ? a + m_tls.controllerArgs() : a;
    }

    /// Stop the controller and check what it admitted over its life.
    static void expectAdmitted(ControllerProcess& ctl, int sessions) {
        ctl.stop();
        QVERIFY2(ctl.log().contains(QStringLiteral("%1 sessions admitted").arg(sessions)),
                 qPrintable(ctl.log()));
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

    void rightCertificateIsAdmitted() {
        ControllerProcess ctl(args());
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        QVERIFY2(ctl.log().contains("TLS 1.3, client certificates from"), qPrintable(ctl.log()));
        const Attempt a = helloOver("127.0.0.1", ctl.port(), m_tls.console());
        QVERIFY2(a.admitted, qPrintable(a.error + "\n" + ctl.log()));
        expectAdmitted(ctl, 1);
    }

    void pinnedControllerWithoutCa() {
        ControllerProcess ctl(args());
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        QString fp;
        QVERIFY2(TlsFixture::certs({"fingerprint", m_tls.cert("controller")}, &fp), qPrintable(fp));
        TlsSpec pinned = m_tls.console();
        pinned.ca.clear();
        pinned.pins = {fp.toStdString()};
        const Attempt a = helloOver("127.0.0.1", ctl.port(), pinned);
        QVERIFY2(a.admitted, qPrintable(a.error + "\n" + ctl.log()));
        // Another pin and no CA: the controller's certificate is not trusted.
        pinned.pins = {std::string(64, 'a')};
        const Attempt b = helloOver("127.0.0.1", ctl.port(), pinned);
        QVERIFY(!b.admitted);
        QVERIFY2(b.error.contains("TLS handshake with 127.0.0.1") &&
                     b.error.contains("the controller's certificate"),
                 qPrintable(b.error));
        expectAdmitted(ctl, 1);
    }

    void noClientCertificate() {
        // The console itself cannot be set up without one ...
        TlsSpec none = m_tls.console();
        none.certificate.clear();
        const Attempt a = helloOver("127.0.0.1", 1, none);
        QVERIFY2(a.error.contains("certificate and key"), qPrintable(a.error));
        // ... and a TLS client without one is refused by the controller.
        ControllerProcess ctl(args());
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const QString answer =
            helloWithoutCertificate(ctl.port(), m_tls.path("ca/ca.pem").toStdString());
        QVERIFY2(answer.contains("certificate required"), qPrintable(answer));
        QTRY_VERIFY2_WITH_TIMEOUT(ctl.log().contains("TLS handshake failed") &&
                                      ctl.log().contains("did not return a certificate"),
                                  qPrintable(ctl.log()), 20000);
        expectAdmitted(ctl, 0);
    }

    void certificateFromAnotherCa() {
        ControllerProcess ctl(args());
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const Attempt a = helloOver("127.0.0.1", ctl.port(), m_tls.console("stranger"));
        QVERIFY(!a.admitted);
        QVERIFY2(a.error.contains("ended the TLS session") && a.error.contains("unknown ca"),
                 qPrintable(a.error));
        QTRY_VERIFY2_WITH_TIMEOUT(ctl.log().contains("unable to get local issuer certificate"),
                                  qPrintable(ctl.log()), 20000);
        expectAdmitted(ctl, 0);
    }

    void expiredCertificate() {
        ControllerProcess ctl(args());
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const Attempt a = helloOver("127.0.0.1", ctl.port(), m_tls.console("expired"));
        QVERIFY(!a.admitted);
        QVERIFY2(a.error.contains("ended the TLS session") && a.error.contains("expired"),
                 qPrintable(a.error));
        QTRY_VERIFY2_WITH_TIMEOUT(ctl.log().contains("certificate has expired"),
                                  qPrintable(ctl.log()), 20000);
        expectAdmitted(ctl, 0);
    }

    void revokedAfterSighup() {
        ControllerProcess ctl(args());
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        LinkClientOptions o;
        o.tls = m_tls.console();
        LinkClient admitted(o);
        const Attempt before =
            helloOver("127.0.0.1", ctl.port(), m_tls.console(), kToken, &admitted);
        QVERIFY2(before.admitted, qPrintable(before.error + "\n" + ctl.log()));
        QString fp;
        QVERIFY2(TlsFixture::certs({"fingerprint", m_tls.cert("console")}, &fp), qPrintable(fp));
        {
            std::ofstream revoked(m_tls.path("revoked.txt").toStdString());
            revoked << "# the console's certificate, lost with its laptop\n"
                    << fp.toStdString() << "\n";
        }
        QCOMPARE(::kill(pid_t(ctl.pid()), SIGHUP), 0);
        QTRY_VERIFY2_WITH_TIMEOUT(
            ctl.log().contains("SIGHUP: TLS files reloaded (0 pins, 1 revoked)"),
            qPrintable(ctl.log()), 20000);
        // The admitted session with that certificate is closed with the reason ...
        std::string e;
        const auto m = admitted.receive(kWait, e);
        QVERIFY(m && std::holds_alternative<ErrorMsg>(*m));
        QVERIFY2(std::get<ErrorMsg>(*m).reason.find("revoked") != std::string::npos,
                 std::get<ErrorMsg>(*m).reason.c_str());
        // ... and a new connection with it is refused, without a restart.
        const Attempt after = helloOver("127.0.0.1", ctl.port(), m_tls.console());
        QVERIFY(!after.admitted);
        QVERIFY2(after.error.contains("ended the TLS session"), qPrintable(after.error));
        QTRY_VERIFY2_WITH_TIMEOUT(ctl.log().contains("is revoked"), qPrintable(ctl.log()), 20000);
        std::ofstream(m_tls.path("revoked.txt").toStdString()).flush(); // empty again
        expectAdmitted(ctl, 1);
    }

    void plaintextClientOnTlsPort() {
        ControllerProcess ctl(args());
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const Attempt a = helloOver("127.0.0.1", ctl.port(), std::nullopt);
        QVERIFY(!a.admitted);
        QVERIFY2(a.error.contains("speaks TLS on this port") && a.error.contains("tls://"),
                 qPrintable(a.error));
        QTRY_VERIFY2_WITH_TIMEOUT(ctl.log().contains("a plaintext client on the TLS port"),
                                  qPrintable(ctl.log()), 20000);
        expectAdmitted(ctl, 0);
    }

    void tlsClientOnPlaintextPort() {
        ControllerProcess ctl(args(false));
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const Attempt a = helloOver("127.0.0.1", ctl.port(), m_tls.console());
        QVERIFY(!a.admitted);
        QVERIFY2(a.error.contains("TLS handshake with 127.0.0.1") &&
                     a.error.contains("listening without TLS"),
                 qPrintable(a.error));
        QTRY_VERIFY2_WITH_TIMEOUT(ctl.log().contains("a TLS client on a plaintext port"),
                                  qPrintable(ctl.log()), 20000);
        expectAdmitted(ctl, 0);
    }

    void rightCertificateWrongToken() {
        ControllerProcess ctl(args());
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const Attempt a = helloOver("127.0.0.1", ctl.port(), m_tls.console(), "a-wrong-token");
        QVERIFY(!a.admitted);
        QVERIFY2(a.error.contains("wrong token"), qPrintable(a.error));
        QTRY_VERIFY2_WITH_TIMEOUT(ctl.log().contains(": wrong token"), qPrintable(ctl.log()),
                                  20000);
        expectAdmitted(ctl, 0);
    }

    void controllerCertificateMustNameTheHost() {
        ControllerProcess ctl(args());
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        // Its certificate names IP 127.0.0.1 only; "localhost" is not in it.
        const Attempt a = helloOver("localhost", ctl.port(), m_tls.console());
        QVERIFY(!a.admitted);
        QVERIFY2(a.error.contains("does not name localhost"), qPrintable(a.error));
        expectAdmitted(ctl, 0);
    }

    void keyReadableByOthersIsRefused() {
        const QString key = m_dir.filePath("open.key");
        QVERIFY(QFile::copy(m_tls.key("controller"), key));
        QFile::setPermissions(key, QFile::ReadOwner | QFile::WriteOwner | QFile::ReadGroup |
                                       QFile::ReadOther);
        QStringList a = args();
        a[a.indexOf("--tls-key") + 1] = key;
        QProcess p;
        p.setProcessChannelMode(QProcess::MergedChannels);
        p.start(QStringLiteral(HSMU_CONTROLLER_EXE), a << "--port"
                                                       << "0");
        QVERIFY(p.waitForFinished(20000));
        const QString out = QString::fromUtf8(p.readAll());
        QCOMPARE(p.exitCode(), 2);
        QVERIFY2(out.contains("readable by other users") && out.contains("chmod 600 " + key),
                 qPrintable(out));
        // The console's side: the same rule when the configuration is checked.
        TlsSpec open = m_tls.console();
        open.key = key.toStdString();
        const Attempt c = helloOver("127.0.0.1", 1, open);
        QVERIFY2(c.error.contains("chmod 600"), qPrintable(c.error));
    }

    void nonLoopbackWithTlsStartsWithoutInsecurePlaintext() {
        ControllerProcess ctl(args() << "--bind"
                                     << "0.0.0.0");
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const Attempt a = helloOver("127.0.0.1", ctl.port(), m_tls.console());
        QVERIFY2(a.admitted, qPrintable(a.error + "\n" + ctl.log()));
        QVERIFY2(!ctl.log().contains("in clear"), qPrintable(ctl.log()));
        expectAdmitted(ctl, 1);
    }
};

QTEST_GUILESS_MAIN(TestTlsRefusals)
#include "TestTlsRefusals.moc"
