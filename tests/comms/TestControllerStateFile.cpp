// hsmu-controller keeps a state file by default (issue 16): on a fixed port the journal is
// $XDG_STATE_HOME/hsmu/controller/<config>-<port>.state (~/.local/state when unset), so a
// restarted controller continues its specimens without any option; --state-file FILE names
// another one, --no-state-file keeps none, --port 0 has no default. Checked on the parser
// and on the real program started with no state option: it names the default journal and
// creates it (the restart-resume behaviour of a journal: TestLinkFaults).
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <QDeadlineTimer>
#include <QProcess>

#include "comms/controller/ControllerCommandLine.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

using hsmu::comms::ControllerCommandLine;

namespace {
/// A port no one listens on now (the kernel's choice for an ephemeral bind).
quint16 freePort() {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t n = sizeof a;
    const bool ok = fd >= 0 && ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0 &&
                    ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &n) == 0;
    if (fd >= 0)
        ::close(fd);
    return ok ? ntohs(a.sin_port) : 0;
}

std::optional<ControllerCommandLine> parse(std::vector<const char*> args, std::string& error) {
    args.insert(args.begin(), "hsmu-controller");
    return ControllerCommandLine::parse(int(args.size()), args.data(), error);
}
} // namespace

class TestControllerStateFile : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        qputenv("XDG_STATE_HOME", m_dir.path().toUtf8());
    }

    void defaultPathFollowsXdgStateHome() {
        std::string error;
        auto c = parse({"--config", "/x/sdof.json", "--port", "5600"}, error);
        QVERIFY2(c, error.c_str());
        QCOMPARE(QString::fromStdString(c->stateFile()),
                 m_dir.filePath(QStringLiteral("hsmu/controller/sdof-5600.state")));
        // --state-file and its older name --state; --no-state-file; both is an error.
        c = parse({"--config", "/x/sdof.json", "--port", "5600", "--state-file", "/tmp/j"}, error);
        QVERIFY(c);
        QCOMPARE(c->stateFile(), std::string("/tmp/j"));
        c = parse({"--config", "/x/sdof.json", "--port", "5600", "--state", "/tmp/k"}, error);
        QVERIFY(c);
        QCOMPARE(c->stateFile(), std::string("/tmp/k"));
        c = parse({"--config", "/x/sdof.json", "--port", "5600", "--no-state-file"}, error);
        QVERIFY(c);
        QVERIFY(c->stateFile().empty());
        QVERIFY(!parse({"--config", "/x/sdof.json", "--port", "5600", "--no-state-file",
                        "--state-file", "/tmp/j"},
                       error));
        QVERIFY2(error.find("contradict") != std::string::npos, error.c_str());
        // Port 0: no default (a restart would listen on another port).
        c = parse({"--config", "/x/sdof.json", "--port", "0"}, error);
        QVERIFY(c);
        QVERIFY(c->stateFile().empty());
        // A relative XDG_STATE_HOME is ignored (XDG spec): HOME/.local/state.
        const QByteArray xdg = qgetenv("XDG_STATE_HOME"), home = qgetenv("HOME");
        qputenv("XDG_STATE_HOME", "relative/dir");
        qputenv("HOME", "/home/someone");
        QCOMPARE(ControllerCommandLine::defaultStateFile("/x/sdof.json", 7),
                 std::string("/home/someone/.local/state/hsmu/controller/sdof-7.state"));
        qunsetenv("XDG_STATE_HOME");
        qunsetenv("HOME");
        QVERIFY(ControllerCommandLine::defaultStateFile("/x/sdof.json", 7).empty());
        qputenv("XDG_STATE_HOME", xdg);
        qputenv("HOME", home);
    }

    void aRestartOnTheSamePortContinuesWithoutOptions() {
        const QString config =
            QStringLiteral(HSMU_SOURCE_DIR "/resources/presets/paper-condition-3.json");
        QTemporaryDir fresh;
        qputenv("XDG_STATE_HOME", fresh.path().toUtf8());
        const quint16 port = freePort();
        QVERIFY(port != 0);
        const std::string expected =
            ControllerCommandLine::defaultStateFile(config.toStdString(), port);
        QVERIFY(!QFile::exists(QString::fromStdString(expected)));
        // The real program with no state option at all (the default applies).
        QProcess ctl;
        ctl.setProcessChannelMode(QProcess::MergedChannels);
        ctl.start(QStringLiteral(HSMU_CONTROLLER_EXE),
                  {"--config", config, "--pace", "fast", "--port", QString::number(port)});
        QVERIFY(ctl.waitForStarted(30000));
        QByteArray log;
        QDeadlineTimer deadline(30000);
        while (!log.contains("listening on") && !deadline.hasExpired() &&
               ctl.state() == QProcess::Running) {
            ctl.waitForReadyRead(1000);
            log += ctl.readAll();
        }
        QVERIFY2(log.contains("listening on"), log.constData());
        QVERIFY2(log.contains(QByteArray("state file ") + expected.c_str()), log.constData());
        QVERIFY2(QFile::exists(QString::fromStdString(expected)), expected.c_str());
        QFile journal(QString::fromStdString(expected));
        QVERIFY(journal.open(QIODevice::ReadOnly));
        QVERIFY(journal.readLine().startsWith("hsmu-controller-state 1"));
        ctl.kill();
        ctl.waitForFinished(10000);
        qputenv("XDG_STATE_HOME", m_dir.path().toUtf8());
    }
};

QTEST_MAIN(TestControllerStateFile)
#include "TestControllerStateFile.moc"
