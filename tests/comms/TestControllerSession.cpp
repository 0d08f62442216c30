// ControllerSession (hsmu-controller's console connection) against a client that does not read
// its replies (issue 14). In process and deterministic: the session's kernel send buffer is
// made small (SO_SNDBUF 4 KiB on the accepted socket), so a few thousand unread replies fill
// the kernel and the rest wait in the session's own queue, below its 256 KiB cap. Then:
//  - a client that falls silent is refused for its silence, and the refusal (which it will
//    never read) does not keep the connection open: closed within the refusal's grace;
//  - a client that keeps sending heartbeats at a console's pace (never silent, its queue
//    growing 24 bytes a beat) is dropped once a reply has waited the idle timeout;
//  - a client that reads its replies is never dropped (control).
// Every wait is bounded; no assertion is on wall time.
#include "comms/controller/ControllerSession.h"

#include "comms/protocol/FrameCodec.h"

#include <QDeadlineTimer>
#include <QtTest>

#include <boost/asio/io_context.hpp>

#include <arpa/inet.h>
#include <cerrno>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <memory>
#include <string>
#include <vector>

using namespace hsmu;
using namespace hsmu::comms;
namespace asio = boost::asio;

namespace {

constexpr double kIdle = 0.5; // [s] the host's idle timeout

struct Host final : SessionHost {
    bool isClosed = false;
    std::vector<std::string> drops;
    std::optional<ErrorMsg> admit(ControllerSession&, const HelloMsg&, HelloAckMsg&,
                                  double&) override {
        return std::nullopt;
    }
    std::optional<Message> handle(ControllerSession&, const Message&) override {
        return std::nullopt;
    }
    void closed(ControllerSession&) override { isClosed = true; }
    double idleTimeout() const override { return kIdle; }
    void dropped(ControllerSession&, const std::string& why) override { drops.push_back(why); }
    bool droppedFor(const std::string& text) const {
        for (const auto& d : drops)
            if (d.find(text) != std::string::npos)
                return true;
        return false;
    }
};

/// The consecutive frames [sequence, sequence + count) as heartbeats.
std::vector<std::uint8_t> heartbeats(std::uint32_t& sequence, int count) {
    std::vector<std::uint8_t> out;
    for (int i = 0; i < count; ++i, ++sequence)
        encodeFrame(HeartbeatMsg{sequence}, sequence, out); // appends
    return out;
}

/// A session on one end of a loopback connection, the raw client socket on the other.
class Pair {
public:
    Pair() : m_acceptor(m_io) {
        const asio::ip::tcp::endpoint ep(asio::ip::make_address("127.0.0.1"), 0);
        m_acceptor.open(ep.protocol());
        m_acceptor.bind(ep);
        m_acceptor.listen();
        m_client = ::socket(AF_INET, SOCK_STREAM, 0);
        int small = 4096; // the client's buffers small too: the queue is the session's
        ::setsockopt(m_client, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_port = htons(m_acceptor.local_endpoint().port());
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        m_connected = ::connect(m_client, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
        asio::ip::tcp::socket s = m_acceptor.accept();
        s.set_option(asio::socket_base::send_buffer_size(4096));
        m_session = std::make_shared<ControllerSession>(std::make_unique<ByteStream>(std::move(s)), host);
        m_session->start();
    }
    ~Pair() {
        if (m_client >= 0)
            ::close(m_client);
        m_session->close();
        m_io.poll();
    }
    bool connected() const { return m_connected; }

    /// Send every byte without blocking the session's thread (it runs between tries).
    bool send(const std::vector<std::uint8_t>& bytes) {
        std::size_t off = 0;
        const QDeadlineTimer bound(30000);
        while (off < bytes.size() && !bound.hasExpired()) {
            const ssize_t n = ::send(m_client, bytes.data() + off, bytes.size() - off,
                                     MSG_NOSIGNAL | MSG_DONTWAIT);
            if (n > 0)
                off += std::size_t(n);
            else if (errno != EAGAIN && errno != EWOULDBLOCK)
                return false;
            m_io.run_for(std::chrono::milliseconds(1));
        }
        return off == bytes.size();
    }
    /// Run the session for up to ms, or until it is closed; whether it was.
    bool runUntilClosed(int ms) {
        const QDeadlineTimer bound(ms);
        while (!host.isClosed && !bound.hasExpired())
            m_io.run_for(std::chrono::milliseconds(10));
        return host.isClosed;
    }
    /// Read whatever replies are waiting (the reading client).
    std::size_t drain() {
        std::uint8_t buf[65536];
        std::size_t total = 0;
        for (;;) {
            const ssize_t n = ::recv(m_client, buf, sizeof buf, MSG_DONTWAIT);
            if (n <= 0)
                return total;
            total += std::size_t(n);
        }
    }
    void run(int ms) { m_io.run_for(std::chrono::milliseconds(ms)); }

    Host host;

private:
    asio::io_context m_io{1};
    asio::ip::tcp::acceptor m_acceptor;
    int m_client = -1;
    bool m_connected = false;
    std::shared_ptr<ControllerSession> m_session;
};

/// Hello, then enough heartbeats that the unread replies fill the kernel's buffers and wait
/// in the session's queue (well under its cap).
bool helloAndFill(Pair& p, std::uint32_t& sequence) {
    std::vector<std::uint8_t> hello;
    encodeFrame(HelloMsg{kProtocolVersion, 1, "", ""}, sequence++, hello);
    return p.send(hello) && p.send(heartbeats(sequence, 4000)); // 96 kB of replies
}

} // namespace

class TestControllerSession : public QObject {
    Q_OBJECT
private slots:
    void silentNonReaderIsClosedDespiteItsRefusal() {
        Pair p;
        QVERIFY(p.connected());
        std::uint32_t sequence = 1;
        QVERIFY(helloAndFill(p, sequence));
        QVERIFY(!p.host.isClosed);
        // Silent from here on: refused for it (a Timeout frame it never reads), then closed.
        QVERIFY2(p.runUntilClosed(20000), "the refused session was never closed");
        QVERIFY(p.host.droppedFor("no frame for"));
        QVERIFY(!p.host.droppedFor("send queue past")); // not the cap: the timeout
    }

