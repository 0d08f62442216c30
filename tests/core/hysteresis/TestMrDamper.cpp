// Tests of MrDamper (core/hysteresis/MrDamper.h), the rate-dependent law of an MR damper
// (Spencer et al. 1997's modified Bouc-Wen model), against closed forms:
//  - hysteresis off (alpha = 0, k0 = 0): a dashpot c0 c1 / (c0 + c1) and a spring k1 in
//    parallel, force = c v + k1 u + f0 exactly at every step, whatever the steps;
//  - the viscous energy per steady cycle of u = X sin(omega t): pi c omega X^2 (times
//    sinc^2(omega dt / 2), exact for the backward velocity of the steps);
//  - hysteresis off with k0 > 0: the standard linear solid, energy per cycle
//    pi X^2 c1 omega (k0^2 + c0 c omega^2) / (k0^2 + c^2 omega^2), converging at first order;
//  - a rigid series dashpot (c1 huge, c0 = k0 = k1 = 0): the Bouc-Wen law boucWen integrates;
//  - the tangent against central finite differences of the trial force;
//  - the quasi-static step (dt = +infinity), the trial / commit / revert / clone contract, the
//    time increment's rules and the parameters' admissibility.
// LawStatus is compared with QVERIFY(a == b): QCOMPARE would pick hsmu::toString by ADL.

#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/LawFactory.h"
#include "core/hysteresis/MrDamper.h"
#include "tests/support/LawByName.h"

#include "LawTestSupport.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

using namespace hsmu;
using namespace hsmu::testsupport;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// A damper in the range the shared records calibrate to (normalized; scales in m, kN).
MrDamperParameters typicalDamper() {
    MrDamperParameters p;
    p.c0 = 0.024;
    p.c1 = 3.2;
    p.k0 = 0.016;
    p.k1 = 0.0085;
    p.f0 = -0.07;
    p.alpha = 72.0;
    p.A = 1.0;
    p.beta = 2.5;
    p.gamma = 9.7;
    p.n = 0.54;
    p.uRef = 0.0054;
    p.fRef = 0.32;
    return p;
}

/// Drives law through u(t) = X sin(omega t) for `cycles` cycles of N steps; returns the
/// energy sum_k F_k (u_k - u_k-1) over the last cycle.
double lastCycleEnergy(HysteresisLaw& law, double X, double omega, int N, int cycles) {
    const double dt = 2.0 * kPi / omega / N;
    law.setTimeIncrement(dt);
    double energy = 0.0, previous = 0.0;
    for (int k = 1; k <= cycles * N; ++k) {
        const double u = X * std::sin(omega * k * dt);
        if (law.setTrialDeformation(u) != LawStatus::Ok)
            return std::nan("");
        if (k > (cycles - 1) * N)
            energy += law.trialForce() * (u - previous);
        law.commit();
        previous = u;
    }
    return energy;
}

} // namespace

class TestMrDamper : public QObject {
    Q_OBJECT

private slots:
    void identityAndFactory();
    void needsATimeIncrement();
    void linearSpringAndDashpotWhenHysteresisIsOff();
    void viscousEnergyPerCycle();
    void standardLinearSolidEnergyPerCycle();
    void rigidSeriesDashpotIsBoucWen();
    void tangentMatchesFiniteDifferences();
    void quasiStaticStepRelaxes();
    void fasterMeansMoreForce();
    void trialCommitRevertAndClone();
    void rescaledIsTheSamePhysicalLaw();
    void parameters();
};

