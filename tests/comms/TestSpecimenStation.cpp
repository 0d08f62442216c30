// The virtual lab's parts without sockets (comms/controller): the predictor-corrector's
// extrapolation, correction and hold; the actuator models; a SpecimenStation against the
// in-process VirtualSpecimen (bit-equal with an ideal actuator); idempotent re-sends; every
// interlock limit; the state journal's replay and its refusals.
#include "comms/controller/SpecimenStation.h"
#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"

#include "LinkFixture.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <random>

using namespace hsmu;
using namespace hsmu::comms;

namespace {

ElementSpec specimenSpec(const nlohmann::json& interlock = nullptr) {
    nlohmann::json j = linkfixture::condition3();
    if (!interlock.is_null())
        j["structure"]["elements"][0]["specimen"]["interlock"] = interlock;
    return parseConfig(j, "memory.json").elements[0];
}

double targetAt(int n) {
    return 0.03 * std::sin(0.05 * n) * (1.0 + 0.01 * n);
} // [rad]

MeasurementMsg expectMeasurement(const std::optional<Message>& m) {
    if (!m || !std::holds_alternative<MeasurementMsg>(*m)) {
        const auto* e = m ? std::get_if<ErrorMsg>(&*m) : nullptr;
        qWarning("expected a measurement, got %s", e ? e->reason.c_str() : "nothing");
        return MeasurementMsg{~0ull, NAN, NAN, NAN, 0, 0};
    }
    return std::get<MeasurementMsg>(*m);
}

std::optional<ErrorMsg> asError(const std::optional<Message>& m) {
    if (m && std::holds_alternative<ErrorMsg>(*m))
        return std::get<ErrorMsg>(*m);
    return std::nullopt;
}

bool acked(const Message& m) {
    return std::holds_alternative<AckMsg>(m);
}

ConfigureMsg configure001() {
    return ConfigureMsg{0.01};
}

} // namespace

class TestSpecimenStation : public QObject {
    Q_OBJECT
private slots:
    void predictorExtrapolatesAQuadraticExactly() {
        PredictorCorrector pc;
        pc.setTiming(10, 5);
        pc.beginStep(9.0, 9.0, 4.0, 1.0); // f(k) = k^2 at k = 3, 2, 1
        for (int i = 1; i <= 5; ++i) {
            const double c = pc.tick();
            QVERIFY(std::abs(c - std::pow(3.0 + i / 10.0, 2)) < 1e-12);
        }
        QCOMPARE(pc.phase(), PredictorCorrector::Phase::Late);
        const double heldAt = pc.command();
        for (int i = 0; i < 7; ++i)
            QCOMPARE(pc.tick(), heldAt); // late: the actuator holds
        QCOMPARE(pc.heldTicks(), 7);
        pc.setTarget(16.0);
        for (int j = 1; j <= 5; ++j)
            pc.tick(); // correction over N - P = 5 ticks
        QCOMPARE(pc.phase(), PredictorCorrector::Phase::Arrived);
        QCOMPARE(pc.command(), 16.0); // exactly
    }

    void earlyTargetIsReachedInTheRestOfTheStep() {
        PredictorCorrector pc;
        pc.setTiming(10, 5);
        pc.beginStep(0.0, 0.0, 0.0, 0.0);
        pc.tick();
        pc.tick();
        pc.setTarget(1.0);
        for (int j = 1; j <= 7; ++j) {
            pc.tick();
            QCOMPARE(pc.phase(), PredictorCorrector::Phase::Correcting);
        }
        pc.tick(); // the 8th = N - 2
        QCOMPARE(pc.phase(), PredictorCorrector::Phase::Arrived);
        QCOMPARE(pc.command(), 1.0);
        QCOMPARE(pc.heldTicks(), 0);
    }

