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
//  - J4..J9 of a run with a damper compare against the reference run with the damper (the
//    damper at the specimen and the device the twin models at the twin's storey): with a twin
//    equal to the specimen's damper they read what a run without a damper reads against its own
//    reference (within the stated tolerances), where the reference without dampers would read
//    them several times larger.
//  - A stroke-limit hold (the plant past it) and a command beyond the stroke are refused on
//    resume naming the channel, and the run stays held; resuming a run that is not held is
//    refused.
#include "core/rths/DamperReference.h"
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

    void jAgainstTheReferenceWithTheDamper()
    {
        RthsSettings s = settings();
        s.damper.twin = s.damper.specimen; // a perfect twin
        const Partition p = benchmarkPartition(1, s.plant);
        const GroundMotion g = sine(6.0);
        const RthsRun run = runRths(p, g, s);
        QVERIFY(run.hold.empty());
        const long n = long(run.time.size());
        const Eigen::MatrixXd bare = referenceResponse(p.reference, g, 1.0 / s.rate, n);
        const Eigen::MatrixXd damped = referenceResponse(p.reference, g, 1.0 / s.rate, n, referenceDampers(p, s.damper));
        QVERIFY(run.reference == damped);
        const auto col = [](const Eigen::MatrixXd& a, int i) {
            return std::vector<double>(a.col(i).data(), a.col(i).data() + a.rows());
        };
        // The dampers change the reference: floor 1 of the bare structure differs by this much.
        const double effect = normalizedRmsError(col(damped, 0), col(bare, 0));
        const double j4Bare = normalizedRmsError(col(bare, 0), run.measured);
        RthsSettings plain = s;
        plain.damper.enabled = false;
        const RthsRun without = runRths(p, g, plain);
        qInfo("damper's effect on floor 1 %.2f %%; J4 %.2f %% (against the bare reference %.2f %%; a run without a damper %.2f %%); J6 %.2f %%, J8 %.2f %%",
              effect, run.criteria.j[3], j4Bare, without.criteria.j[3], run.criteria.j[5], run.criteria.j[7]);
        QVERIFY2(effect > 20.0, qPrintable(QString::number(effect)));
        // RMS (J4, J6, J7) within 1 % point of the run without a damper, peaks (J5, J8, J9), one
        // sample each, within 2.5 points.
        for (int i = 3; i < 9; ++i)
            QVERIFY2(std::abs(run.criteria.j[std::size_t(i)] - without.criteria.j[std::size_t(i)]) <=
                         (i == 4 || i >= 7 ? 2.5 : 1.0),
                     qPrintable(QStringLiteral("J%1 %2 vs %3").arg(i + 1).arg(run.criteria.j[std::size_t(i)]).arg(without.criteria.j[std::size_t(i)])));
        QVERIFY2(j4Bare > 3.0 * run.criteria.j[3], qPrintable(QString::number(j4Bare)));
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
