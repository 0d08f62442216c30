// Bounded resources in hsmu-controller (issue 14): hostile and careless clients against a real
// controller process. A client that sends heartbeats and never reads the replies is dropped
// (capped send queue, or the idle timeout); idle strangers (no hello) never lock out a token
// holder; failed tokens are rate-limited per address; the token is never taken from argv.
// After every pattern the controller's peak resident set (VmHWM) stays under 100 MB; each
// figure is printed.
#include "comms/protocol/FrameCodec.h"

#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "RawClient.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <arpa/inet.h>
#include <cerrno>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <vector>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;

namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr long kMaxRssKb = 1024 * 1024; // a sanitizer's shadow memory: only runaway growth
#else
constexpr long kMaxRssKb = 100 * 1024; // 100 MB
#endif

/// A plain blocking TCP socket to 127.0.0.1:port (-1 on failure).
int rawConnect(std::uint16_t port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd < 0 || ::connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
        if (fd >= 0)
            ::close(fd);
        return -1;
    }
    return fd;
}

/// How many sockets the process has open (-1 if unknown).
int socketsOf(qint64 pid) {
    const QDir fds(QStringLiteral("/proc/%1/fd").arg(pid));
    if (!fds.exists())
        return -1;
    int n = 0;
    for (const QString& name : fds.entryList(QDir::System | QDir::NoDotAndDotDot)) {
        char target[64] = {};
        const QByteArray path = fds.filePath(name).toLocal8Bit();
        if (::readlink(path.constData(), target, sizeof target - 1) > 0 &&
            std::strncmp(target, "socket:", 7) == 0)
            ++n;
    }
    return n;
}

} // namespace

