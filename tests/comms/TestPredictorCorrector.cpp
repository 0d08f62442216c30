// The predictor-corrector of hsmu-controller (comms/controller/PredictorCorrector) when a
// target is late: the command slows to a hold over the ramp (speed falling linearly, never
// above the last predicted speed), resumes smoothly when the target arrives, ends the step on
// the target exactly, and stays inside the increment limit. Expected values are the header's
// formulas evaluated here, or bounds derived from them (stated per test).
#include "comms/controller/PredictorCorrector.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <vector>

using hsmu::comms::PredictorCorrector;

namespace {

// Commands of `ticks` ticks and their per-tick increments (the first from `start`).
struct Path {
    std::vector<double> command, increment;
};

Path run(PredictorCorrector& pc, int ticks) {
    Path p;
    double last = pc.command();
    for (int k = 0; k < ticks; ++k) {
        const double c = pc.tick();
        p.command.push_back(c);
        p.increment.push_back(c - last);
        last = c;
    }
    return p;
}

/// A corrector of N ticks per step, P of them predicted, a hold ramp of R ticks, starting a
/// step at h0 after the committed targets h0, h1, h2.
PredictorCorrector started(int n, int p, int ramp, double h0, double h1, double h2) {
    PredictorCorrector pc;
    pc.setTiming(n, p);
    pc.setHoldRamp(ramp);
    pc.beginStep(h0, h0, h1, h2);
    return pc;
}

} // namespace

class TestPredictorCorrector : public QObject {
    Q_OBJECT
private slots:
    void lateTargetSlowsLinearlyToAHold() {
        PredictorCorrector pc =
            started(10, 5, 8, 3.0, 2.0, 1.0); // a constant speed of 0.1 per tick
        run(pc, 5);
        QCOMPARE(pc.phase(), PredictorCorrector::Phase::Late);
        const double v0 = pc.velocity();
        QVERIFY(std::abs(v0 - 0.1) < 1e-12);
        const double c5 = pc.command();
        const Path late = run(pc, 20);
        // v_k = v0 (R - k) / R for k < R, then 0: a speed that falls by v0 / R per tick.
        for (int k = 1; k <= 20; ++k) {
            const double expected = k < 8 ? v0 * (8 - k) / 8.0 : 0.0;
            QVERIFY2(std::abs(late.increment[k - 1] - expected) < 1e-12,
                     qPrintable(QString("tick %1: %2").arg(k).arg(late.increment[k - 1])));
            QVERIFY(late.increment[k - 1] <= v0 + 1e-15);
        }
        // Held at c5 + v0 (R - 1) / 2 after the ramp; the step's clock stopped meanwhile.
        QVERIFY(std::abs(pc.command() - (c5 + v0 * 7.0 / 2.0)) < 1e-12);
        QCOMPARE(pc.heldTicks(), 20);
        QCOMPARE(pc.tickInStep(), 5);
        QCOMPARE(pc.velocity(), 0.0);
    }

    void holdRampZeroStopsAtOnce() {
        PredictorCorrector pc = started(10, 5, 0, 3.0, 2.0, 1.0);
        run(pc, 5);
        const double c5 = pc.command();
        const Path late = run(pc, 4);
        for (double c : late.command)
            QCOMPARE(c, c5);
    }

    void lateTargetResumesFromRestSmoothly() {
        PredictorCorrector pc = started(20, 10, 5, 3.0, 2.9, 2.8); // 0.005 per tick
        run(pc, 10 + 12);                                          // predicted, slowed, held
        QCOMPARE(pc.velocity(), 0.0);
        const double c0 = pc.command();
        const double target = c0 + 0.2;
        pc.setTarget(target);
        const int r = 10; // N - P ticks left
        const Path resume = run(pc, r);
        QCOMPARE(pc.phase(), PredictorCorrector::Phase::Arrived);
        QCOMPARE(pc.command(), target); // exactly
        // From rest: c_j - c0 = D (2 s^2 - s^3), s = j / R, D = T - c0.
        const double d = target - c0;
        for (int j = 1; j < r; ++j) {
            const double s = double(j) / r;
            QVERIFY(std::abs(resume.command[j - 1] - (c0 + d * (2 * s * s - s * s * s))) < 1e-12);
        }
        // No jump in speed: the first increment is D (2 - 1 / R) / R^2 (not D / R), and the
        // speed changes per tick by at most max|f''| / R^2 = 4 D / R^2; at most 4/3 D / R.
        QVERIFY(std::abs(resume.increment[0] - d * (2.0 - 1.0 / r) / (r * r)) < 1e-12);
        double previous = 0.0;
        for (double inc : resume.increment) {
            QVERIFY(std::abs(inc - previous) <= 4.0 * d / (r * r) + 1e-12);
            QVERIFY(inc <= 4.0 / 3.0 * d / r + 1e-12);
            previous = inc;
        }
    }