    void actuatorModels() {
        ActuatorDynamics ideal(ActuatorModel{}, 1024.0);
        QCOMPARE(ideal.tick(0.3), 0.3);
        ActuatorModel lagModel{ActuatorModel::Type::Lag, 0.01, 0.0};
        ActuatorDynamics lag(lagModel, 1000.0);
        lag.reset(0.0);
        const double k = 1.0 - std::exp(-0.001 / 0.01);
        QVERIFY(std::abs(lag.tick(1.0) - k) < 1e-15);
        QVERIFY(std::abs(lag.tick(1.0) - (k + (1 - k) * k)) < 1e-15);
        ActuatorModel delayModel{ActuatorModel::Type::Delay, 0.0, 0.003};
        ActuatorDynamics delay(delayModel, 1000.0); // 3 ticks
        delay.reset(0.0);
        QCOMPARE(delay.tick(1.0), 0.0);
        QCOMPARE(delay.tick(2.0), 0.0);
        QCOMPARE(delay.tick(3.0), 0.0);
        QCOMPARE(delay.tick(4.0), 1.0);
        // servoHydraulic: the ServoActuator at the controller's rate (its own "rate" ignored),
        // bit for bit; it lags a step command and settles on it.
        ActuatorModel servoModel{ActuatorModel::Type::ServoHydraulic, 0.0, 0.0};
        servoModel.servo.rate = 4096.0;
        ActuatorDynamics servo(servoModel, 1024.0);
        servo.reset(0.0);
        rths::ServoActuatorSettings alone = servoModel.servo;
        alone.rate = 1024.0;
        rths::ServoActuator reference(alone);
        double early = 0.0;
        for (int i = 0; i < 10; ++i) { // 10 ms: under way, far from there yet
            early = servo.tick(0.002);
            QCOMPARE(early, reference.tick(0.002));
        }
        QVERIFY2(early > 0.0 && early < 0.0015, qPrintable(QString::number(early)));
        double last = early;
        for (int i = 0; i < 2048; ++i) {
            last = servo.tick(0.002);
            QCOMPARE(last, reference.tick(0.002));
        }
        QVERIFY(std::abs(last - 0.002) < 1e-6);
    }

    void fastStationEqualsTheInProcessSpecimen() {
        const ElementSpec spec = specimenSpec();
        auto reference = buildVirtualSpecimen(spec);
        QVERIFY(reference->prepare(0.01).ok);
        SpecimenStation st(0, spec, ControllerSettings{}, SpecimenStation::Pace::Fast, nullptr);
        QVERIFY(acked(st.configure(configure001())));
        for (int n = 1; n <= 300; ++n) {
            const double d = targetAt(n);
            ControlMeasurement ref;
            QVERIFY(reference->setTarget(d).ok && reference->measure(ref).ok);
            const MeasurementMsg m = expectMeasurement(st.target(TargetMsg{std::uint64_t(n), d}));
            QCOMPARE(m.step, std::uint64_t(n));
            QCOMPARE(m.deformation, ref.deformation); // bit for bit
            QCOMPARE(m.force, ref.force);
            QCOMPARE(m.commanded, d);
            QVERIFY(reference->commit().ok);
            QVERIFY(acked(st.commit(CommitMsg{std::uint64_t(n)})));
        }
        QVERIFY(st.status().description.find("fracture") != std::string::npos);
    }

    void resentTargetsAndCommitsAreIdempotent() {
        SpecimenStation st(0, specimenSpec(), ControllerSettings{}, SpecimenStation::Pace::Fast,
                           nullptr);
        QVERIFY(asError(st.target(TargetMsg{1, 0.001})).has_value()); // before configure
        QVERIFY(acked(st.configure(configure001())));
        const MeasurementMsg first = expectMeasurement(st.target(TargetMsg{1, 0.001}));
        const MeasurementMsg again = expectMeasurement(st.target(TargetMsg{1, 0.001}));
        QCOMPARE(again.force, first.force); // no second trial: the same noisy reading
        QVERIFY(again.flags & kFlagReplayed);
        QVERIFY(acked(st.commit(CommitMsg{1})));
        QVERIFY(acked(st.commit(CommitMsg{1}))); // repeated commit
        QCOMPARE(st.committedSteps(), std::uint64_t(1));
        const MeasurementMsg committed = expectMeasurement(st.target(TargetMsg{1, 0.001}));
        QCOMPARE(committed.force, first.force);
        QCOMPARE(asError(st.target(TargetMsg{1, 0.002}))->code, ErrorCode::StateMismatch);
        QCOMPARE(asError(st.target(TargetMsg{5, 0.002}))->code, ErrorCode::ProtocolViolation);
        QCOMPARE(std::get<ErrorMsg>(st.commit(CommitMsg{2})).code, ErrorCode::ProtocolViolation);
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
        // Elastic range: F ~ k0 fRef / uRef d = 1000 d kN m; 0.004 rad -> ~4 kN m > 3.
        SpecimenStation st(
            0, specimenSpec({{"deformation", 0.01}, {"increment", 0.005}, {"force", 3.0}}),
            ControllerSettings{}, SpecimenStation::Pace::Fast, nullptr);
        QVERIFY(acked(st.configure(configure001())));
        const auto e = asError(st.target(TargetMsg{1, target}));
        QVERIFY(e);
        QCOMPARE(e->code, ErrorCode::Interlock);
        QVERIFY2(e->reason.find(limit.toStdString()) != std::string::npos, e->reason.c_str());
        QVERIFY(st.holding());
        QCOMPARE(asError(st.target(TargetMsg{1, 0.001}))->code, ErrorCode::Holding);
        QVERIFY(acked(st.resume()));
        QCOMPARE(expectMeasurement(st.target(TargetMsg{1, 0.001})).step, std::uint64_t(1));
    }

