// Issue 24 on hsmu-controller: each actuator channel of an N-channel specimen runs its own
// predictor-corrector and actuator model at the controller's loop rate (comms/controller/
// ActuatorLoop.h, SpecimenStation.h "N actuator channels"):
// - ideal actuators at 1024 Hz (10 ticks per step, 5 predicted) on a real controller process
//   give the two-actuator column frame equal to the once-per-step in-process lab and to the
//   all-numerical frame to 1e-9 of the peak;
// - lagging actuators (lateral tau 5 ms, vertical force loop tau 3 ms) at 1000 Hz without
//   prediction (the command a linear ramp over the K = 10 ticks of each step) give each
//   channel's reached value in the discrete lag's closed form to 1e-12 of the peak;
// - a late Targets frame holds every channel for the same held ticks (real-time pace, ticked
//   here by hand: no clock), and each channel still ends its step on its target;
// - a channel's bound is checked every tick: a servo-hydraulic lateral actuator overshooting
//   its stroke limit inside a step trips, naming the channel, and every actuator is put back
//   at its committed stroke and force.
#include "comms/controller/SpecimenStation.h"
#include "comms/link/ControlFactory.h"

#include "../ControllerProcess.h"
#include "../RawClient.h"
#include "ChannelLoopsFixture.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;
using namespace multiactuator;
using namespace channelloops;

namespace {

ElementSpec column(const nlohmann::json& j) {
    return parseConfig(j, "memory.json").elements[0];
}

std::optional<MeasurementsMsg> measurements(const std::optional<Message>& m) {
    if (m && std::holds_alternative<MeasurementsMsg>(*m))
        return std::get<MeasurementsMsg>(*m);
    if (m && std::holds_alternative<ErrorMsg>(*m))
        qWarning("error: %s", std::get<ErrorMsg>(*m).reason.c_str());
    return std::nullopt;
}

} // namespace

