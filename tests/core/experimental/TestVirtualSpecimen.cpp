// Tests of VirtualSpecimen (core/experimental/VirtualSpecimen.h) through the
// ExperimentalControl calls a test makes per step (setTarget, measure, commit): the ideal
// actuator returns the true law exactly, the lag and delay actuators follow their closed
// forms, noise has the configured statistics and is reproducible, fracture and interlock
// act from the documented step on.

#include "core/experimental/VirtualSpecimen.h"
#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/LinearElastic.h"

#include <QtTest>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

using namespace hsmu;

namespace {

BoucWenParameters trueParameters() {
    BoucWenParameters p; // the presets' specimen: uRef 0.02 rad, fRef 20 kN m
    p.k0 = 1.0;
    p.alpha = 0.03;
    p.n = 2.0;
    p.beta = 2.5;
    p.gamma = 0.5;
    p.deltaNu = 0.03;
    p.deltaEta = 0.03;
    p.uRef = 0.02;
    p.fRef = 20.0;
    return p;
}

// Cyclic rotation history of growing amplitude up to 0.06 rad.
double history(int i) {
    return 0.06 * i / 300.0 * std::sin(2.0 * std::numbers::pi * i / 100.0);
}

// One test step: target, measurement, commit. Fails the test on a fault.
ControlMeasurement stepTo(VirtualSpecimen& v, double target) {
    ControlMeasurement m;
    const ControlResult t = v.setTarget(target);
    if (!t.ok)
        qWarning("setTarget: %s", t.reason.c_str());
    const ControlResult r = v.measure(m);
    if (!r.ok)
        qWarning("measure: %s", r.reason.c_str());
    v.commit();
    return m;
}

} // namespace

class TestVirtualSpecimen : public QObject {
    Q_OBJECT
private slots:
    void prepareRejectsBadDt();
    void idealActuatorGivesTheTrueLawExactly();
    void lagFollowsFirstOrderStep();
    void delayReproducesTargetsLater();
    void forceNoiseHasConfiguredStd();
    void sameSeedSameNoise();
    void fractureAtTime();
    void fractureAtTimeOnDecimalSteps();
    void fractureAtCumulativeDeformation();
    void interlockRefusesAndHolds();
};

void TestVirtualSpecimen::prepareRejectsBadDt() {
    VirtualSpecimen v(std::make_unique<LinearElastic>(10.0), {});
    QVERIFY(!v.prepare(0.0).ok);
    QVERIFY(!v.prepare(-0.01).ok);
    QVERIFY(v.prepare(0.01).ok);
}

void TestVirtualSpecimen::idealActuatorGivesTheTrueLawExactly() {
    VirtualSpecimen v(std::make_unique<BoucWen>(trueParameters()), {});
    QVERIFY(v.prepare(0.01).ok);
    BoucWen reference(trueParameters());
    for (int i = 1; i <= 300; ++i) {
        const double d = history(i);
        reference.setTrialDeformation(d);
        const ControlMeasurement m = stepTo(v, d);
        reference.commit();
        // Same law, same inputs, no noise: bit-identical.
        QCOMPARE(m.deformation, d);
        QVERIFY2(m.force == reference.trialForce(),
                 qPrintable(
                     QString("step %1: %2 vs %3").arg(i).arg(m.force).arg(reference.trialForce())));
        QCOMPARE(v.achievedDeformation(), d);
    }
    QVERIFY(std::abs(v.trueLaw().committedForce()) > 0.0);
    QVERIFY(!v.fractured());
}

void TestVirtualSpecimen::lagFollowsFirstOrderStep() {
    VirtualSpecimenOptions o;
    o.actuator.type = ActuatorModel::Type::Lag;
    o.actuator.timeConstant = 0.05; // [s]
    const double k = 100.0, dt = 0.01, target = 0.02;
    VirtualSpecimen v(std::make_unique<LinearElastic>(k), o);
    QVERIFY(v.prepare(dt).ok);
    for (int n = 1; n <= 60; ++n) {
        const ControlMeasurement m = stepTo(v, target);
        const double expected = target * (1.0 - std::exp(-n * dt / o.actuator.timeConstant));
        // The recursion d[n] = d[n-1] + (d_t - d[n-1]) (1 - e^{-dt/tau}) accumulates a few
        // ulps per step: 1e-15 absolute on a 0.02 target.
        QVERIFY2(std::abs(m.deformation - expected) < 1e-15,
                 qPrintable(QString("step %1: %2 vs %3").arg(n).arg(m.deformation).arg(expected)));
        QVERIFY(std::abs(m.force - k * m.deformation) < 1e-13); // the law sees the achieved d
    }
}