    void consoleLimitsTightenTheInterlock() {
        SpecimenStation st(0, specimenSpec(), ControllerSettings{}, SpecimenStation::Pace::Fast,
                           nullptr);
        ConfigureMsg c = configure001();
        c.maxDeformation = 0.002;
        QVERIFY(acked(st.configure(c)));
        QCOMPARE(asError(st.target(TargetMsg{1, 0.003}))->code, ErrorCode::Interlock);
    }

    void clientCannotLoosenTheConfigurationLimits() {
        // The element's `limits` (0.15 rad in the preset) hold whatever a client configures.
        SpecimenStation st(0, specimenSpec(), ControllerSettings{}, SpecimenStation::Pace::Fast,
                           nullptr);
        ConfigureMsg c = configure001();
        c.maxDeformation = 0.0; // "off"
        c.maxForce = -1.0;
        c.maxIncrement = NAN;
        QVERIFY(acked(st.configure(c)));
        QCOMPARE(st.limits().maxDeformation, 0.15);
        QCOMPARE(st.limits().maxIncrement, 0.01);
        QCOMPARE(st.limits().maxForce, 40.0);
        const auto e = asError(st.target(TargetMsg{1, 100.0}));
        QVERIFY(e);
        QCOMPARE(e->code, ErrorCode::Interlock);
        QVERIFY2(e->reason.find("target deformation |d| = 100") != std::string::npos,
                 e->reason.c_str());
        QCOMPARE(st.peakCommand(), 0.0); // the actuator held
        c.maxDeformation = 1.0;          // looser than the configuration: ignored
        QVERIFY(acked(st.configure(c)));
        QCOMPARE(st.limits().maxDeformation, 0.15);
    }

    void noCommandEverLeavesTheLimits() {
        // Property: random configuration limits (element `limits`, `interlock`), random client
        // limits (looser, tighter, 0, NaN), actuators ideal / lag / delay, both paces, random
        // walks with wild targets. Whatever happens, no command given to the actuator exceeds
        // the configuration's deformation limit (or the client's, when tighter), every target
        // past it is refused with Error(Interlock), and every measurement is inside it.
        std::mt19937_64 rng(14);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        const double wild[] = {100.0, -100.0, 1e300, -1e300, NAN, INFINITY};
        int refused = 0, measured = 0;
        for (int trial = 0; trial < 24; ++trial) {
            nlohmann::json j = linkfixture::condition3();
            auto& el = j["structure"]["elements"][0];
            const double lim = 0.002 + 0.02 * u(rng), inc = 0.3 * lim + 0.01 * u(rng);
            el["limits"] = {{"deformation", lim}, {"increment", inc}, {"force", 1e6}};
            if (trial % 3 == 1)
                el["specimen"]["interlock"] = {{"deformation", 0.5 * lim}};
            el["specimen"]["forceNoiseStd"] = 0.0;
            el["specimen"].erase("fracture");
            const int act = trial % 3;
            if (act == 1)
                el["specimen"]["actuator"] = {{"type", "lag"}, {"timeConstant", 0.004}};
            else if (act == 2)
                el["specimen"]["actuator"] = {{"type", "delay"}, {"delay", 0.003}};
            const ElementSpec spec = parseConfig(j, "memory.json").elements[0];
            const auto pace =
                trial % 2 ? SpecimenStation::Pace::RealTime : SpecimenStation::Pace::Fast;
            SpecimenStation st(0, spec, ControllerSettings{}, pace, nullptr);
            ConfigureMsg c = configure001();
            const double clientChoices[] = {0.0, -1.0, NAN, INFINITY, 10.0 * lim, 0.7 * lim};
            c.maxDeformation = clientChoices[trial % 6];
            QVERIFY(acked(st.configure(c)));
            double bound = (trial % 3 == 1) ? 0.5 * lim : lim;
            if (trial % 6 == 5)
                bound = std::min(bound, 0.7 * lim);
            QCOMPARE(st.limits().maxDeformation, bound);
            double last = 0.0;
            for (std::uint64_t n = 1, k = 0; k < 150; ++k) {
                if (st.holding())
                    QVERIFY(acked(st.resume()));
                double d = last + (2.0 * u(rng) - 1.0) * 0.9 * std::min(inc, bound);
                if (u(rng) < 0.1)
                    d = wild[k % 6];
                else if (u(rng) < 0.1)
                    d = (u(rng) < 0.5 ? -1.0 : 1.0) * bound * (1.0 + 0.5 * u(rng));
                std::optional<Message> m = st.target(TargetMsg{n, d});
                for (int t = 0; t < 1000 && !m && pace == SpecimenStation::Pace::RealTime; ++t)
                    m = st.tick();
                QVERIFY(m);
                const bool outside = !(std::abs(d) <= bound);
                if (outside) {
                    const auto e = asError(m);
                    QVERIFY2(e && e->code == ErrorCode::Interlock,
                             qPrintable(QString("target %1 accepted").arg(d)));
                    ++refused;
                } else if (const auto* mm = std::get_if<MeasurementMsg>(&*m)) {
                    QVERIFY(std::abs(mm->commanded) <= bound);
                    QVERIFY(std::abs(mm->deformation) <= bound);
                    QVERIFY(acked(st.commit(CommitMsg{n})));
                    last = d;
                    ++n;
                    ++measured;
                }
                QVERIFY2(st.peakCommand() <= bound,
                         qPrintable(QString("trial %1: command %2 > %3")
                                        .arg(trial)
                                        .arg(st.peakCommand())
                                        .arg(bound)));
            }
        }
        QVERIFY(refused > 100 && measured > 1000); // both branches exercised
    }