class TestChannelLoops : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void idealChannelsEqualTheOncePerStepLabAndTheNumericalFrame() {
        const std::string path = writeConfig(m_dir.path(), "frame.json", preset(5.0));
        ControllerProcess ctl(
            {"--config", QString::fromStdString(path), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const TestConfig cfg = loadConfigFile(path);
        const Run linked = runTest(cfg, nativeAt(ctl.port()));
        QVERIFY2(linked.state == HybridTest::State::Finished, linked.error.c_str());
        QCOMPARE(linked.records.size(), std::size_t(501));
        QVERIFY(everyStepOnce(linked));
        const Run inProcess = runTest(cfg, {}); // each channel evaluated once per step
        const Run numerical = runTest(parseConfig(numericalTwin(preset(5.0)), "twin.json"), {});
        const double vsLab = maxDifference(inProcess, linked);
        const double vsNumerical = relativeDifference(numerical, linked);
        qInfo("ideal channels at 1024 Hz: max |diff| to the once-per-step lab %.3g, relative to "
              "the numerical frame %.3g",
              vsLab, vsNumerical);
        QVERIFY2(vsLab <= 1e-9, qPrintable(QString::number(vsLab)));
        QVERIFY2(vsNumerical <= 1e-9, qPrintable(QString::number(vsNumerical)));
    }

    void lagChannelsFollowTheClosedForm() {
        const double tauL = 0.005, tauV = 0.003, rate = 1000.0, h = 1.0 / rate;
        const int K = 10; // dt 0.01 s at 1000 Hz
        const std::string path =
            writeConfig(m_dir.path(), "lag.json", lagColumn(tauL, tauV, rate, 0.0));
        ControllerProcess ctl(
            {"--config", QString::fromStdString(path), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY(c.send(HelloMsg{kProtocolVersion, 11, "", "Column L"}));
        QVERIFY(c.expect<HelloAckMsg>());
        QVERIFY(c.send(ConfigureMsg{0.01}));
        QVERIFY(c.expect<AckMsg>());
        const double lateral[] = {0.001, 0.004, 0.002, 0.002, 0.002, -0.001, 0.0, 0.003};
        const double vertical[] = {-500, -500, -450, -450, -300, -300, -500, -500};
        double aL = 0, aV = 0, cL = 0, cV = 0, worstL = 0, worstV = 0;
        for (std::uint64_t n = 1; n <= 8; ++n) {
            const double tL = lateral[n - 1], tV = vertical[n - 1];
            QVERIFY(c.send(TargetsMsg{n, {{kChannelForce, tV}, {kChannelDisplacement, tL}}}));
            const auto mm = c.expect<MeasurementsMsg>();
            QVERIFY2(mm && mm->step == n && mm->channels.size() == 2, "a measurement");
            aL = lagAfterRamp(aL, cL, tL, K, h, tauL);
            aV = lagAfterRamp(aV, cV, tV, K, h, tauV);
            cL = tL;
            cV = tV;
            QCOMPARE(mm->channels[0].command, tV); // each command ends its step on the target
            QCOMPARE(mm->channels[1].command, tL);
            worstL = std::max({worstL, std::abs(mm->channels[1].stroke - aL),
                               std::abs(mm->channels[1].force - 1000.0 * aL) / 1000.0});
            worstV = std::max({worstV, std::abs(mm->channels[0].force - aV),
                               std::abs(mm->channels[0].stroke - aV / 2e5) * 2e5});
            QVERIFY(c.send(CommitMsg{n}));
            QVERIFY(c.expect<AckMsg>());
        }
        qInfo("lag over %d ticks: lateral max |diff| %.3g m (peak 0.004), vertical %.3g kN "
              "(peak 500)",
              K, worstL, worstV);
        QVERIFY2(worstL <= 1e-12 * 0.004, qPrintable(QString::number(worstL)));
        QVERIFY2(worstV <= 1e-12 * 500.0, qPrintable(QString::number(worstV)));
        QVERIFY(std::abs(aL - 0.003) > 1e-4); // the lag is visible: not the ideal actuator
    }

    void lateTargetsHoldEveryChannel() {
        SpecimenStation st(0, column(lagColumn(0.005, 0.0, 1024.0, 0.5)), ControllerSettings{},
                           SpecimenStation::Pace::RealTime, nullptr);
        QVERIFY(std::holds_alternative<AckMsg>(st.configure(ConfigureMsg{0.01}))); // N 10, P 5
        const auto step = [&](std::uint64_t n, double lateral, int late) {
            for (int i = 0; i < 5 + late; ++i)
                QVERIFY(!st.tick()); // predicted, then late: no measurement
            QVERIFY(!st.targets(
                TargetsMsg{n, {{kChannelForce, -500.0}, {kChannelDisplacement, lateral}}}));
            std::optional<Message> m;
            for (int i = 0; i < 100 && !m; ++i)
                m = st.tick();
            const auto mm = measurements(m);
            QVERIFY(mm && mm->step == n);
            QCOMPARE(st.loop(0).heldTicks(), late);
            QCOMPARE(st.loop(1).heldTicks(), late);
            QCOMPARE(mm->channels[0].command, -500.0);
            QCOMPARE(mm->channels[1].command, lateral);
            QVERIFY(std::holds_alternative<AckMsg>(st.commit(CommitMsg{n})));
        };
        step(1, 0.001, 0);
        step(2, 0.002, 0);
        step(3, 0.003, 12); // 12 ticks late
        step(4, 0.003, 0);
        QVERIFY(!st.holding());
        QCOMPARE(st.totalHeldTicks(), 12L);
    }

    void servoOvershootTripsInsideTheStep() {
        nlohmann::json j = preset(1.0);
        nlohmann::json& lateral = j["structure"]["elements"][0]["actuators"][1];
        lateral["material"] = {{"law", "elastic"}, {"k", 1000.0}};
        lateral["actuator"] = {{"type", "servoHydraulic"}};
        lateral["limits"]["deformation"] = 0.0101;
        SpecimenStation st(0, column(j), ControllerSettings{}, SpecimenStation::Pace::Fast,
                           nullptr);
        QVERIFY(std::holds_alternative<AckMsg>(st.configure(ConfigureMsg{0.01})));
        QVERIFY(measurements(
            st.targets(TargetsMsg{1, {{kChannelForce, -500.0}, {kChannelDisplacement, 0.0}}})));
        QVERIFY(std::holds_alternative<AckMsg>(st.commit(CommitMsg{1})));
        // A 10 mm target, inside the 10.1 mm stroke limit, held: the servo (kp 2, ki 95 /s)
        // reaches 7.6 mm in two steps and overshoots the limit at a tick of the third.
        const TargetsMsg hold10{0, {{kChannelForce, -500.0}, {kChannelDisplacement, 0.01}}};
        double committed = 0.0;
        for (std::uint64_t n = 2; n <= 3; ++n) {
            TargetsMsg t = hold10;
            t.step = n;
            const auto mm = measurements(st.targets(t));
            QVERIFY(mm);
            committed = mm->channels[1].stroke;
            QVERIFY(std::holds_alternative<AckMsg>(st.commit(CommitMsg{n})));
        }
        QVERIFY(committed > 0.007 && committed < 0.0101);
        const double f0 = st.rig()->lab().committedForce(0);
        TargetsMsg t = hold10;
        t.step = 4;
        const auto r = st.targets(t);
        QVERIFY(r && std::holds_alternative<ErrorMsg>(*r));
        const ErrorMsg e = std::get<ErrorMsg>(*r);
        QCOMPARE(e.code, ErrorCode::Interlock);
        QVERIFY2(e.reason.find("channel 2 'lateral': actuator stroke |d| = ") != std::string::npos,
                 e.reason.c_str());
        QVERIFY(st.holding());
        QCOMPARE(st.rig()->lab().committedStroke(1), committed);
        QCOMPARE(st.rig()->lab().actuator(1).law->trialDeformation(), committed);
        QCOMPARE(st.rig()->lab().actuator(0).law->trialForce(), f0);
        QCOMPARE(st.loop(1).achieved(), committed); // the actuator back at its committed stroke
        QCOMPARE(st.loop(0).achieved(), -500.0);
        QVERIFY(st.loop(1).peakCommand() <= 0.0101); // no command ever left the limit
    }
};

QTEST_GUILESS_MAIN(TestChannelLoops)
#include "TestChannelLoops.moc"
