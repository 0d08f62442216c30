// A real hsmu-controller process (started here) against the console's link: the run over
// the link equals the in-process run step by step; refusals (token, version, busy, unknown
// element, malformed frames); every interlock limit, also through a HybridTest; a late target
// makes the real-time predictor-corrector hold.
#include "comms/link/ControlFactory.h"
#include "comms/protocol/FrameCodec.h"

#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "RawClient.h"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <chrono>
#include <fstream>
#include <thread>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;

namespace {

TcpControlOptions patientOptions() {
    TcpControlOptions o; // generous: a loaded 2-core CI machine
    o.connectTimeout = 20.0;
    o.stepDeadline = 30.0;
    o.silenceTimeout = 30.0;
    o.reconnectAttempts = 5;
    o.reconnectDelay = 0.2;
    return o;
}

LinkAddress local(quint16 port) {
    return LinkAddress{LinkAddress::Kind::Tcp, "127.0.0.1", port};
}

} // namespace

class TestControllerProcess : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::string m_config;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_config = writeConfig(m_dir.path(), "c3.json", condition3(3.0));
    }

    void linkRunEqualsInProcessRun() {
        ControllerProcess ctl(
            {"--config", QString::fromStdString(m_config), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const TestConfig cfg = loadConfigFile(m_config);
        const Run inProcess = runTest(cfg, {});
        const Run linked = runTest(cfg, makeControlFactory(local(ctl.port()), patientOptions()));
        QVERIFY2(linked.prepared, linked.error.c_str());
        QCOMPARE(inProcess.state, HybridTest::State::Finished);
        QCOMPARE(linked.state, HybridTest::State::Finished);
        QCOMPARE(linked.records.size(), std::size_t(301));
        QVERIFY(everyStepOnce(linked));
        const double diff = maxDifference(inProcess, linked);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
    }

    void realTimePaceGivesTheSameResult() {
        // Wall clock at 1024 Hz, ~10 ms per step: with an ideal actuator each step still ends
        // exactly on its target, so the result is the in-process one.
        const std::string path = writeConfig(m_dir.path(), "short.json", condition3(0.5));
        // The loop under SCHED_FIFO when allowed (else it says so and runs at normal priority).
        ControllerProcess ctl({"--config", QString::fromStdString(path), "--pace", "realtime",
                               "--realtime-priority", "10", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const TestConfig cfg = loadConfigFile(path);
        const Run linked = runTest(cfg, makeControlFactory(local(ctl.port()), patientOptions()));
        QVERIFY2(linked.state == HybridTest::State::Finished, linked.error.c_str());
        QCOMPARE(linked.records.size(), std::size_t(51));
        const double diff = maxDifference(runTest(cfg, {}), linked);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
        ctl.stop();
        QVERIFY2(ctl.log().contains("deadline misses"), qPrintable(ctl.log()));
    }

    void badRealTimePriorityIsRefused() {
        ControllerProcess ctl({"--config", QString::fromStdString(m_config), "--pace", "realtime",
                               "--realtime-priority", "100", "--quiet"});
        QVERIFY(!ctl.start());
        QVERIFY2(ctl.log().contains("--realtime-priority: expected 1..99, found '100'"),
                 qPrintable(ctl.log()));
    }

    void twoSpecimensShareOneSession() {
        // The paper's reference run: Element 2 is a specimen too (its own copy of the true
        // specimen); one controller serves both, one connection each, one console session.
        nlohmann::json j = condition3(1.0);
        j.erase("updating"); // Element 2 is no longer a numerical model to update
        auto& e2 = j["structure"]["elements"][1];
        e2["experimental"] = true;
        e2["specimen"] = j["structure"]["elements"][0]["specimen"];
        e2["specimen"]["seed"] = 11;
        e2["limits"] = j["structure"]["elements"][0]["limits"];
        const std::string path = writeConfig(m_dir.path(), "two.json", j);
        ControllerProcess ctl(
            {"--config", QString::fromStdString(path), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        QVERIFY(ctl.log().contains("2 specimens"));
        const TestConfig cfg = loadConfigFile(path);
        const Run linked = runTest(cfg, makeControlFactory(local(ctl.port()), patientOptions()));
        QVERIFY2(linked.state == HybridTest::State::Finished, linked.error.c_str());
        const double diff = maxDifference(runTest(cfg, {}), linked);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
    }

    void builtinAddressMeansInProcess() {
        QVERIFY(!makeControlFactory(LinkAddress{})); // empty: core builds VirtualSpecimens
        QVERIFY(makeControlFactory(local(1)));
    }

    void silentControllerIsAFaultNotAHang() {
        // A socket that listens but never answers (the kernel completes the handshake).
        boost::asio::io_context io;
        boost::asio::ip::tcp::acceptor mute(io, {boost::asio::ip::address_v4::loopback(), 0});
        TcpControlOptions o = patientOptions();
        o.stepDeadline = 1.0;
        o.reconnectAttempts = 1;
        TcpControl c("127.0.0.1", mute.local_endpoint().port(), "Element 1", {}, o);
        const ControlResult r = c.prepare(0.01);
        QVERIFY(!r.ok);
        QVERIFY2(r.reason.find("no answer to the hello") != std::string::npos, r.reason.c_str());
        QVERIFY(!c.linkUp());
        QVERIFY(!c.setTarget(0.0).ok); // nothing is sent on a dead link
    }

    void tokenIsChecked() {
        // The token comes from a file (never argv, which ps shows).
        const QString tokenFile = m_dir.filePath("token.txt");
        std::ofstream(tokenFile.toStdString()) << "open sesame\n";
        QFile::setPermissions(tokenFile, QFile::ReadOwner | QFile::WriteOwner); // 0600
        ControllerProcess ctl({"--config", QString::fromStdString(m_config), "--pace", "fast",
                               "--token-file", tokenFile, "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient bad;
        QVERIFY(bad.connect(ctl.port()));
        QVERIFY(bad.send(HelloMsg{kProtocolVersion, 1, "guess", ""}));
        const auto e = bad.expect<ErrorMsg>();
        QVERIFY(e);
        QCOMPARE(e->code, ErrorCode::Unauthorized);
        QVERIFY(bad.closedByPeer());
        // The console's control reports it, and the right token works.
        TcpControlOptions o = patientOptions();
        o.token = "guess";
        TcpControl wrong("127.0.0.1", ctl.port(), "Element 1", {}, o);
        const ControlResult r = wrong.prepare(0.01);
        QVERIFY(!r.ok);
        QVERIFY2(r.reason.find("unauthorized") != std::string::npos, r.reason.c_str());
        o.token = "open sesame";
        TcpControl right("127.0.0.1", ctl.port(), "Element 1", {}, o);
        QVERIFY2(right.prepare(0.01).ok, right.linkError().c_str());
    }

    void wrongVersionIsRefused() {
        ControllerProcess ctl(
            {"--config", QString::fromStdString(m_config), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient header; // a frame of protocol version 2
        QVERIFY(header.connect(ctl.port()));
        std::vector<std::uint8_t> frame;
        encodeRawFrame({kFrameMagic, 2, std::uint16_t(MessageType::Heartbeat), 1, 8},
                       std::vector<std::uint8_t>(8, 0), frame);
        QVERIFY(header.sendRaw(frame));
        auto e = header.expect<ErrorMsg>();
        QVERIFY(e);
        QCOMPARE(e->code, ErrorCode::UnsupportedVersion);
        QVERIFY(header.closedByPeer());
        RawClient hello; // a version-1 frame whose hello asks for version 2
        QVERIFY(hello.connect(ctl.port()));
        QVERIFY(hello.send(HelloMsg{2, 1, "", ""}));
        e = hello.expect<ErrorMsg>();
        QVERIFY(e);
        QCOMPARE(e->code, ErrorCode::UnsupportedVersion);
        QVERIFY(hello.closedByPeer());
    }

    void malformedAndOutOfOrderFramesAreRefused() {
        ControllerProcess ctl(
            {"--config", QString::fromStdString(m_config), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient garbage;
        QVERIFY(garbage.connect(ctl.port()));
        QVERIFY(garbage.sendRaw(std::vector<std::uint8_t>(64, 0x41)));
        auto e = garbage.expect<ErrorMsg>();
        QVERIFY(e);
        QCOMPARE(e->code, ErrorCode::Malformed);
        QVERIFY(garbage.closedByPeer());
        RawClient early; // a target before the hello
        QVERIFY(early.connect(ctl.port()));
        QVERIFY(early.send(TargetMsg{1, 0.0}));
        e = early.expect<ErrorMsg>();
        QVERIFY(e);
        QCOMPARE(e->code, ErrorCode::ProtocolViolation);
        RawClient unknown;
        QVERIFY(unknown.connect(ctl.port()));
        QVERIFY(unknown.send(HelloMsg{kProtocolVersion, 1, "", "Element 7"}));
        e = unknown.expect<ErrorMsg>();
        QVERIFY(e);
        QCOMPARE(e->code, ErrorCode::UnknownElement);
    }

    void secondClientIsBusy() {
        ControllerProcess ctl(
            {"--config", QString::fromStdString(m_config), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient first, second;
        QVERIFY(first.connect(ctl.port()));
        QVERIFY(first.hello(111));
        QVERIFY(second.connect(ctl.port()));
        QVERIFY(second.send(HelloMsg{kProtocolVersion, 222, "", ""}));
        const auto e = second.expect<ErrorMsg>();
        QVERIFY(e);
        QCOMPARE(e->code, ErrorCode::Busy);
        // The code says "busy"; the reason says why, without repeating it ("busy: busy:").
        QVERIFY2(e->reason.find("another console session") != std::string::npos &&
                     e->reason.find("busy") == std::string::npos,
                 e->reason.c_str());
        // Once the first session says bye, the controller is free again (bounded wait).
        QVERIFY(first.send(ByeMsg{"done"}));
        bool admitted = false;
        for (int i = 0; i < 100 && !admitted; ++i) {
            RawClient third;
            admitted = third.connect(ctl.port()) && third.hello(333);
            if (!admitted)
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        QVERIFY(admitted);
    }

    void eachLimitTripsTheInterlock_data() {
        QTest::addColumn<double>("target");
        QTest::addColumn<QString>("limit");
        QTest::newRow("deformation") << 0.012 << "target deformation";
        QTest::newRow("increment") << 0.006 << "target increment";
        QTest::newRow("force") << 0.004 << "measured force";
    }
    void eachLimitTripsTheInterlock() {
        QFETCH(double, target);
        QFETCH(QString, limit);
        nlohmann::json j = condition3(3.0);
        j["structure"]["elements"][0]["specimen"]["interlock"] = {
            {"deformation", 0.01}, {"increment", 0.005}, {"force", 3.0}};
        const std::string path = writeConfig(m_dir.path(), "interlock.json", j);
        ControllerProcess ctl(
            {"--config", QString::fromStdString(path), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY(c.hello(1));
        QVERIFY(c.send(ConfigureMsg{0.01}));
        QVERIFY(c.expect<AckMsg>());
        QVERIFY(c.send(TargetMsg{1, target}));
        const auto e = c.expect<ErrorMsg>();
        QVERIFY(e);
        QCOMPARE(e->code, ErrorCode::Interlock);
        QVERIFY2(e->reason.find(limit.toStdString()) != std::string::npos, e->reason.c_str());
        QVERIFY(c.send(TargetMsg{1, 0.001})); // holding until resumed
        QCOMPARE(c.expect<ErrorMsg>()->code, ErrorCode::Holding);
        QVERIFY(c.send(ResumeMsg{}));
        QVERIFY(c.expect<AckMsg>());
        QVERIFY(c.send(TargetMsg{1, 0.001}));
        QVERIFY(c.expect<MeasurementMsg>());
    }

    void interlockHoldsTheHybridTest() {
        double peak = 0.0; // half the peak force of the uninterrupted run trips for sure
        for (const auto& r : runTest(loadConfigFile(m_config), {}).records)
            peak = std::max(peak, std::abs(r.elements[0].force));
        QVERIFY(peak > 0.0);
        nlohmann::json j = condition3(3.0);
        j["structure"]["elements"][0]["specimen"]["interlock"] = {{"force", 0.5 * peak}};
        const std::string path = writeConfig(m_dir.path(), "force.json", j);
        ControllerProcess ctl(
            {"--config", QString::fromStdString(path), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const Run run =
            runTest(loadConfigFile(path), makeControlFactory(local(ctl.port()), patientOptions()));
        QVERIFY2(run.prepared, run.error.c_str());
        QCOMPARE(run.state, HybridTest::State::Holding);
        QVERIFY2(run.error.find("interlock: measured force") != std::string::npos,
                 run.error.c_str());
        QVERIFY(run.records.size() > 1 && everyStepOnce(run));
    }

    void lateTargetMakesThePredictorCorrectorHold() {
        ControllerProcess ctl(
            {"--config", QString::fromStdString(m_config), "--pace", "realtime", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY(c.hello(1));
        QVERIFY(c.send(ConfigureMsg{0.01}));
        QVERIFY(c.expect<AckMsg>());
        for (std::uint64_t n = 1; n <= 3; ++n) {
            QVERIFY(c.send(TargetMsg{n, 1e-4 * double(n)}));
            QVERIFY(c.expect<MeasurementMsg>());
            QVERIFY(c.send(CommitMsg{n}));
            QVERIFY(c.expect<AckMsg>());
        }
        // A step lasts ~10 ms at 1024 Hz; a target 300 ms late finds the actuator holding.
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        QVERIFY(c.send(TargetMsg{4, 4e-4}));
        const auto m = c.expect<MeasurementMsg>();
        QVERIFY(m);
        QVERIFY2(m->heldTicks > 0, qPrintable(QString::number(m->heldTicks)));
        QCOMPARE(m->commanded, 4e-4); // and still reaches the target exactly
    }
};

QTEST_GUILESS_MAIN(TestControllerProcess)
#include "TestControllerProcess.moc"