    void heartbeaterThatNeverReadsIsDropped() {
        Pair p;
        QVERIFY(p.connected());
        std::uint32_t sequence = 1;
        QVERIFY(helloAndFill(p, sequence));
        // A console's heartbeat pace (every 100 ms): never silent, and its queue would take
        // the better part of an hour to reach the cap.
        const QDeadlineTimer bound(20000); // a bound on the loop only
        while (!p.host.isClosed && !bound.hasExpired()) {
            QVERIFY(p.send(heartbeats(sequence, 1)));
            p.run(100);
        }
        QVERIFY2(p.host.isClosed, "a client that never reads was never dropped");
        QVERIFY(p.host.droppedFor("does not read its replies (none taken for"));
        QVERIFY(!p.host.droppedFor("no frame for"));
    }

    void readingClientIsKept() {
        Pair p;
        QVERIFY(p.connected());
        std::uint32_t sequence = 1;
        std::vector<std::uint8_t> hello;
        encodeFrame(HelloMsg{kProtocolVersion, 1, "", ""}, sequence++, hello);
        QVERIFY(p.send(hello));
        // Bursts of heartbeats read back, for eight idle timeouts: never dropped.
        std::size_t replies = 0;
        for (int i = 0; i < 40; ++i) {
            QVERIFY(p.send(heartbeats(sequence, 200)));
            p.run(100);
            replies += p.drain();
            QVERIFY2(!p.host.isClosed,
                     p.host.drops.empty() ? "closed" : p.host.drops.front().c_str());
        }
        QVERIFY(replies > 0);
    }
};

QTEST_GUILESS_MAIN(TestControllerSession)
#include "TestControllerSession.moc"
