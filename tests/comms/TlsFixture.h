#pragma once
// TlsFixture: the certificates of the TLS tests, made by the project's own tool
// (scripts/hsmu-certs.sh, the openssl command line) into a temporary folder: the lab CA "ca",
// another lab's CA "rogue", and certificates
//   controller  (ca; subjectAltName IP 127.0.0.1)   console  (ca)
//   expired     (ca; valid in January 2020 only)    stranger (rogue)
// and the empty revoked list revoked.txt. Never hangs: every openssl run is bounded.
// tlsfixture::helloOver: a console's LinkClient connecting and saying hello (admitted or why
// not).

#include "comms/link/LinkClient.h"
#include "comms/protocol/Messages.h"
#include "core/config/TlsConfig.h"

#include <QFile>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QTemporaryDir>

#include <optional>
#include <string>
#include <variant>

class TlsFixture {
public:
    /// Make everything; false with the tool's output in *log.
    bool make(QString* log) {
        if (!m_dir.isValid())
            return false;
        const QString ca = path("ca"), rogue = path("rogue"), out = path("certs");
        const QList<QStringList> steps = {
            {"init-ca", ca},
            {"init-ca", rogue},
            {"issue", "controller", "--ca", ca, "--ip", "127.0.0.1", "--out", out},
            {"issue", "console", "--ca", ca, "--out", out},
            {"issue", "expired", "--ca", ca, "--out", out, "--not-before", "200101000000Z",
             "--not-after", "200201000000Z"},
            {"issue", "stranger", "--ca", rogue, "--out", out}};
        for (const QStringList& args : steps)
            if (!certs(args, log))
                return false;
        QFile revoked(path("revoked.txt"));
        return revoked.open(QIODevice::WriteOnly);
    }

    /// Run scripts/hsmu-certs.sh with args; its standard output (trimmed) in *out.
    static bool certs(const QStringList& args, QString* out) {
        QProcess p;
        p.setProcessChannelMode(QProcess::MergedChannels);
        p.start(QStringLiteral("bash"),
                QStringList{QStringLiteral(HSMU_SOURCE_DIR "/scripts/hsmu-certs.sh")} + args);
        const bool finished = p.waitForFinished(60000);
        if (!finished)
            p.kill();
        *out = QString::fromUtf8(p.readAll()).trimmed();
        return finished && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
    }

    QString path(const QString& name) const { return m_dir.filePath(name); }
    QString cert(const QString& name) const { return path("certs/" + name + ".pem"); }
    QString key(const QString& name) const { return path("certs/" + name + ".key"); }

    /// The console's side: certificate `name`, trusting the lab CA.
    hsmu::TlsSpec console(const QString& name = QStringLiteral("console")) const {
        hsmu::TlsSpec s;
        s.ca = path("ca/ca.pem").toStdString();
        s.certificate = cert(name).toStdString();
        s.key = key(name).toStdString();
        return s;
    }

    /// The console's "tls" block for a configuration (absolute paths).
    QString consoleJson(const QString& name = QStringLiteral("console")) const {
        return QStringLiteral(R"({"ca": "%1", "certificate": "%2", "key": "%3"})")
            .arg(path("ca/ca.pem"), cert(name), key(name));
    }

    /// hsmu-controller's TLS options: its certificate, the lab CA, the revoked list.
    QStringList controllerArgs() const {
        return {"--tls-certificate", cert("controller"), "--tls-key",     key("controller"),
                "--tls-ca",          path("ca/ca.pem"),  "--tls-revoked", path("revoked.txt")};
    }

private:
    QTemporaryDir m_dir;
};

namespace tlsfixture {

inline constexpr double kWait = 20.0; // [s] generous for a loaded CI machine
inline const std::string kToken = "the-right-token";

struct Attempt {
    bool admitted = false;
    QString error; ///< the console's words when refused
};

/// Connect (TLS when tls is set) and say hello with token; whether it was admitted.
inline Attempt helloOver(const std::string& host, quint16 port, std::optional<hsmu::TlsSpec> tls,
                         const std::string& token = kToken, hsmu::comms::LinkClient* keep = nullptr) {
    using namespace hsmu::comms;
    LinkClientOptions o;
    o.tls = std::move(tls);
    LinkClient local(o);
    LinkClient& link = keep ? *keep : local;
    std::string e;
    if (!link.connect(host, port, kWait, e))
        return {false, QString::fromStdString(e)};
    if (!link.send(HelloMsg{kProtocolVersion, 7, token, ""}, e))
        return {false, QString::fromStdString(e)};
    const auto m = link.receive(kWait, e);
    if (!m)
        return {false, QString::fromStdString(e)};
    if (std::holds_alternative<HelloAckMsg>(*m))
        return {true, {}};
    if (const auto* err = std::get_if<ErrorMsg>(&*m))
        return {false, QString::fromStdString(err->reason)};
    return {false, QStringLiteral("unexpected reply")};
}

} // namespace tlsfixture