void TestMrDamper::identityAndFactory() {
    MrDamper law;
    QCOMPARE(law.lawName(), std::string("mrDamper"));
    QVERIFY(law.isRateDependent());
    QVERIFY(std::isnan(law.timeIncrement()));
    QVERIFY((law.parameterNames() ==
             std::vector<std::string>{"c0", "c1", "k0", "k1", "f0", "alpha", "A", "beta", "gamma",
                                      "n", "uRef", "fRef"}));
    for (const char* name : {"mrDamper", "mr-damper", "MRDAMPER"})
        QCOMPARE(makeLaw(name, {})->lawName(), std::string("mrDamper"));
    const auto made = makeLaw("mrDamper", {{"c1", 4.0}, {"f0", -0.5}, {"beta", -0.2}});
    QCOMPARE(*test::parameterNamed(*made, "c1"), 4.0);
    QCOMPARE(*test::parameterNamed(*made, "f0"), -0.5);
    QCOMPARE(*test::parameterNamed(*made, "c0"), 1.0); // default kept
    // Rate-independent laws ignore the time increment.
    BoucWen bw;
    bw.setTimeIncrement(0.01);
    QVERIFY(!bw.isRateDependent());
    QVERIFY(std::isnan(bw.timeIncrement()));
    QVERIFY(std::isinf(historyTimeIncrement(std::vector<double>{0.5, 0.6}, 0)));
    QCOMPARE(historyTimeIncrement(std::vector<double>{0.5, 0.75}, 1), 0.25);
    QVERIFY(std::isnan(historyTimeIncrement(std::vector<double>{0.5}, 1)));
}

void TestMrDamper::needsATimeIncrement() {
    MrDamper law(typicalDamper());
    QVERIFY(law.setTrialDeformation(1e-3) == LawStatus::InvalidInput);
    QVERIFY(law.failureReason().find("setTimeIncrement") != std::string::npos);
    QCOMPARE(law.trialDeformation(), 0.0); // reset to the committed state
    for (const double bad : {0.0, -0.01, std::nan("")}) {
        law.setTimeIncrement(bad);
        QVERIFY(law.setTrialDeformation(1e-3) == LawStatus::InvalidInput);
    }
    law.setTimeIncrement(0.01);
    QVERIFY(law.setTrialDeformation(std::nan("")) == LawStatus::InvalidInput);
    QVERIFY(law.failureReason().find("not finite") != std::string::npos);
    QVERIFY(law.setTrialDeformation(1e-3) == LawStatus::Ok);
    QVERIFY(law.failureReason().empty());
    // Kept until set again, through commit, revert, revertToStart and clone.
    law.commit();
    law.revert();
    law.revertToStart();
    QCOMPARE(law.timeIncrement(), 0.01);
    QCOMPARE(law.clone()->timeIncrement(), 0.01);
}

void TestMrDamper::linearSpringAndDashpotWhenHysteresisIsOff() {
    // alpha = 0, k0 = 0: force = c0 c1 / (c0 + c1) v + k1 u + f0 at every step, exactly (to
    // rounding), for any increments and time steps, in physical units (uRef, fRef).
    MrDamperParameters p;
    p.c0 = 0.3;
    p.c1 = 1.2;
    p.k0 = 0.0;
    p.k1 = 2.5;
    p.f0 = -0.4;
    p.alpha = 0.0;
    p.uRef = 0.02;
    p.fRef = 50.0;
    MrDamper law(p);
    const double scale = p.fRef / p.uRef;
    const double c = p.c0 * p.c1 / (p.c0 + p.c1) * scale, k = p.k1 * scale, f0 = p.f0 * p.fRef;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> step(-0.01, 0.01), time(1e-4, 0.05);
    double u = 0.0;
    QCOMPARE(law.committedForce(), f0); // the virgin force
    for (int i = 0; i < 500; ++i) {
        const double du = step(rng), dt = time(rng);
        law.setTimeIncrement(dt);
        QVERIFY(law.setTrialDeformation(u + du) == LawStatus::Ok);
        const double expected = c * du / dt + k * (u + du) + f0;
        QVERIFY2(std::abs(law.trialForce() - expected) <= 1e-11 * (std::abs(expected) + 50.0),
                 qPrintable(QString("step %1: %2 vs %3").arg(i).arg(law.trialForce()).arg(expected)));
        QVERIFY(std::abs(law.trialTangent() - (c / dt + k)) <= 1e-12 * (c / dt + k));
        QVERIFY(std::abs(law.trialVelocity() - du / dt) <= 1e-12 * std::abs(du / dt));
        law.commit();
        u += du;
    }
}

