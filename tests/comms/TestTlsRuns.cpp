// Runs over tls:// (issue 26, "Acceptance"): `hsmu run` (the real binary) against real
// hsmu-controller processes with TLS 1.3 and client certificates (made by
// scripts/hsmu-certs.sh) writes the very steps.csv, byte for byte, of the same run over
// plaintext tcp:// (fast pace, same configuration and seed): the paper's condition 3 on one
// controller, and the paper-bridge-two-labs preset on two. The record says how each site's
// link was protected (/sites security: "tls" or "plaintext-loopback").
#include "../gui/CliTestSupport.h"
#include "ControllerProcess.h"
#include "TlsFixture.h"

#include "core/record/RecordReader.h"

#include <QFile>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <fstream>

using namespace clitest;

namespace {

nlohmann::json preset(const char* name) {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) + "/resources/presets/" + name + ".json");
    return nlohmann::json::parse(in);
}

QByteArray fileBytes(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// The record's /sites `security`, in its sites' order, once summary.json's link_security is
// seen to say the same (otherwise a one-element vector naming the difference).
std::vector<std::string> siteSecurity(const QString& runDir) {
    const hsmu::RecordReader reader((runDir + "/record.h5").toStdString());
    const auto& sites = reader.data().layout.sites;
    const auto& security = reader.data().meta.siteSecurity;
    nlohmann::json recorded = nlohmann::json::object();
    for (std::size_t i = 0; i < sites.size() && i < security.size(); ++i)
        recorded[sites[i]] = security[i];
    std::ifstream in((runDir + "/summary.json").toStdString());
    const nlohmann::json summary = nlohmann::json::parse(in, nullptr, false);
    if (summary.is_discarded() || !summary.contains("link_security") ||
        summary.at("link_security") != recorded)
        return {"summary.json link_security differs from the record's " + recorded.dump()};
    return security;
}

} // namespace

class TestTlsRuns : public QObject {
    Q_OBJECT
    TlsFixture m_tls;
    QTemporaryDir m_dir;

    /// The configuration j with the console's tls block, written into the temporary folder.
    QString write(nlohmann::json j, const QString& name) {
        j["tls"] = nlohmann::json::parse(m_tls.consoleJson().toStdString());
        const QString path = m_dir.filePath(name);
        std::ofstream(path.toStdString()) << j.dump(2);
        return path;
    }

    QStringList controllerArgs(const QString& config, bool tls) const {
        QStringList a{"--config", config, "--pace", "fast", "--no-state-file"};
        return tls ? a + m_tls.controllerArgs() : a;
    }

private slots:
    void initTestCase() {
        QString log;
        QVERIFY2(m_tls.make(&log), qPrintable(log));
        QVERIFY(m_dir.isValid());
    }

    void tlsRunEqualsPlaintextRun() {
        nlohmann::json j = preset("paper-condition-3");
        j["analysis"]["duration"] = 2.0;
        const QString config = write(j, "c3.json");
        ControllerProcess plain(controllerArgs(config, false)), tls(controllerArgs(config, true));
        QVERIFY2(plain.start(), qPrintable(plain.log()));
        QVERIFY2(tls.start(), qPrintable(tls.log()));
        const QString a = m_dir.filePath("tcp"), b = m_dir.filePath("tls");
        const Result ra =
            clitest::hsmu({"run", config, "--controller",
                           QStringLiteral("tcp://127.0.0.1:%1").arg(plain.port()), "--out", a});
        QVERIFY2(ra.exitCode == 0, qPrintable(report(ra) + plain.log()));
        const QString address = QStringLiteral("tls://127.0.0.1:%1").arg(tls.port());
        const Result rb = clitest::hsmu({"run", config, "--controller", address, "--out", b});
        QVERIFY2(rb.exitCode == 0, qPrintable(report(rb) + tls.log()));
        QVERIFY2(rb.err.contains(address + " (native protocol, tls)"), qPrintable(rb.err));

        const QByteArray x = fileBytes(a + "/steps.csv"), y = fileBytes(b + "/steps.csv");
        QCOMPARE(x.count('\n'), 202);    // header + steps 0..200
        QVERIFY(x.contains("param_k0")); // updating ran on both
        QVERIFY2(x == y, "steps.csv over TLS differs from the plaintext run's");
        QCOMPARE(siteSecurity(a), std::vector<std::string>{"plaintext-loopback"});
        QCOMPARE(siteSecurity(b), std::vector<std::string>{"tls"});
        tls.stop();
        QVERIFY2(tls.log().contains("1 sessions admitted"), qPrintable(tls.log()));
    }

    void twoLabsOverTlsEqualPlaintext() {
        nlohmann::json j = preset("paper-bridge-two-labs");
        j["analysis"]["duration"] = 1.5;
        const QString served = write(j, "two-labs.json");
        ControllerProcess plainD(controllerArgs(served, false)),
            plainC(controllerArgs(served, false)), tlsD(controllerArgs(served, true)),
            tlsC(controllerArgs(served, true));
        for (ControllerProcess* c : {&plainD, &plainC, &tlsD, &tlsC})
            QVERIFY2(c->start(), qPrintable(c->log()));
        auto pointed = [&](const char* scheme, quint16 d, quint16 c, const QString& name) {
            nlohmann::json k = j;
            for (auto& site : k["sites"])
                site["address"] = std::string(scheme) +
                                  "://127.0.0.1:" + std::to_string(site["name"] == "Lab D" ? d : c);
            return write(k, name);
        };
        const QString a = m_dir.filePath("labs-tcp"), b = m_dir.filePath("labs-tls");
        const Result ra = clitest::hsmu(
            {"run", pointed("tcp", plainD.port(), plainC.port(), "labs-tcp.json"), "--out", a});
        QVERIFY2(ra.exitCode == 0, qPrintable(report(ra) + plainD.log() + plainC.log()));
        const Result rb = clitest::hsmu(
            {"run", pointed("tls", tlsD.port(), tlsC.port(), "labs-tls.json"), "--out", b});
        QVERIFY2(rb.exitCode == 0, qPrintable(report(rb) + tlsD.log() + tlsC.log()));

        const QByteArray x = fileBytes(a + "/steps.csv"), y = fileBytes(b + "/steps.csv");
        QCOMPARE(x.count('\n'), 302); // header + steps 0..300
        QVERIFY2(x == y, "the two-lab steps.csv over TLS differs from the plaintext run's");
        const auto sa = siteSecurity(a), sb = siteSecurity(b);
        QCOMPARE(sa.size(), std::size_t(2));
        QCOMPARE(sa, (std::vector<std::string>{"plaintext-loopback", "plaintext-loopback"}));
        QCOMPARE(sb, (std::vector<std::string>{"tls", "tls"}));
        tlsD.stop();
        tlsC.stop();
        QVERIFY2(tlsD.log().contains("on specimen 'Bearing D'"), qPrintable(tlsD.log()));
        QVERIFY2(tlsC.log().contains("on specimen 'Bearing C'"), qPrintable(tlsC.log()));
    }
};

QTEST_GUILESS_MAIN(TestTlsRuns)
#include "TestTlsRuns.moc"