    void lateTargetHoldsTheActuator() {
        SpecimenStation st(0, specimenSpec(), ControllerSettings{}, SpecimenStation::Pace::RealTime,
                           nullptr);
        QVERIFY(acked(st.configure(configure001()))); // N = 10, P = 5 at 1024 Hz
        for (int i = 0; i < 20; ++i)
            QVERIFY(!st.tick());
        QVERIFY(!st.target(TargetMsg{1, 0.001})); // under way
        std::optional<Message> m;
        for (int i = 0; i < 100 && !m; ++i)
            m = st.tick();
        const MeasurementMsg mm = expectMeasurement(m);
        QCOMPARE(mm.heldTicks, std::uint32_t(15));
        QCOMPARE(mm.commanded, 0.001);
    }

    void lateTargetAfterMotionStillEndsOnTheTarget() {
        // Moving steps (the predictor extrapolates a speed), then a target 15 ticks late: the
        // actuator slows over the 8-tick ramp instead of stopping, yet the step ends exactly
        // on the target, with the late ticks counted and no interlock trip.
        ControllerSettings cs;
        cs.holdRamp = 8.0 / 1024.0;
        SpecimenStation st(0, specimenSpec(), cs, SpecimenStation::Pace::RealTime, nullptr);
        QVERIFY(acked(st.configure(configure001()))); // N = 10, P = 5 at 1024 Hz
        const auto stepTo = [&](std::uint64_t n, int lateTicks) {
            for (int i = 0; i < 5 + lateTicks; ++i)
                QVERIFY(!st.tick());
            QVERIFY(!st.target(TargetMsg{n, 2e-4 * double(n)}));
            std::optional<Message> m;
            for (int i = 0; i < 100 && !m; ++i)
                m = st.tick();
            const MeasurementMsg mm = expectMeasurement(m);
            QCOMPARE(mm.commanded, 2e-4 * double(n));
            QCOMPARE(mm.heldTicks, std::uint32_t(lateTicks));
            QVERIFY(acked(st.commit(CommitMsg{n})));
        };
        for (std::uint64_t n = 1; n <= 3; ++n)
            stepTo(n, 0);
        stepTo(4, 15);
        stepTo(5, 0);
        QVERIFY(!st.holding());
        QCOMPARE(st.totalHeldTicks(), 15L);
    }