void TestMrDamper::viscousEnergyPerCycle() {
    // Steady sinusoid: E = pi c omega X^2 for a dashpot c; the backward velocity of N steps
    // per cycle gives exactly pi c omega X^2 sinc^2(omega dt / 2) (relative error
    // (omega dt)^2 / 12: 2e-6 at 1000 steps).
    MrDamperParameters p;
    p.alpha = 0.0;
    p.k0 = 0.0;
    p.k1 = 0.0;
    p.c0 = 2.0;
    p.c1 = 6.0;
    p.f0 = 0.3; // a constant force does no work over a cycle
    const double c = p.c0 * p.c1 / (p.c0 + p.c1);
    const double X = 0.05, omega = 2.0 * kPi * 1.3;
    for (const int N : {100, 1000}) {
        MrDamper law(p);
        const double energy = lastCycleEnergy(law, X, omega, N, 2);
        const double half = omega * (2.0 * kPi / omega / N) / 2.0;
        const double sinc = std::sin(half) / half;
        const double closed = kPi * c * omega * X * X;
        QVERIFY2(std::abs(energy - closed * sinc * sinc) <= 1e-10 * closed,
                 qPrintable(QString("N %1: %2 vs %3").arg(N).arg(energy).arg(closed * sinc * sinc)));
        QVERIFY(std::abs(energy / closed - 1.0) <= 1.01 * half * half / 3.0);
    }
}

void TestMrDamper::standardLinearSolidEnergyPerCycle() {
    // alpha = 0, k0 > 0: the internal branch (c0 with k0) in series with c1, a standard linear
    // solid; K*(omega) = c1 i omega (k0 + i c0 omega) / (k0 + i c omega), and the energy per
    // steady cycle pi X^2 Im K* = pi X^2 c1 omega (k0^2 + c0 c omega^2) / (k0^2 + c^2 omega^2).
    // Backward Euler in time: first order (the error halves with the step).
    MrDamperParameters p;
    p.alpha = 0.0;
    p.c0 = 0.5;
    p.c1 = 2.0;
    p.k0 = 20.0;
    p.k1 = 3.0;
    const double c = p.c0 + p.c1;
    const double X = 0.02, omega = 2.0 * kPi * 2.0; // omega c / k0 = 1.6: well in the transition
    const double closed = kPi * X * X * p.c1 * omega * (p.k0 * p.k0 + p.c0 * c * omega * omega) /
                          (p.k0 * p.k0 + c * c * omega * omega);
    double previousError = 0.0;
    for (const int N : {2000, 4000, 8000}) {
        MrDamper law(p);
        const double energy = lastCycleEnergy(law, X, omega, N, 6); // transient: tau = c / k0
        const double error = std::abs(energy / closed - 1.0);
        qInfo("standard linear solid, %d steps per cycle: energy %.8g, closed form %.8g, "
              "relative error %.2e", N, energy, closed, error);
        QVERIFY(error < 4e-3);
        if (previousError > 0)
            QVERIFY(error < 0.6 * previousError); // first order
        previousError = error;
    }
}