    void targetDuringTheRampResumesFromTheCurrentSpeed() {
        PredictorCorrector pc = started(20, 10, 10, 3.0, 2.9, 2.8);
        run(pc, 10 + 3); // three ticks into the ramp: v = v0 * 7 / 10
        const double v = pc.velocity();
        QVERIFY(std::abs(v - 0.005 * 0.7) < 1e-12);
        const double c0 = pc.command();
        const double target = c0 + 0.06; // the linear correction's speed 0.006 per tick
        pc.setTarget(target);
        const Path resume = run(pc, 10);
        QCOMPARE(pc.command(), target);
        // Hermite from (c0, v) to (T, D / R): c_j = c0 + R v h10(s) + D (2 s^2 - s^3).
        const double d = target - c0;
        for (int j = 1; j < 10; ++j) {
            const double s = j / 10.0;
            const double h10 = s * s * s - 2 * s * s + s;
            QVERIFY(std::abs(resume.command[j - 1] -
                             (c0 + 10 * v * h10 + d * (2 * s * s - s * s * s))) < 1e-12);
        }
        // The first increment continues the speed within the ramp's own change per tick.
        QVERIFY(std::abs(resume.increment[0] - v) < 0.0005);
    }

    void onTimeTargetIsCorrectedLinearlyAsBefore() {
        // No late tick (the fast pace's case): c_j = c0 + (T - c0) j / R exactly, as before.
        PredictorCorrector pc = started(10, 5, 8, 3.0, 2.0, 1.0);
        run(pc, 5);
        const double c0 = pc.command();
        pc.setTarget(4.0);
        const Path p = run(pc, 5);
        for (int j = 1; j < 5; ++j)
            QCOMPARE(p.command[j - 1], c0 + (4.0 - c0) * double(j) / 5.0);
        QCOMPARE(pc.command(), 4.0);
    }

    void incrementLimitBoundsPredictionAndRamp() {
        // Targets rising by 1 per step: the prediction reaches h0 + 0.5 at 0.1 per tick and
        // the ramp would add 0.1 * 19 / 2, but the limit keeps every command in h0 +- 0.55.
        PredictorCorrector pc = started(10, 5, 20, 0.0, -1.0, -2.0);
        pc.setIncrementLimit(0.55);
        const Path p = run(pc, 40);
        double peak = 0.0;
        for (std::size_t k = 0; k < p.command.size(); ++k) {
            QVERIFY(std::abs(p.command[k]) <= 0.55 + 1e-15);
            QVERIFY(std::abs(p.increment[k]) <= 0.1 + 1e-12); // never above the predicted speed
            peak = std::max(peak, p.command[k]);
        }
        QCOMPARE(peak, 0.55);
        pc.setTarget(0.5);
        for (double c : run(pc, 5).command)
            QVERIFY(c >= 0.5 - 1e-15 && c <= 0.55 + 1e-15);
        QCOMPARE(pc.command(), 0.5);
    }

    void stopFreezesAtOnce() {
        PredictorCorrector pc = started(10, 5, 8, 3.0, 2.0, 1.0);
        run(pc, 3);
        const double c = pc.command();
        pc.stop(); // an interlock trip or a console hold: no ramp
        for (double x : run(pc, 5).command)
            QCOMPARE(x, c);
        QCOMPARE(pc.velocity(), 0.0);
    }
};

QTEST_APPLESS_MAIN(TestPredictorCorrector)
#include "TestPredictorCorrector.moc"
