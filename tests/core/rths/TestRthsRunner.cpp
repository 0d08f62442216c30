// Hold and resume of an RTHS run (core/rths/RthsRunner.h; docs/rths.md, "Hold and resume"):
// benchmark case 1 at 1024 Hz under a 2 Hz sine, noise on, the product's default compensation
// (ATS: its coefficients are estimates that move during the run), an MR damper in the specimen
// and its twin updated mid-run (ScheduledTwinUpdates).
//  - Held by the gate before tick K and resumed, the run equals the unheld run bit for bit:
//    every tick's time, desired, command, measured, force and hybrid floors, the twin's
//    parameters, every update event, J1..J9, peaks and tracking indicator (the simulated pace:
//    nothing ticks during the hold, so nothing of the plant or the structure moves).
//  - Every tick reaches the observer once, in order, and the resume is noted at tick K.
//  - Held twice, at two ticks, the same.
//  - A stroke-limit hold (the plant past it) and a command beyond the stroke are refused on
//    resume naming the channel, and the run stays held; resuming a run that is not held is
//    refused.
#include "core/rths/RthsBenchmark.h"
#include "core/rths/RthsRunner.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <set>

using namespace hsmu;
using namespace hsmu::rths;

namespace {

GroundMotion sine(double seconds, double amplitude = 1.0)
{
    GroundMotion g;
    g.dt = 0.005;
    g.name = "2 Hz sine";
    for (int i = 0; i <= int(std::lround(seconds / g.dt)); ++i)
        g.acceleration.push_back(amplitude * std::sin(2 * std::numbers::pi * 2.0 * g.dt * i));
    return g;
}

RthsSettings settings()
{
    RthsSettings s = defaultCompensation();
    s.rate = 1024.0;
    fitToNominalLoop(s);
    s.sensors.seed = 7;
    s.damper.enabled = true;
    s.damper.specimen.uRef = 0.0054;
    s.damper.specimen.fRef = 320.0;
    s.damper.twin = s.damper.specimen;
    s.damper.twin.alpha *= 0.5;
    s.damper.twinDof = 1;
    return s;
}

ScheduledTwinUpdates updates()
{
    return ScheduledTwinUpdates({TwinUpdate{{"alpha", "c0"}, {80.0, 0.03}, "operator", 700},
                                 TwinUpdate{{"c1"}, {2.5}, "operator", 1500}});
}

/// Refuses the ticks listed, once each.
class HoldAt final : public TickGate {
public:
    explicit HoldAt(std::set<long> ticks) : m_ticks(std::move(ticks)) {}
    bool admit(long k, std::string& why) override
    {
        if (!m_ticks.erase(k))
            return true;
        why = "test hold before tick " + std::to_string(k);
        return false;
    }
    void done(long) override {}
    void resume(long k) override { resumedAt.push_back(k); }
    std::vector<long> resumedAt;

private:
    std::set<long> m_ticks;
};

class Ticks final : public TickObserver {
public:
    void onTick(long k, const RthsTick&,
                const Eigen::Ref<const Eigen::RowVectorXd, 0, Eigen::InnerStride<>>&) override
    {
        ticks.push_back(k);
    }
    void onResume(long k, double, const std::string& note) override { notes.emplace_back(k, note); }
    std::vector<long> ticks;
    std::vector<std::pair<long, std::string>> notes;
};

void compareBitForBit(const RthsRun& a, const RthsRun& b)
{
    QCOMPARE(a.time.size(), b.time.size());
    for (std::size_t k = 0; k < a.time.size(); ++k) {
        QCOMPARE(a.time[k], b.time[k]); // QCOMPARE on double is fuzzy: bits compared below
        QVERIFY2(a.desired[k] == b.desired[k] && a.command[k] == b.command[k] &&
                     a.measured[k] == b.measured[k] && a.force[k] == b.force[k],
                 qPrintable(QString("tick %1 differs").arg(k)));
    }
    QVERIFY(a.hybrid == b.hybrid);
    QVERIFY(a.reference == b.reference);
    for (int i = 0; i < 9; ++i)
        QVERIFY2(a.criteria.j[std::size_t(i)] == b.criteria.j[std::size_t(i)], qPrintable(QString("J%1").arg(i + 1)));
    QVERIFY(a.peakForce == b.peakForce && a.peakStroke == b.peakStroke && a.peakVelocity == b.peakVelocity);
    QVERIFY(a.trackingIndicator == b.trackingIndicator);
    QCOMPARE(a.updates.size(), b.updates.size());
    for (std::size_t i = 0; i < a.updates.size(); ++i) {
        QCOMPARE(a.updates[i].step, b.updates[i].step);
        QVERIFY(a.updates[i].applied == b.updates[i].applied);
    }
    QVERIFY(a.twin.has_value() && b.twin.has_value());
    QVERIFY(a.twin->alpha == b.twin->alpha && a.twin->c0 == b.twin->c0 && a.twin->c1 == b.twin->c1);
}

} // namespace