void TestMrDamper::rigidSeriesDashpotIsBoucWen() {
    // c0 = k0 = k1 = 0 and a rigid c1 (y does not move): f = alpha z with z driven by x, i.e.
    // boucWen with k0 = alpha, alpha = 0 and the same A, beta, gamma, n.
    MrDamperParameters p;
    p.c0 = 0.0;
    p.c1 = 1e12;
    p.k0 = 0.0;
    p.k1 = 0.0;
    p.alpha = 3.0;
    p.A = 1.3;
    p.beta = 2.0;
    p.gamma = 0.7;
    p.n = 1.6;
    MrDamper mr(p);
    BoucWenParameters b;
    b.k0 = p.alpha;
    b.alpha = 0.0;
    b.A0 = p.A;
    b.beta = p.beta;
    b.gamma = p.gamma;
    b.n = p.n;
    BoucWen bw(b);
    mr.setTimeIncrement(0.01);
    const std::vector<double> u = sineHistory(4.0 * MrDamper::ultimateZ(p), 3, 400);
    const Run a = drive(mr, u), r = drive(bw, u);
    QVERIFY(a.ok && r.ok);
    const double d = maxDifference(a.force, 1, r.force, 1), peak = peakAbs(r.force);
    qInfo("rigid series dashpot: max |F_mrDamper - F_boucWen| = %.3g of the peak force",
          d / peak);
    QVERIFY(d <= 1e-9 * peak);
}

void TestMrDamper::tangentMatchesFiniteDifferences() {
    // d(trial force)/d(trial deformation) at fixed dt, through the sub-stepped integration,
    // against a central difference from the same committed state (h small against the step,
    // so that the sub-steps stay the same), at points along a loop with sub-stepped
    // increments, near reversals and on the yield plateau.
    MrDamper law(typicalDamper());
    const double dt = 0.01, X = 0.012, omega = 2.0 * kPi * 0.84;
    law.setTimeIncrement(dt);
    int checked = 0, subStepped = 0;
    double worst = 0.0;
    for (int k = 1; k <= 150; ++k) {
        const double u = X * std::sin(omega * k * dt);
        QVERIFY(law.setTrialDeformation(u) == LawStatus::Ok);
        const double tangent = law.trialTangent();
        QCOMPARE(law.algorithmicTangent(), tangent);
        if (k % 5 == 0) {
            const int subSteps = law.trialSubSteps();
            const double h = 1e-7 * std::max(std::abs(u - law.committedDeformation()), 1e-6);
            QVERIFY(law.setTrialDeformation(u + h) == LawStatus::Ok);
            const double fp = law.trialForce();
            const bool sameSteps = law.trialSubSteps() == subSteps;
            QVERIFY(law.setTrialDeformation(u - h) == LawStatus::Ok);
            const double fm = law.trialForce();
            if (sameSteps && law.trialSubSteps() == subSteps) {
                const double fd = (fp - fm) / (2.0 * h);
                const double error = std::abs(fd - tangent) / std::abs(tangent);
                worst = std::max(worst, error);
                QVERIFY2(error < 1e-5, qPrintable(QString("step %1: tangent %2, difference %3")
                                                      .arg(k).arg(tangent).arg(fd)));
                ++checked;
                subStepped += subSteps > 1;
            }
            QVERIFY(law.setTrialDeformation(u) == LawStatus::Ok);
        }
        law.commit();
    }
    qInfo("tangent: %d points checked (%d sub-stepped), worst relative error %.2e", checked,
          subStepped, worst);
    QVERIFY(checked >= 20 && subStepped >= 5);
    // After commit (no trial yet): the tangent of a trial at the committed deformation.
    const double afterCommit = law.trialTangent();
    QVERIFY(law.setTrialDeformation(law.committedDeformation()) == LawStatus::Ok);
    QCOMPARE(law.trialTangent(), afterCommit);
}

