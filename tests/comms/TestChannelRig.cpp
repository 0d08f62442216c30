// An N-channel specimen on the controller without sockets (comms/controller/ChannelRig.h
// through SpecimenStation): the preset two-actuator column's vertical actuator (force control,
// elastic 2e5 kN/m) holds its force at the stroke F / k, the lateral one (displacement control,
// Bouc-Wen) takes its stroke; re-sends are idempotent; each channel's limit trips the station
// naming the channel, and the trip puts every actuator back at its committed stroke and force.
#include "comms/controller/SpecimenStation.h"
#include "core/config/ConfigLoader.h"

#include <QtTest>

#include <fstream>

using namespace hsmu;
using namespace hsmu::comms;

namespace {

ElementSpec columnSpec(double verticalStrokeLimit = 0.01) {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) +
                     "/resources/presets/two-actuator-column-frame.json");
    nlohmann::json j = nlohmann::json::parse(in);
    j["structure"]["elements"][0]["actuators"][0]["limits"]["deformation"] = verticalStrokeLimit;
    return parseConfig(j, "memory.json").elements[0];
}

TargetsMsg targets(std::uint64_t step, double lateral, double vertical = -500.0) {
    return TargetsMsg{step, {{kChannelForce, vertical}, {kChannelDisplacement, lateral}}};
}

} // namespace

class TestChannelRig : public QObject {
    Q_OBJECT
private slots:
    void forceAndDisplacementChannels() {
        SpecimenStation st(0, columnSpec(), ControllerSettings{}, SpecimenStation::Pace::Fast,
                           nullptr);
        QCOMPARE(st.status().channelCommands, (std::vector<double>{0.0, 0.0}));
        QVERIFY(std::holds_alternative<ErrorMsg>(*st.targets(targets(1, 0.001)))); // unconfigured
        QVERIFY(std::holds_alternative<AckMsg>(st.configure(ConfigureMsg{0.01})));
        const Message m = *st.targets(targets(1, 0.001));
        QVERIFY(std::holds_alternative<MeasurementsMsg>(m));
        const auto& mm = std::get<MeasurementsMsg>(m);
        QCOMPARE(mm.channels.size(), std::size_t(2));
        QVERIFY(std::abs(mm.channels[0].force + 500.0) <= 1e-12 * 500.0);
        QVERIFY(std::abs(mm.channels[0].stroke + 500.0 / 2e5) <= 1e-15); // F / k [m]
        QCOMPARE(mm.channels[1].stroke, 0.001);
        QVERIFY(mm.channels[1].force > 0.0);
        // The same targets again: the same answer, flagged as repeated, no new trial.
        const auto again = std::get<MeasurementsMsg>(*st.targets(targets(1, 0.001)));
        QCOMPARE(again.flags, kFlagReplayed);
        QCOMPARE(again.channels[1].force, mm.channels[1].force);
        QVERIFY(std::holds_alternative<AckMsg>(st.commit(CommitMsg{1})));
        QCOMPARE(st.status().channelCommands, (std::vector<double>{-500.0, 0.001}));
        QCOMPARE(st.status().lastCommittedTarget, 0.001); // the lateral stroke, not the force
        QVERIFY(std::holds_alternative<AckMsg>(st.commit(CommitMsg{1}))); // repeated commit
        QCOMPARE(st.committedSteps(), std::uint64_t(1));
        // The committed step re-sent with other targets: a state mismatch.
        const Message other = *st.targets(targets(1, 0.002));
        const auto* e = std::get_if<ErrorMsg>(&other);
        QVERIFY(e && e->code == ErrorCode::StateMismatch);
    }

    void eachChannelsLimitTripsAndEveryActuatorHolds() {
        SpecimenStation st(0, columnSpec(), ControllerSettings{}, SpecimenStation::Pace::Fast,
                           nullptr);
        st.configure(ConfigureMsg{0.01});
        QVERIFY(std::holds_alternative<MeasurementsMsg>(*st.targets(targets(1, 0.01))));
        QVERIFY(std::holds_alternative<AckMsg>(st.commit(CommitMsg{1})));
        const double f1 = st.rig()->lab().committedForce(1);
        // Lateral: increment limit 0.05 m per step (the preset's), stroke limit 0.2 m.
        const Message m = *st.targets(targets(2, 0.07));
        const auto* e = std::get_if<ErrorMsg>(&m);
        QVERIFY(e && e->code == ErrorCode::Interlock);
        QVERIFY2(e->reason.find("channel 2 'lateral': ") != std::string::npos, e->reason.c_str());
        QVERIFY(st.holding());
        QCOMPARE(st.rig()->lab().committedStroke(1), 0.01);
        QCOMPARE(st.rig()->lab().committedForce(1), f1);
        QCOMPARE(st.rig()->lab().actuator(1).law->trialDeformation(), 0.01);
        QVERIFY(std::holds_alternative<ErrorMsg>(*st.targets(targets(2, 0.02)))); // holding
        st.resume();
        // Vertical: a force past its 1000 kN limit is never applied.
        const Message f = *st.targets(targets(2, 0.02, -1200.0));
        e = std::get_if<ErrorMsg>(&f);
        QVERIFY(e && e->code == ErrorCode::Interlock);
        QVERIFY2(e->reason.find("channel 1 'vertical': ") != std::string::npos, e->reason.c_str());
        const VirtualActuatorLab& lab = st.rig()->lab(); // every actuator at its committed state
        QCOMPARE(lab.actuator(0).law->trialForce(), lab.committedForce(0));
        QVERIFY(std::abs(lab.committedForce(0) + 500.0) <= 1e-12 * 500.0);
        QCOMPARE(lab.actuator(1).law->trialDeformation(), 0.01);
        QCOMPARE(lab.actuator(1).law->trialForce(), f1);
    }

    void forceChannelPastItsStrokeLimitTrips() {
        // The vertical actuator's stroke under 500 kN is 2.5 mm; its limit 2 mm (+5 %): the
        // measured stroke trips it, naming the channel, before anything is committed.
        SpecimenStation st(0, columnSpec(0.002), ControllerSettings{}, SpecimenStation::Pace::Fast,
                           nullptr);
        st.configure(ConfigureMsg{0.01});
        const Message m = *st.targets(targets(1, 0.001));
        const auto* e = std::get_if<ErrorMsg>(&m);
        QVERIFY(e && e->code == ErrorCode::Interlock);
        QVERIFY2(e->reason.find("channel 1 'vertical': measured") != std::string::npos,
                 e->reason.c_str());
        QCOMPARE(st.committedSteps(), std::uint64_t(0));
        QCOMPARE(st.rig()->lab().actuator(0).law->trialDeformation(), 0.0); // back at rest
        QCOMPARE(st.rig()->lab().actuator(1).law->trialDeformation(), 0.0);
    }

    void oneChannelFramesAreRefused() {
        SpecimenStation st(0, columnSpec(), ControllerSettings{}, SpecimenStation::Pace::Fast,
                           nullptr);
        st.configure(ConfigureMsg{0.01});
        const auto r = st.target(TargetMsg{1, 0.001});
        QVERIFY(r && std::holds_alternative<ErrorMsg>(*r));
        QCOMPARE(std::get<ErrorMsg>(*r).code, ErrorCode::ProtocolViolation);
        QVERIFY(!st.holding());
    }
};

QTEST_MAIN(TestChannelRig)
#include "TestChannelRig.moc"
