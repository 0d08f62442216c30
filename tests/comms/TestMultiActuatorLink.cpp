// Issue 24's acceptance over the native protocol: the one-bay frame whose left column is the
// two-actuator specimen (preset two-actuator-column-frame: a force-controlled vertical
// actuator holding 500 kN, a displacement-controlled lateral one) runs end to end on a real
// hsmu-controller process, its two channels in Targets / Measurements frames, and equals both
// the in-process virtual lab run and the all-numerical frame (that column numerical, same laws,
// axial load held) to 1e-9 of the peak. A dropped link, a channel's limit tripped at the
// controller and an emergency hold each leave every actuator holding (the hello-ack's
// per-channel committed commands are the test's last committed ones) and the record keeps
// every step exactly once; a lost commit acknowledgement is settled without a hold; a
// controller killed mid-run and restarted without a state file leaves the test held.
#include "comms/link/ControlFactory.h"

#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "LoopbackProxy.h"
#include "MultiActuatorFixture.h"
#include "RawClient.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;
using namespace multiactuator;

namespace {

TcpControlOptions patient(std::uint64_t session = 0) {
    TcpControlOptions o; // generous: a loaded 2-core CI machine
    o.connectTimeout = 20.0;
    o.stepDeadline = 30.0;
    o.silenceTimeout = 30.0;
    o.reconnectAttempts = 3;
    o.reconnectDelay = 0.2;
    o.sessionId = session;
    return o;
}

LinkAddress local(quint16 port) {
    return LinkAddress{LinkAddress::Kind::Tcp, "127.0.0.1", port};
}

/// The specimen's state as a second connection of the same console session sees it.
std::optional<HelloAckMsg> specimenSeenBy(std::uint16_t port, std::uint64_t session) {
    RawClient c;
    if (!c.connect(port) || !c.send(HelloMsg{kProtocolVersion, session, "", "Column L"}))
        return std::nullopt;
    return c.expect<HelloAckMsg>();
}

/// The committed commands of the last recorded step: vertical (held force), lateral (the
/// shear DOF's commanded stroke: NoTransformation -dir 1 2).
bool holdsAtLastStep(const HelloAckMsg& ack, const Run& run) {
    return ack.holding && ack.channelCommands.size() == 2 &&
           ack.channelCommands[0] == -500.0 &&
           ack.channelCommands[1] == run.records.back().elements[0].commanded;
}

} // namespace

