// hsmu-controller's OpenFresco servers against hostile raw clients (issue 26): GenericTCP init
// lines that try to forge log lines or fill the disk (D2), an unknown action code as the first
// frame (D7), and clients refused before their sizes header, whose log line must name them (D9).
#include "comms/openfresco/OfFrame.h"

#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "OfRawPeer.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;
using namespace ofpeer;
using hsmu::comms::of::kInitLineBytes;

namespace {

std::vector<std::uint8_t> initLine(const std::string& text) {
    std::vector<std::uint8_t> b(kInitLineBytes, 0);
    std::memcpy(b.data(), text.data(), std::min(text.size(), b.size()));
    return b;
}

} // namespace

class TestOpenFrescoHostile : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::string m_quiet;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_quiet = writeConfig(m_dir.path(), "quiet.json", quietCondition3());
    }

    // D2: what a client sends reaches the log only as printable text, bounded in length and
    // in count: no CR/LF that would start a forged line, no escape sequences, no disk filling.
    void initLinesCannotForgeOrFloodTheLog() {
        ControllerProcess ctl = ofController(m_quiet, "generictcp", {"--data-size", "32"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawPeer p;
        QVERIFY2(p.socket.connect("127.0.0.1", ctl.port(), kWait, p.error), p.error.c_str());
        QVERIFY(p.send(header({1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 32})));
        QVERIFY(p.send(initLine("expControl GenericTCP 1\r\nFAKE: interlock cleared\n")));
        QVERIFY(p.send(initLine("\x1b[2J\x1b[31mred\x07\x01\xff\xfe binary")));
        QVERIFY(p.send(initLine(std::string(16384, 'x')))); // a full line, no NUL
        constexpr int kFlood = 200;
        for (int i = 0; i < kFlood; ++i)
            QVERIFY(p.send(initLine("line " + std::to_string(i))));
        QVERIFY(p.send(frame({6.0}, 32))); // the session still answers after them
        const auto r = p.receive(32);
        QVERIFY2(r, p.error.c_str());
        QCOMPARE((*r)[0], 0.0);
        p.socket.close();
        ctl.stop();
        const QString log = ctl.log();
        QVERIFY2(!log.contains('\r') && !log.contains(QChar(0x1b)) && !log.contains(QChar(0x07)),
                 qPrintable(log.left(2000)));
        for (const QString& line : log.split('\n'))
            QVERIFY2(line.isEmpty() || line.startsWith("hsmu-controller") ||
                         line.startsWith("listening") || line.startsWith(' '),
                     qPrintable("forged or foreign line: " + line.left(200)));
        QVERIFY2(log.contains("FAKE: interlock cleared"), qPrintable(log.left(2000))); // shown
        QVERIFY2(log.size() < 20000, qPrintable(QString::number(log.size()) + " bytes of log"));
        QVERIFY2(log.count("init line: ") == 16, qPrintable(log.left(4000)));
        QVERIFY2(log.contains("init lines not logged"), qPrintable(log.left(4000)));
        QVERIFY2(log.contains(QString::number(kFlood + 3) + " init lines"),
                 qPrintable(log.right(2000)));
    }

    // D7: an unknown action code as the first frame is refused at once (logged, closed), not
    // read as the first 8 bytes of a 16,385-byte init line that never completes.
    void unknownFirstCodeClosesTheSession() {
        ControllerProcess ctl = ofController(m_quiet, "generictcp", {"--data-size", "32"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        for (const double code : {42.0, -3.0, 100.0}) {
            RawPeer p;
            QVERIFY2(p.socket.connect("127.0.0.1", ctl.port(), kWait, p.error), p.error.c_str());
            QVERIFY(p.send(header({1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 32})));
            QVERIFY(p.send(frame({code, 0.01}, 32)));
            std::uint8_t byte;
            QVERIFY(!p.socket.read(&byte, 1, kWait, p.error));
            QVERIFY2(p.socket.closedByPeer(), p.error.c_str()); // closed, not timed out
        }
        ctl.stop();
        for (const char* code : {"42", "-3", "100"})
            QVERIFY2(ctl.log().contains(QString("unknown action code ") + code),
                     qPrintable(ctl.log()));
    }

    // D9: a client refused before its sizes header is named by its address in the log.
    void refusedBeforeTheHeaderIsNamed() {
        for (const QString protocol : {"simapp", "generictcp"}) {
            ControllerProcess ctl = ofController(m_quiet, protocol);
            QVERIFY2(ctl.start(), qPrintable(ctl.log()));
            RawPeer p;
            QVERIFY2(p.socket.connect("127.0.0.1", ctl.port(), kWait, p.error), p.error.c_str());
            p.socket.close(); // no header
            RawPeer q;        // the server is free again once the first is refused
            QVERIFY2(q.socket.connect("127.0.0.1", ctl.port(), kWait, q.error), q.error.c_str());
            QVERIFY(q.send(header({1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 256})));
            QVERIFY(q.send(frame({6.0}, 256)));
            QVERIFY2(q.receive(256), q.error.c_str());
            ctl.stop();
            QVERIFY2(ctl.log().contains(
                         QRegularExpression("refused 127\\.0\\.0\\.1:[0-9]+: no sizes header")),
                     qPrintable(ctl.log()));
        }
    }
};

QTEST_GUILESS_MAIN(TestOpenFrescoHostile)
#include "TestOpenFrescoHostile.moc"