void TestVirtualSpecimen::delayReproducesTargetsLater() {
    VirtualSpecimenOptions o;
    o.actuator.type = ActuatorModel::Type::Delay;
    o.actuator.delay = 0.03; // 3 steps of 0.01 s
    const int delaySteps = 3;
    VirtualSpecimen v(std::make_unique<LinearElastic>(50.0), o);
    QVERIFY(v.prepare(0.01).ok);
    std::vector<double> sent;
    for (int n = 1; n <= 100; ++n) {
        const double target = 0.01 * std::sin(0.3 * n);
        sent.push_back(target);
        const ControlMeasurement m = stepTo(v, target);
        const double expected = n > delaySteps ? sent[n - 1 - delaySteps] : 0.0;
        QVERIFY2(m.deformation == expected,
                 qPrintable(QString("step %1: %2 vs %3").arg(n).arg(m.deformation).arg(expected)));
        QVERIFY(m.force == 50.0 * expected);
    }
}

void TestVirtualSpecimen::forceNoiseHasConfiguredStd() {
    VirtualSpecimenOptions o;
    o.forceNoiseStd = 0.2; // [kN m]
    o.seed = 7;
    VirtualSpecimen v(std::make_unique<LinearElastic>(100.0), o);
    QVERIFY(v.prepare(0.01).ok);
    const int n = 20000;
    double sum = 0.0, sum2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const double d = 0.01 * std::sin(0.01 * i);
        const ControlMeasurement m = stepTo(v, d);
        QCOMPARE(m.deformation, d); // no deformation noise configured
        const double e = m.force - 100.0 * d;
        sum += e;
        sum2 += e * e;
    }
    const double mean = sum / n;
    const double sd = std::sqrt((sum2 - n * mean * mean) / (n - 1));
    // Sample std of 20000 normals: relative standard error 1/sqrt(2n) = 0.5 %; 5 % is 10 sigma.
    QVERIFY2(std::abs(sd - o.forceNoiseStd) < 0.05 * o.forceNoiseStd,
             qPrintable(QString::number(sd)));
    // Mean: standard error 0.2 / sqrt(20000) = 1.4e-3; 5 sigma.
    QVERIFY2(std::abs(mean) < 5.0 * o.forceNoiseStd / std::sqrt(double(n)),
             qPrintable(QString::number(mean)));
}

void TestVirtualSpecimen::sameSeedSameNoise() {
    auto noisy = [](std::uint64_t seed) {
        VirtualSpecimenOptions o;
        o.forceNoiseStd = 0.5;
        o.deformationNoiseStd = 1e-4;
        o.seed = seed;
        auto v = std::make_unique<VirtualSpecimen>(std::make_unique<BoucWen>(trueParameters()), o);
        v->prepare(0.01);
        return v;
    };
    auto a = noisy(42), b = noisy(42), c = noisy(43);
    int differ = 0;
    for (int i = 1; i <= 200; ++i) {
        const ControlMeasurement ma = stepTo(*a, history(i));
        const ControlMeasurement mb = stepTo(*b, history(i));
        const ControlMeasurement mc = stepTo(*c, history(i));
        QVERIFY(ma.force == mb.force);
        QVERIFY(ma.deformation == mb.deformation);
        differ += ma.force != mc.force ? 1 : 0;
        // Deformation noise is on the reading only: the specimen moves to the target.
        QCOMPARE(a->achievedDeformation(), history(i));
    }
    QCOMPARE(differ, 200);
}