class TestControllerHostile : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::string m_config;
    QString m_tokenFile;

    ControllerProcess controller() {
        return ControllerProcess({"--config", QString::fromStdString(m_config), "--pace", "fast",
                                  "--token-file", m_tokenFile});
    }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_config = writeConfig(m_dir.path(), "c3.json", condition3(1.0));
        m_tokenFile = m_dir.filePath("token");
        std::ofstream(m_tokenFile.toStdString()) << "s3cret\n";
        QFile::setPermissions(m_tokenFile, QFile::ReadOwner | QFile::WriteOwner); // 0600
    }

    void nonReadingClientIsDropped() {
        ControllerProcess ctl = controller();
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const int fd = rawConnect(ctl.port());
        QVERIFY(fd >= 0);
        int small = 4096; // keep the kernel's buffers small: the queue is the controller's
        ::setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
        std::vector<std::uint8_t> hello, beats;
        encodeFrame(HelloMsg{kProtocolVersion, 1, "s3cret", ""}, 1, hello);
        QCOMPARE(::write(fd, hello.data(), hello.size()), ssize_t(hello.size()));
        std::uint32_t sequence = 2; // the decoder wants consecutive sequence numbers
        const auto refill = [&] {
            beats.clear();
            for (int i = 0; i < 4096; ++i) {
                std::vector<std::uint8_t> f;
                encodeFrame(HeartbeatMsg{sequence}, sequence, f);
                ++sequence;
                beats.insert(beats.end(), f.begin(), f.end());
            }
        };
        std::size_t offset = 0;
        refill();
        ::fcntl(fd, F_SETFL, O_NONBLOCK);
        // Heartbeats (each answered by the controller), never reading: the controller must drop
        // the connection once its queue of unread replies passes its cap.
        std::size_t sent = 0;
        bool closed = false, accepted = false;
        const QDeadlineTimer bound(120000); // [ms] a bound on the loop, not a timing assertion
        // Sends until the controller drops the connection (however slowly a loaded machine
        // lets it get there); the deadline only keeps a broken controller from hanging us.
        while (!closed) {
            const ssize_t n =
                ::send(fd, beats.data() + offset, beats.size() - offset, MSG_NOSIGNAL);
            if (n > 0) {
                sent += std::size_t(n);
                offset += std::size_t(n);
                if (offset == beats.size()) {
                    refill();
                    offset = 0;
                }
                continue;
            }
            if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) {
                closed = true; // reset by the controller
                break;
            }
            pollfd p{fd, POLLOUT, 0};
            if (::poll(&p, 1, 200) > 0 && (p.revents & (POLLERR | POLLHUP)))
                closed = true;
            // The controller may have closed its end while this socket cannot hear of it yet:
            // on loopback with this tiny receive buffer both kernels can drop each other's
            // segments and back their retransmissions off for a minute or more (observed),
            // so the controller's own sockets are looked at too.
            const int sockets = socketsOf(ctl.pid());
            if (sockets >= 2)
                accepted = true; // the listener and this connection
            else if (accepted && sockets == 1)
                closed = true; // the listener only: the connection is gone

            if (bound.hasExpired())
                break; // never hang: the log check below then fails
        }
        ::close(fd);
        const long peak = ctl.rssKb(true);
        qInfo("non-reading client: %zu bytes of heartbeats sent; controller VmHWM %ld kB", sent,
              peak);
        QVERIFY(peak > 0 && peak < kMaxRssKb);
        ctl.stop();
        // Dropped: the controller closed the connection, at the send-queue cap or at the idle
        // timeout when the stream stalls (seen about once in 60 runs under load: the two
        // kernels dropped each other's segments and backed off for a minute; the old session
        // then hung on its undeliverable timeout refusal). Either way it says so.
        // (The timeout paths themselves: test_comms_controller_session.)
        qInfo("dropped at the queue cap: %s",
              ctl.log().contains("send queue past") ? "yes" : "no (timeout)");
        QVERIFY2(closed, qPrintable("the controller never dropped the client: " + ctl.log()));
        QVERIFY2(ctl.log().contains("dropped "), qPrintable(ctl.log()));
    }

    void idleStrangersDoNotLockOutTheTokenHolder() {
        ControllerProcess ctl = controller();
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        std::vector<int> strangers;
        for (int i = 0; i < 64; ++i) {
            const int fd = rawConnect(ctl.port());
            QVERIFY(fd >= 0);
            strangers.push_back(fd);
        }
        RawClient console;
        QVERIFY(console.connect(ctl.port()));
        QVERIFY2(console.hello(7, "s3cret"), qPrintable(ctl.log()));
        const long peak = ctl.rssKb(true);
        qInfo("64 idle strangers: controller VmHWM %ld kB", peak);
        QVERIFY(peak > 0 && peak < kMaxRssKb);
        for (const int fd : strangers)
            ::close(fd);
    }

    // Past 5 wrong tokens from one address in 10 s, the next wrong ones are refused late
    // (each connection held 1 s before its refusal, so guessing is slow), but the token is
    // still compared: the right one is admitted at once, so wrong guesses from the same host
    // (or NAT) can never keep the console out (issue 26, D5).
    void failedTokensAreRateLimited() {
        ControllerProcess ctl = controller();
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        int wrong = 0, limited = 0;
        for (int i = 0; i < 10; ++i) {
            RawClient c;
            QVERIFY(c.connect(ctl.port()));
            QVERIFY(c.send(HelloMsg{kProtocolVersion, 1, "guess" + std::to_string(i), ""}));
            const auto e = c.expect<ErrorMsg>();
            QVERIFY(e && e->code == ErrorCode::Unauthorized);
            if (e->reason.find("too many wrong tokens") != std::string::npos)
                ++limited;
            else
                ++wrong;
        }
        qInfo("10 wrong tokens: %d refused at once, %d refused late; controller VmHWM %ld kB",
              wrong, limited, ctl.rssKb(true));
        // The window is 10 s; a slow machine may straddle one boundary, hence >= 1.
        QVERIFY2(limited >= 1 && wrong + limited == 10, qPrintable(QString::number(limited)));
        RawClient console; // the right token, from the same address, during the lockout
        QVERIFY(console.connect(ctl.port()));
        QVERIFY2(console.hello(9, "s3cret"), qPrintable(ctl.log()));
        QVERIFY(ctl.rssKb(true) < kMaxRssKb);
    }

    // D6 (issue 26): a hello whose sequence number is not 1 is a protocol violation.
    void firstFrameMustCarrySequenceOne() {
        ControllerProcess ctl = controller();
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        for (const std::uint32_t seq : {0u, 5u, 0xFFFFFFFFu}) {
            RawClient c;
            QVERIFY(c.connect(ctl.port()));
            std::vector<std::uint8_t> b;
            encodeFrame(HelloMsg{kProtocolVersion, 4, "s3cret", ""}, seq, b);
            QVERIFY(c.sendRaw(b));
            const auto e = c.expect<ErrorMsg>();
            QVERIFY2(e && e->code == ErrorCode::ProtocolViolation, qPrintable(ctl.log()));
            QVERIFY2(e->reason.find("first frame") != std::string::npos, e->reason.c_str());
        }
        RawClient ok;
        QVERIFY(ok.connect(ctl.port()));
        QVERIFY2(ok.hello(4, "s3cret"), qPrintable(ctl.log()));
    }

    void tokenIsNeverAnArgument() {
        QProcess p;
        p.start(QStringLiteral(HSMU_CONTROLLER_EXE),
                {"--config", QString::fromStdString(m_config), "--port", "0", "--token", "x"});
        QVERIFY(p.waitForFinished(20000));
        QVERIFY(p.exitCode() != 0);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(err.contains("--token-file") && err.contains("HSMU_CONTROLLER_TOKEN"),
                 qPrintable(err));
        // The environment variable works.
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("HSMU_CONTROLLER_TOKEN", "from-env");
        QProcess q;
        q.setProcessEnvironment(env);
        q.setProcessChannelMode(QProcess::MergedChannels);
        q.start(QStringLiteral(HSMU_CONTROLLER_EXE), {"--config", QString::fromStdString(m_config),
                                                      "--port", "0", "--pace", "fast"});
        QVERIFY(q.waitForReadyRead(20000));
        const QString line = QString::fromUtf8(q.readLine());
        const auto m = QRegularExpression(":(\\d+) ").match(line);
        QVERIFY2(m.hasMatch(), qPrintable(line));
        RawClient c;
        QVERIFY(c.connect(quint16(m.captured(1).toUInt())));
        QVERIFY(c.hello(3, "from-env"));
        q.terminate();
        QVERIFY(q.waitForFinished(20000));
    }
};

QTEST_GUILESS_MAIN(TestControllerHostile)
#include "TestControllerHostile.moc"
