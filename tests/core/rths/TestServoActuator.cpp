// The virtual lab's servo-hydraulic actuator (docs/rths.md, "The actuator in the virtual lab"):
// alone, inside a VirtualSpecimen, and from a configuration.
#include "core/config/RthsConfig.h"
#include "core/experimental/VirtualSpecimen.h"
#include "core/hysteresis/LinearElastic.h"
#include "core/rths/RthsBenchmark.h"
#include "core/rths/ServoActuator.h"

#include <QtTest>

#include <cmath>

using namespace hsmu;
using namespace hsmu::rths;

class TestServoActuator : public QObject {
    Q_OBJECT

private slots:
    void tracksASineWithTheLoopsDelay()
    {
        // PI 2 + 95/s on the nominal plant at 4096 Hz: a 1 Hz command is followed with the
        // closed loop's delay (about 10.4 ms, RTHS-BENCHMARK.md) and its gain, within 0.1 ms and 1 %.
        ServoActuatorSettings s;
        s.rate = 4096.0;
        ServoActuator a(s);
        std::vector<double> c, x;
        for (int k = 0; k < 4096 * 6; ++k) {
            const double cmd = 0.002 * std::sin(2 * M_PI * 1.0 * k / 4096.0);
            const double pos = a.tick(cmd);
            if (k >= 4096 * 2) {
                c.push_back(cmd);
                x.push_back(pos);
            }
        }
        RthsSettings loop = benchmarkSampleController();
        loop.compensation.lead.enabled = false;
        // tick() returns the position at the end of its tick: one tick earlier than the loop's
        // own sampling (closedLoopResponse pairs a command with the next tick's measurement).
        const double expected = loopDelay(loop, 1.0) * 1e3 - 1000.0 / 4096.0;
        const double measured = delayByCorrelation(c, x, 1.0 / 4096.0, 80);
        QVERIFY2(std::abs(measured - expected) < 0.1, qPrintable(QString("%1 ms against %2 ms").arg(measured).arg(expected)));
        const double gain = *std::max_element(x.begin(), x.end()) / 0.002;
        QVERIFY(std::abs(gain - std::abs(closedLoopResponse(loop, 2 * M_PI))) < 0.01);
    }

    void resetHoldsTheGivenPosition()
    {
        ServoActuator a;
        a.reset(0.003);
        for (int k = 0; k < 2048; ++k)
            a.tick(0.003);
        QVERIFY(std::abs(a.position() - 0.003) < 1e-7);
        QVERIFY(a.limitBreach().empty());
    }

    void virtualSpecimenHoldsOnAStrokeLimitNamingIt()
    {
        VirtualSpecimenOptions o;
        o.actuator.type = ActuatorModel::Type::ServoHydraulic;
        o.actuator.servo.limits.stroke = 0.001;
        VirtualSpecimen v(std::make_unique<LinearElastic>(1000.0), o);
        QVERIFY(v.prepare(0.01).ok);
        // A slow approach is followed; the achieved position lags the target.
        ControlMeasurement m;
        QVERIFY(v.setTarget(0.0005).ok);
        QVERIFY(v.measure(m).ok);
        QVERIFY(m.deformation > 0.0 && m.deformation < 0.0005);
        QCOMPARE(m.force, 1000.0 * m.deformation);
        QVERIFY(v.commit().ok);
        ControlResult r = v.setTarget(0.004);
        int steps = 0;
        while (r.ok && steps < 50) {
            QVERIFY(v.measure(m).ok);
            QVERIFY(v.commit().ok);
            r = v.setTarget(0.004);
            ++steps;
        }
        QVERIFY(!r.ok);
        QVERIFY2(r.reason.find("stroke limit") != std::string::npos, r.reason.c_str());
        QVERIFY(v.holding());
    }

    void parsedFromAConfiguration()
    {
        const auto doc = nlohmann::json::parse(R"({"type": "servoHydraulic", "rate": 2048,
            "plant": {"ke": 1.0e6, "specimenDampingRatio": 0.01}, "controller": {"kp": 3, "ki": 80},
            "limits": {"stroke": 0.05, "force": 1e5, "velocity": 1.0}, "metresPerUnit": 0.001})");
        ServoActuatorSettings s;
        parseServoActuator(JsonCursor(doc, "test.json", "actuator"), s);
        QCOMPARE(s.rate, 2048.0);
        QCOMPARE(s.plant.ke, 1.0e6);
        QVERIFY(std::abs(s.plant.ce - 2 * 0.01 * std::sqrt(1.0e6 * s.plant.me)) < 1e-9);
        QCOMPARE(s.pid.kp, 3.0);
        QCOMPARE(s.limits.stroke, 0.05);
        QCOMPARE(s.metresPerUnit, 0.001);
        const auto bad = nlohmann::json::parse(R"({"type": "servoHydraulic", "plant": {"b2": -5}})");
        try {
            parseServoActuator(JsonCursor(bad, "test.json", "actuator"), s);
            QFAIL("a negative b2 was accepted");
        } catch (const ConfigError& e) {
            QVERIFY2(std::string(e.what()).find("b2") != std::string::npos, e.what());
            QVERIFY(std::string(e.what()).find("test.json") != std::string::npos);
        }
        const auto typo = nlohmann::json::parse(R"({"type": "servoHydraulic", "plnat": {}})");
        QVERIFY_THROWS_EXCEPTION(ConfigError, parseServoActuator(JsonCursor(typo, "t.json"), s));
    }

    void benchmarkPresetsAndRthsConfigErrors()
    {
        const RthsConfig c = loadRthsConfig("rths-benchmark-case-3");
        QCOMPARE(c.benchmarkCase, 3);
        QCOMPARE(c.settings.rate, 4096.0);
        QVERIFY(c.settings.compensation.lead.enabled);
        QCOMPARE(c.groundMotionScale, 0.4);
        QCOMPARE(c.partition().numerical.m(0, 0), 1300.0 - c.settings.plant.me);
        QVERIFY(!rthsBenchmarkDocument("rths-benchmark-case-5"));
        auto doc = *rthsBenchmarkDocument("rths-benchmark-case-1");
        doc["rths"]["compensation"]["type"] = "smith";
        try {
            parseRthsConfig(doc, "mine.json");
            QFAIL("an unknown compensation was accepted");
        } catch (const ConfigError& e) {
            QVERIFY2(std::string(e.what()).find("rths.compensation.type") != std::string::npos, e.what());
        }
        doc = *rthsBenchmarkDocument("rths-benchmark-case-1");
        doc["rths"]["groundMotion"]["unit"] = "furlongs";
        QVERIFY_THROWS_EXCEPTION(ConfigError, parseRthsConfig(doc, "mine.json"));
    }
};

QTEST_APPLESS_MAIN(TestServoActuator)
#include "TestServoActuator.moc"