void TestMrDamper::quasiStaticStepRelaxes() {
    const MrDamperParameters p = typicalDamper();
    MrDamper law(p);
    // From the virgin state: force k1 u + f0, tangent k1, no sub-steps.
    law.setTimeIncrement(kInf);
    const double u0 = -0.0126;
    QVERIFY(law.setTrialDeformation(u0) == LawStatus::Ok);
    const double scale = p.fRef / p.uRef;
    QVERIFY(std::abs(law.trialForce() - (p.k1 * scale * u0 + p.f0 * p.fRef)) <= 1e-15);
    QCOMPARE(law.trialTangent(), p.k1 * scale);
    QCOMPARE(law.trialSubSteps(), 0);
    QCOMPARE(law.trialVelocity(), 0.0);
    law.commit();
    // Loaded by fast motion, then a quasi-static step: the internal branch relaxes to rest
    // (alpha z + k0 w = 0), the force to k1 u + f0.
    law.setTimeIncrement(0.01);
    double u = u0;
    for (int k = 0; k < 20; ++k) {
        u += 5e-4;
        QVERIFY(law.setTrialDeformation(u) == LawStatus::Ok);
        law.commit();
    }
    const MrDamperState loaded = law.committedState();
    QVERIFY(std::abs(p.alpha * loaded.z + p.k0 * loaded.w) > 0.1);
    law.setTimeIncrement(kInf);
    QVERIFY(law.setTrialDeformation(u) == LawStatus::Ok);
    const MrDamperState rested = law.trialState();
    QVERIFY(std::abs(p.alpha * rested.z + p.k0 * rested.w) <= 1e-10);
    QVERIFY(std::abs(law.trialForce() - (p.k1 * scale * u + p.f0 * p.fRef)) <= 1e-9 * p.fRef);
}

void TestMrDamper::fasterMeansMoreForce() {
    // The same loop at three frequencies: the peak force grows with the velocity (the viscous
    // terms) and the loop's area too.
    double previousPeak = 0.0, previousEnergy = 0.0;
    for (const double hz : {0.1, 1.0, 4.0}) {
        MrDamper law(typicalDamper());
        const double omega = 2.0 * kPi * hz;
        const int N = 400;
        const double energy = lastCycleEnergy(law, 0.012, omega, N, 2);
        law.setTimeIncrement(2.0 * kPi / omega / N);
        double peak = 0.0;
        for (int k = 1; k <= N; ++k) {
            QVERIFY(law.setTrialDeformation(0.012 * std::sin(2.0 * kPi * k / N)) == LawStatus::Ok);
            peak = std::max(peak, std::abs(law.trialForce()));
            law.commit();
        }
        qInfo("%.1f Hz: peak force %.4g, energy per cycle %.4g", hz, peak, energy);
        QVERIFY(peak > previousPeak && energy > previousEnergy);
        previousPeak = peak;
        previousEnergy = energy;
    }
}

void TestMrDamper::trialCommitRevertAndClone() {
    MrDamper law(typicalDamper());
    law.setTimeIncrement(0.01);
    QVERIFY(law.setTrialDeformation(0.002) == LawStatus::Ok);
    law.commit();
    const double f1 = law.committedForce();
    const MrDamperState s1 = law.committedState();
    // Trials never change the committed state; the last one counts.
    QVERIFY(law.setTrialDeformation(0.004) == LawStatus::Ok);
    QVERIFY(law.setTrialDeformation(0.003) == LawStatus::Ok);
    const double f3 = law.trialForce();
    QCOMPARE(law.committedForce(), f1);
    QCOMPARE(law.committedState().z, s1.z);
    law.revert();
    QCOMPARE(law.trialForce(), f1);
    QCOMPARE(law.trialDeformation(), 0.002);
    QVERIFY(law.setTrialDeformation(0.003) == LawStatus::Ok);
    QCOMPARE(law.trialForce(), f3);
    // A clone carries the state and the time increment: the same next trial.
    const auto copy = law.clone();
    QCOMPARE(copy->trialForce(), f3);
    law.commit();
    copy->commit();
    QVERIFY(law.setTrialDeformation(0.0035) == LawStatus::Ok);
    QVERIFY(copy->setTrialDeformation(0.0035) == LawStatus::Ok);
    QCOMPARE(copy->trialForce(), law.trialForce());
    // A failed trial leaves the committed state.
    QVERIFY(law.setTrialDeformation(std::numeric_limits<double>::infinity()) ==
            LawStatus::InvalidInput);
    QCOMPARE(law.trialDeformation(), 0.003);
    law.revertToStart();
    QCOMPARE(law.committedDeformation(), 0.0);
    QCOMPARE(law.committedForce(), typicalDamper().f0 * typicalDamper().fRef);
    QCOMPARE(law.committedState().z, 0.0);
}