    void journalRestoresTheDamagedSpecimen() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("state.txt").toStdString();
        const ElementSpec spec = specimenSpec();
        const std::vector<JournalElement> ids{{spec.name, 1234}};
        std::vector<MeasurementMsg> uninterrupted;
        {
            SpecimenStation ref(0, spec, ControllerSettings{}, SpecimenStation::Pace::Fast,
                                nullptr);
            QVERIFY(acked(ref.configure(configure001())));
            for (int n = 1; n <= 250; ++n) {
                uninterrupted.push_back(
                    expectMeasurement(ref.target(TargetMsg{std::uint64_t(n), targetAt(n)})));
                QVERIFY(acked(ref.commit(CommitMsg{std::uint64_t(n)})));
            }
        }
        {
            StateJournal journal;
            std::vector<JournalRecord> records;
            std::string error;
            QVERIFY2(journal.open(path, ids, records, error), error.c_str());
            SpecimenStation st(0, spec, ControllerSettings{}, SpecimenStation::Pace::Fast,
                               &journal);
            QVERIFY(acked(st.configure(configure001())));
            for (int n = 1; n <= 200; ++n) {
                expectMeasurement(st.target(TargetMsg{std::uint64_t(n), targetAt(n)}));
                QVERIFY(acked(st.commit(CommitMsg{std::uint64_t(n)})));
            }
            expectMeasurement(st.target(TargetMsg{201, targetAt(201)})); // measured, not committed
        }
        { // a crash in the middle of a line
            std::ofstream(path, std::ios::app) << "commit 0 201 0.1";
        }
        StateJournal journal;
        std::vector<JournalRecord> records;
        std::string error;
        QVERIFY2(journal.open(path, ids, records, error), error.c_str());
        QCOMPARE(records.size(), std::size_t(201)); // configure + 200 commits
        SpecimenStation st(0, spec, ControllerSettings{}, SpecimenStation::Pace::Fast, &journal);
        for (const auto& r : records)
            QVERIFY2(st.replay(r, error), error.c_str());
        QCOMPARE(st.committedSteps(), std::uint64_t(200));
        QVERIFY(acked(st.configure(configure001())));
        for (int n = 201; n <= 250; ++n) {
            const MeasurementMsg m =
                expectMeasurement(st.target(TargetMsg{std::uint64_t(n), targetAt(n)}));
            QCOMPARE(m.force, uninterrupted[std::size_t(n - 1)].force);
            QCOMPARE(m.deformation, uninterrupted[std::size_t(n - 1)].deformation);
            QVERIFY(acked(st.commit(CommitMsg{std::uint64_t(n)})));
        }
        QVERIFY(st.status().description.find("250 committed") != std::string::npos);
    }

    void journalRefusesOtherSpecimens() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("state.txt").toStdString();
        std::vector<JournalRecord> records;
        std::string error;
        {
            StateJournal j;
            QVERIFY(j.open(path, {{"Element 1", 1}}, records, error));
        }
        StateJournal j;
        QVERIFY(!j.open(path, {{"Element 1", 2}}, records, error));
        QVERIFY2(error.find("belongs to other specimens") != std::string::npos, error.c_str());
        { // a damaged record in the middle
            std::ofstream(path, std::ios::app) << "commit zero\nreset 0\n";
        }
        StateJournal k;
        QVERIFY(!k.open(path, {{"Element 1", 1}}, records, error));
        QVERIFY2(error.find("unreadable record") != std::string::npos, error.c_str());
    }

    void settingsFromTheControllerSection() {
        nlohmann::json j = linkfixture::condition3();
        j["controller"] = {{"rate", 2048}, {"predictFraction", 0.25}, {"stepDuration", 0.02}};
        const ControllerSettings s = parseControllerSettings(parseConfig(j, "m.json"));
        QCOMPARE(s.ticksPerStep(0.01), 41); // round(0.02 * 2048) = 41
        QCOMPARE(s.predictTicks(0.01), 10);
        QCOMPARE(s.holdRampTicks(), 10); // the default 0.005 s at 2048 Hz
        j["controller"] = {{"holdRamp", 0.01}};
        QCOMPARE(parseControllerSettings(parseConfig(j, "m.json")).holdRampTicks(), 10);
        j["controller"] = {{"holdRamp", -0.01}};
        QVERIFY_THROWS_EXCEPTION(ConfigError, parseControllerSettings(parseConfig(j, "m.json")));
        j["controller"] = {{"rate", -1}};
        QVERIFY_THROWS_EXCEPTION(ConfigError, parseControllerSettings(parseConfig(j, "m.json")));
        j["controller"] = {{"rat", 1}};
        QVERIFY_THROWS_EXCEPTION(ConfigError, parseControllerSettings(parseConfig(j, "m.json")));
    }
};

QTEST_APPLESS_MAIN(TestSpecimenStation)
#include "TestSpecimenStation.moc"