void TestVirtualSpecimen::fractureAtTime() {
    VirtualSpecimenOptions o;
    o.fracture.atTime = 1.0; // dt = 0.25 s (exact in binary): the 4th step ends at t = 1.0
    o.fracture.strengthLoss = 0.4;
    VirtualSpecimen v(std::make_unique<BoucWen>(trueParameters()), o);
    QVERIFY(v.prepare(0.25).ok);
    BoucWen reference(trueParameters());
    QVERIFY(std::isnan(v.fractureTime()));
    for (int n = 1; n <= 12; ++n) {
        const double d = 0.01 * std::sin(0.7 * n);
        reference.setTrialDeformation(d);
        reference.commit();
        const ControlMeasurement m = stepTo(v, d);
        const double factor = n >= 4 ? 0.6 : 1.0;
        // One multiplication: exact up to 1 ulp.
        QVERIFY2(std::abs(m.force - factor * reference.committedForce()) <=
                     1e-15 * std::abs(reference.committedForce()),
                 qPrintable(QString("step %1").arg(n)));
        QCOMPARE(v.fractured(), n >= 4);
    }
    QCOMPARE(v.fractureTime(), 1.0);
    QCOMPARE(v.time(), 3.0);
}

void TestVirtualSpecimen::fractureAtTimeOnDecimalSteps() {
    // The usual dt = 0.01 s: fracture at t = 0.1 s must happen at step 10 (t = 10 dt), as
    // the test clock HybridTest::time() = step dt says, not one step late because ten
    // additions of 0.01 give 0.09999999999999999.
    VirtualSpecimenOptions o;
    o.fracture.atTime = 0.1;
    VirtualSpecimen v(std::make_unique<LinearElastic>(10.0), o);
    const double dt = 0.01;
    QVERIFY(v.prepare(dt).ok);
    for (int n = 1; n <= 10; ++n)
        stepTo(v, 0.001 * n);
    // Time is a count of steps: 1e-12 s allows for n * dt rounding only.
    QVERIFY2(std::abs(v.time() - 10 * dt) < 1e-12, qPrintable(QString::number(v.time(), 'g', 17)));
    QVERIFY2(v.fractured(), "no fracture at step 10 (t = 0.1 s)");
    QVERIFY2(std::abs(v.fractureTime() - 0.1) < 1e-12,
             qPrintable(QString::number(v.fractureTime(), 'g', 17)));
}

void TestVirtualSpecimen::fractureAtCumulativeDeformation() {
    VirtualSpecimenOptions o;
    o.fracture.atCumulativeDeformation = 0.3; // steps of 0.125: sum |dd| = 0.375 at step 3
    o.fracture.strengthLoss = 1.0;            // total loss
    const double dt = 0.125;
    VirtualSpecimen v(std::make_unique<LinearElastic>(10.0), o);
    QVERIFY(v.prepare(dt).ok);
    const double targets[] = {0.125, 0.25, 0.375, 0.25, 0.125, 0.0};
    for (int n = 1; n <= 6; ++n) {
        const ControlMeasurement m = stepTo(v, targets[n - 1]);
        QCOMPARE(m.force, n >= 3 ? 0.0 : 10.0 * targets[n - 1]);
    }
    QVERIFY(v.fractured());
    QCOMPARE(v.fractureTime(), 3 * dt);
}

void TestVirtualSpecimen::interlockRefusesAndHolds() {
    VirtualSpecimenOptions o;
    o.interlock.maxDeformation = 0.05;
    VirtualSpecimen v(std::make_unique<LinearElastic>(100.0), o);
    QVERIFY(v.prepare(0.01).ok);
    stepTo(v, 0.03);
    QVERIFY(!v.holding());

    const ControlResult r = v.setTarget(0.06);
    QVERIFY(!r.ok);
    QVERIFY(v.holding());
    const QString why = QString::fromStdString(v.holdReason());
    QVERIFY2(why.contains("interlock") && why.contains("0.05") && why.contains("0.06"),
             qPrintable(why));
    QCOMPARE(v.achievedDeformation(), 0.03); // held where it was
    QCOMPARE(v.trueLaw().committedDeformation(), 0.03);

    // Everything is refused while holding, even a safe target.
    QVERIFY(!v.setTarget(0.02).ok);
    ControlMeasurement m;
    QVERIFY(!v.measure(m).ok);
    QVERIFY(!v.commit().ok);
    QCOMPARE(v.achievedDeformation(), 0.03);

    v.resume();
    QVERIFY(!v.holding());
    QVERIFY(v.setTarget(0.02).ok);
    QVERIFY(v.measure(m).ok);
    QCOMPARE(m.deformation, 0.02);
    QVERIFY(std::abs(m.force - 2.0) < 1e-14);
    QVERIFY(v.commit().ok);
}

QTEST_APPLESS_MAIN(TestVirtualSpecimen)
#include "TestVirtualSpecimen.moc"