void TestMrDamper::rescaledIsTheSamePhysicalLaw() {
    // Other reference scales, the same physical damper: the same forces along a loop (the
    // sub-steps, judged in normalized units, are the same too: w and z scale alike).
    const MrDamperParameters p = typicalDamper();
    const MrDamperParameters q = MrDamper::rescaled(p, 0.002, 1.5);
    QCOMPARE(q.uRef, 0.002);
    QCOMPARE(q.fRef, 1.5);
    QCOMPARE(q.n, p.n);
    QCOMPARE(q.A, p.A);
    MrDamper a(p), b(q);
    a.setTimeIncrement(0.01);
    b.setTimeIncrement(0.01);
    const std::vector<double> u = sineHistory(0.015, 2, 150);
    const Run ra = drive(a, u), rb = drive(b, u);
    QVERIFY(ra.ok && rb.ok);
    const double peak = peakAbs(ra.force);
    QVERIFY2(maxDifference(ra.force, 1, rb.force, 1) <= 1e-9 * peak,
             qPrintable(QString::number(maxDifference(ra.force, 1, rb.force, 1) / peak)));
    QVERIFY(std::abs(a.committedState().z * p.uRef / q.uRef - b.committedState().z) <=
            1e-9 * std::abs(b.committedState().z));
}

void TestMrDamper::parameters() {
    MrDamper law(typicalDamper());
    law.setTimeIncrement(0.01);
    QVERIFY(law.setTrialDeformation(0.003) == LawStatus::Ok);
    law.commit();
    const MrDamperState s = law.committedState();
    // One at a time: a refused value leaves everything.
    QVERIFY(!test::setParameterNamed(law, "c1", 0.0));
    QVERIFY(!test::setParameterNamed(law, "k1", -1.0));
    QVERIFY(!test::setParameterNamed(law, "gamma", -3.0)); // beta + gamma <= 0
    QVERIFY(!test::setParameterNamed(law, "n", std::nan("")));
    QCOMPARE(law.parameters().c1, typicalDamper().c1);
    // Together: beta and gamma change sign as one admissible set.
    const int beta = law.parameterIndex("beta"), gamma = law.parameterIndex("gamma");
    const std::vector<int> both{beta, gamma};
    QCOMPARE(law.setParameterValues(both, std::vector<double>{-1.0, 3.0}, true), -1);
    QCOMPARE(law.parameters().beta, -1.0);
    QCOMPARE(law.setParameterValues(both, std::vector<double>{-4.0, 3.0}, true), 0);
    QCOMPARE(law.parameters().beta, -1.0);
    // The committed state is kept, the committed force follows the new parameters.
    QCOMPARE(law.committedState().z, s.z);
    const double before = law.committedForce();
    QVERIFY(test::setParameterNamed(law, "f0", 0.0));
    QVERIFY(std::abs(law.committedForce() - (before - typicalDamper().f0 * typicalDamper().fRef)) <=
            1e-14);
    QVERIFY(law.parameterValue(99) != law.parameterValue(99)); // NaN
    // The factory names the parameter and what was expected.
    try {
        makeLaw("mrDamper", {{"c1", 0.0}});
        QFAIL("c1 = 0 accepted");
    } catch (const std::invalid_argument& e) {
        QVERIFY(std::string(e.what()).find("mrDamper: parameter 'c1'") != std::string::npos);
    }
    try {
        makeLaw("mrDamper", {{"beta", -1.0}});
        QFAIL("beta + gamma <= 0 accepted");
    } catch (const std::invalid_argument& e) {
        QVERIFY(std::string(e.what()).find("beta + gamma > 0") != std::string::npos);
    }
}

QTEST_APPLESS_MAIN(TestMrDamper)
#include "TestMrDamper.moc"