class TestRthsRunner : public QObject {
    Q_OBJECT

private slots:
    void heldAndResumedEqualsTheUnheldRun()
    {
        const RthsSettings s = settings();
        const Partition p = benchmarkPartition(1, s.plant);
        const GroundMotion g = sine(3.0);
        ScheduledTwinUpdates u0 = updates();
        const RthsRun unheld = runRths(p, g, s, nullptr, 0.0, nullptr, &u0);
        QVERIFY(unheld.hold.empty());
        QCOMPARE(long(unheld.time.size()), 3073L);
        QCOMPARE(unheld.updates.size(), std::size_t(2));

        HoldAt gate({1000, 2222});
        Ticks seen;
        ScheduledTwinUpdates u1 = updates();
        RthsRunner runner(p, g, s, &gate, 0.0, &seen, &u1);
        QVERIFY(!runner.run());
        QVERIFY(runner.held());
        QCOMPARE(runner.hold(), std::string("test hold before tick 1000"));
        QCOMPARE(runner.next(), 1000L);
        const RthsRun part = runner.result();
        QCOMPARE(part.hold, runner.hold());
        QCOMPARE(long(part.time.size()), 1000L);
        for (long k = 0; k < 1000; ++k)
            QVERIFY(part.measured[std::size_t(k)] == unheld.measured[std::size_t(k)]);
        QVERIFY(!runner.run()); // still held: nothing ticks
        QCOMPARE(runner.next(), 1000L);
        QCOMPARE(runner.resume(), std::string());
        QVERIFY(!runner.run());
        QCOMPARE(runner.next(), 2222L);
        QCOMPARE(runner.resume(), std::string());
        QVERIFY(runner.run());
        QVERIFY(!runner.held());
        const RthsRun resumed = runner.result();
        QVERIFY(resumed.hold.empty());
        compareBitForBit(resumed, unheld);
        QCOMPARE(gate.resumedAt, (std::vector<long>{1000, 2222}));
        QCOMPARE(long(seen.ticks.size()), 3073L);
        for (long k = 0; k < 3073; ++k)
            QCOMPARE(seen.ticks[std::size_t(k)], k);
        QCOMPARE(seen.notes.size(), std::size_t(2));
        QCOMPARE(seen.notes[0].first, 1000L);
        QVERIFY2(seen.notes[0].second.rfind("resumed before tick 1000 (t = 0.976562 s) after: test hold before tick 1000", 0) == 0,
                 seen.notes[0].second.c_str());
        QCOMPARE(runner.resume(), std::string("the run is not held: nothing to resume"));
    }

    void aLimitHoldDoesNotResumeIntoTheBreach()
    {
        RthsSettings s = settings();
        s.damper.enabled = false;
        s.limits.stroke = 1e-4; // 0.1 mm: the plant passes it early
        const Partition p = benchmarkPartition(1, s.plant);
        RthsRunner runner(p, sine(3.0, 3.0), s);
        QVERIFY(!runner.run());
        QVERIFY(runner.held());
        const std::string hold = runner.hold();
        QVERIFY2(hold.find("stroke limit") != std::string::npos, hold.c_str());
        const long at = runner.next();
        const std::string why = runner.resume();
        QVERIFY2(why.rfind("resume refused: ", 0) == 0 && why.find("stroke limit") != std::string::npos &&
                     why.find("not resumed") != std::string::npos,
                 why.c_str());
        QVERIFY(runner.held());
        QCOMPARE(runner.hold(), hold);
        QVERIFY(!runner.run());
        QCOMPARE(runner.next(), at);
        QCOMPARE(runner.result().hold, hold);
    }

    void aCommandBeyondTheStrokeIsNotResumed()
    {
        RthsSettings s = settings();
        s.damper.enabled = false;
        s.sensors.noise = false;
        s.limits.stroke = 1e-4;
        s.limits.velocity = 1e9;
        s.limits.force = 1e12;
        const Partition p = benchmarkPartition(1, s.plant);
        // The command (compensated ahead of the plant) passes the stroke before the plant does.
        RthsRunner runner(p, sine(3.0, 3.0), s);
        QVERIFY(!runner.run());
        const std::string hold = runner.hold();
        QVERIFY2(hold.rfind("actuator command ", 0) == 0, hold.c_str());
        const std::string why = runner.resume();
        QVERIFY2(why.find("actuator command") != std::string::npos &&
                     why.find("has not moved: not resumed") != std::string::npos,
                 why.c_str());
        QVERIFY(runner.held());
    }
};

QTEST_APPLESS_MAIN(TestRthsRunner)
#include "TestRthsRunner.moc"