class TestMultiActuatorLink : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::string m_config;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_config = writeConfig(m_dir.path(), "frame.json", preset(5.0));
    }

    void nativeRunEqualsNumericalFrame() {
        ControllerProcess ctl(
            {"--config", QString::fromStdString(m_config), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const TestConfig cfg = loadConfigFile(m_config);
        const Run linked = runTest(cfg, makeControlFactory(local(ctl.port()), patient()));
        QVERIFY2(linked.state == HybridTest::State::Finished, linked.error.c_str());
        QCOMPARE(linked.records.size(), std::size_t(501));
        QVERIFY(everyStepOnce(linked));
        const Run inProcess = runTest(cfg, {});
        const Run numerical = runTest(parseConfig(numericalTwin(preset(5.0)), "twin.json"), {});
        QCOMPARE(numerical.state, HybridTest::State::Finished);
        const double vsLab = maxDifference(inProcess, linked);
        const double vsNumerical = relativeDifference(numerical, linked);
        qInfo("over the native protocol: max |diff| to the in-process lab %.3g, relative to the "
              "numerical frame %.3g", vsLab, vsNumerical);
        QVERIFY2(vsLab <= 1e-9, qPrintable(QString::number(vsLab)));
        QVERIFY2(vsNumerical <= 1e-9, qPrintable(QString::number(vsNumerical)));
        // Two actuators give the element no one actuator command or position: none over the
        // link, as in process (each is in the channels; before, the link reported channel 0's
        // -500 kN force command, drawn in the element's tracking plot in metres).
        for (std::size_t k = 1; k < linked.records.size(); ++k)
            for (const ElementSample& e : linked.records[k].elements) {
                QVERIFY2(std::isnan(e.actuator.commanded) && std::isnan(e.actuator.measured),
                         qPrintable(QString("step %1: actuator command %2").arg(k).arg(e.actuator.commanded)));
            }
    }

    void channelCountMismatchIsRefused() {
        ControllerProcess ctl(
            {"--config", QString::fromStdString(m_config), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        TcpControlOptions o = patient();
        o.channelModes = {ActuatorMode::Force, ActuatorMode::Displacement,
                          ActuatorMode::Displacement};
        TcpControl three("127.0.0.1", ctl.port(), "Column L", {}, o);
        const ControlResult r = three.prepare(0.01);
        QVERIFY(!r.ok);
        QVERIFY2(r.reason.find("'Column L' has 2 actuator channel(s) at the controller, the "
                               "configuration gives it 3") != std::string::npos,
                 r.reason.c_str());
        TcpControl one("127.0.0.1", ctl.port(), "Column L", {}, patient()); // one channel
        QVERIFY(!one.prepare(0.01).ok);
        // A one-channel frame to the two-channel specimen: a protocol violation, nothing moves.
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY(c.hello(7));
        QVERIFY(c.send(ConfigureMsg{0.01}));
        QVERIFY(c.expect<AckMsg>());
        QVERIFY(c.send(TargetMsg{1, 0.001}));
        const auto e = c.expect<ErrorMsg>();
        QVERIFY(e && e->code == ErrorCode::ProtocolViolation);
        QVERIFY2(e->reason.find("2 actuator channels") != std::string::npos, e->reason.c_str());
        // The console's mode must be the controller's: the vertical actuator is force-controlled.
        QVERIFY(c.send(TargetsMsg{1, {{kChannelDisplacement, 0.0}, {kChannelDisplacement, 0.001}}}));
        const auto m = c.expect<ErrorMsg>();
        QVERIFY(m && m->code == ErrorCode::ProtocolViolation);
        QVERIFY2(m->reason.find("channel 1 'vertical' is under force control") != std::string::npos,
                 m->reason.c_str());
    }

    void droppedLinkHoldsAndResumes() {
        ControllerProcess ctl(
            {"--config", QString::fromStdString(m_config), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        LoopbackProxy proxy(ctl.port());
        proxy.cutAfter(MessageType::Targets, 150); // step 150's measurement is lost
        const std::uint64_t session = 0x24a;
        const TestConfig cfg = loadConfigFile(m_config);
        std::optional<HelloAckMsg> seen;
        const Run run = runTest(
            cfg, makeControlFactory(local(proxy.port()), patient(session)), {},
            [&] { seen = specimenSeenBy(ctl.port(), session); }, 1);
        QCOMPARE(proxy.cuts(), 1);
        QCOMPARE(run.holds, 1);
        QVERIFY2(seen && seen->committedSteps == 149 && seen->channelCommands.size() == 2,
                 "the controller kept the specimen at step 149");
        QCOMPARE(seen->channelCommands[0], -500.0);
        QVERIFY2(run.state == HybridTest::State::Finished, run.error.c_str());
        QVERIFY(everyStepOnce(run));
        const Run numerical = runTest(parseConfig(numericalTwin(preset(5.0)), "twin.json"), {});
        const double diff = relativeDifference(numerical, run);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
    }

    void lostCommitIsSettledWithoutAHold() {
        // The commit of step 200 reaches the controller, its acknowledgement is lost: commit()
        // reconnects and the controller's step count settles it (TcpControl's one path).
        // Real-time pace: the N-channel steps are still evaluated when their targets arrive.
        ControllerProcess ctl(
            {"--config", QString::fromStdString(m_config), "--pace", "realtime", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        LoopbackProxy proxy(ctl.port());
        proxy.cutAfter(MessageType::Commit, 200);
        const Run run = runTest(loadConfigFile(m_config),
                                makeControlFactory(local(proxy.port()), patient()));
        QCOMPARE(proxy.cuts(), 1);
        QCOMPARE(run.holds, 0);
        QVERIFY2(run.state == HybridTest::State::Finished, run.error.c_str());
        QVERIFY(everyStepOnce(run));
        const Run numerical = runTest(parseConfig(numericalTwin(preset(5.0)), "twin.json"), {});
        const double diff = relativeDifference(numerical, run);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
    }

    void channelLimitTripHoldsEveryActuator() {
        // The controller's file is tighter on the lateral channel (4 mm) than the console's.
        nlohmann::json tight = preset(5.0);
        tight["structure"]["elements"][0]["actuators"][1]["limits"]["deformation"] = 0.004;
        const std::string path = writeConfig(m_dir.path(), "tight.json", tight);
        ControllerProcess ctl({"--config", QString::fromStdString(path), "--pace", "fast"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const std::uint64_t session = 0x24b;
        const Run run = runTest(loadConfigFile(m_config),
                                makeControlFactory(local(ctl.port()), patient(session)));
        QCOMPARE(run.state, HybridTest::State::Holding);
        QVERIFY(run.records.size() > 10);
        QVERIFY(everyStepOnce(run));
        QVERIFY2(run.error.find("channel 2 'lateral'") != std::string::npos, run.error.c_str());
        const auto seen = specimenSeenBy(ctl.port(), session); // after the console's bye
        QVERIFY(seen);
        QVERIFY2(seen->holdReason.find("interlock: channel 2 'lateral': target") !=
                     std::string::npos,
                 seen->holdReason.c_str());
        QVERIFY2(holdsAtLastStep(*seen, run), "every actuator at its last committed command");
        QCOMPARE(seen->committedSteps, std::uint64_t(run.records.size() - 1));
        QVERIFY(std::abs(run.records.back().elements[0].commanded) <= 0.004);
        QVERIFY2(ctl.waitForLog("channel 2 'lateral'"), qPrintable(ctl.log()));
    }

    void emergencyHoldHoldsEveryActuator() {
        ControllerProcess ctl(
            {"--config", QString::fromStdString(m_config), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const std::uint64_t session = 0x24c;
        const TestConfig cfg = loadConfigFile(m_config);
        auto test = buildHybridTest(cfg, makeControlFactory(local(ctl.port()), patient(session)));
        Recorder rec;
        test->addObserver(&rec);
        QVERIFY(test->prepare());
        int guard = 0;
        while (test->step() == HybridTest::StepResult::Advanced && ++guard < 100) {
        }
        test->emergencyHold("operator: emergency stop");
        QCOMPARE(test->step(), HybridTest::StepResult::Held);
        Run run;
        run.records = rec.records;
        QCOMPARE(run.records.size(), std::size_t(101));
        const auto seen = specimenSeenBy(ctl.port(), session);
        QVERIFY(seen);
        QVERIFY2(holdsAtLastStep(*seen, run), "every actuator at its last committed command");
        QCOMPARE(seen->committedSteps, std::uint64_t(100));
        test->resume(); // the connection the check replaced is reconnected
        while (test->step() == HybridTest::StepResult::Advanced) {
        }
        QVERIFY2(test->state() == HybridTest::State::Finished,
                 test->alarms().empty() ? "held" : test->alarms().back().message.c_str());
        test->removeObserver(&rec);
        run.records = rec.records;
        QVERIFY(everyStepOnce(run));
        const Run numerical = runTest(parseConfig(numericalTwin(preset(5.0)), "twin.json"), {});
        const double diff = relativeDifference(numerical, run);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
    }

    void killedControllerLeavesTheTestHeld() {
        auto ctl = std::make_unique<ControllerProcess>(
            QStringList{"--config", QString::fromStdString(m_config), "--pace", "fast",
                        "--quiet"});
        QVERIFY2(ctl->start(), qPrintable(ctl->log()));
        const quint16 port = ctl->port();
        TcpControlOptions o = patient();
        o.reconnectAttempts = 2;
        o.stepDeadline = 5.0;
        const Run run = runTest(
            loadConfigFile(m_config), makeControlFactory(local(port), o),
            [&](int step) {
                if (step == 120)
                    ctl->kill();
            },
            [&] { // restarted without a journal: a virgin specimen, step 0 (with its journal
                  // it continues: test_comms_controller_channel_journal)
                ctl = std::make_unique<ControllerProcess>(
                    QStringList{"--config", QString::fromStdString(m_config), "--pace", "fast",
                                "--quiet", "--no-state-file"});
                QVERIFY(ctl->start(port));
            },
            1);
        QCOMPARE(run.state, HybridTest::State::Holding);
        QCOMPARE(run.records.size(), std::size_t(121)); // steps 0..120, each once
        QVERIFY(everyStepOnce(run));
        QVERIFY2(run.error.find("cannot resume without a jump") != std::string::npos,
                 run.error.c_str());
    }
};

QTEST_MAIN(TestMultiActuatorLink)
#include "TestMultiActuatorLink.moc"
