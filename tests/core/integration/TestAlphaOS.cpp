// Tests of AlphaOS (core/integration/AlphaOS.h) on linear systems (elastic springs on a
// Structure, so that the initial stiffness K_I is the true K and alpha-OS is exactly
// HHT-alpha): alpha = 0 is Newmark average acceleration (exact discrete solution, energy
// conservation), second-order convergence to closed forms, agreement with ExplicitNewmark.

#include "core/integration/AlphaOS.h"
#include "core/integration/ExplicitNewmark.h"

#include "IntegrationFixture.h"

#include <QtTest>

#include <cmath>
#include <stdexcept>

using namespace hsmu;
using namespace hsmu::testing;

namespace {
constexpr double kMass = 2.0;    // [t]
constexpr double kStiff = 800.0; // [kN/m] -> omega = 20 rad/s
constexpr double kOmega = 20.0;

// 1/2 v^T M v + 1/2 u^T K0 u over the free DOFs.
double energy(const Structure& s, const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
    return 0.5 * v.dot(s.mass() * v) + 0.5 * u.dot(s.initialStiffness() * u);
}
} // namespace

class TestAlphaOS : public QObject {
    Q_OBJECT
private slots:
    void rejectsAlphaOutsideRange();
    void alphaZeroMatchesAverageAccelerationClosedForm();
    void alphaZeroConservesEnergy();
    void numericalDissipationForNegativeAlpha();
    void freeVibrationConvergesAsDtSquared();
    void harmonicGroundMotionConvergesAsDtSquared();
    void agreesWithExplicitNewmarkOnTwoDof();
};

void TestAlphaOS::rejectsAlphaOutsideRange() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, AlphaOS(0.1));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, AlphaOS(-0.4));
    const AlphaOS a(-1.0 / 3.0);
    QCOMPARE(a.alpha(), -1.0 / 3.0);
    QVERIFY(!a.isExplicit());
    QVERIFY(std::isinf(a.stabilityLimit()));
}

void TestAlphaOS::alphaZeroMatchesAverageAccelerationClosedForm() {
    // Average acceleration, undamped, from u0 at rest: u[1] (1 + x^2) = u0 (1 - x^2) with
    // x = w dt / 2, i.e. u[1] = u0 cos(theta), tan(theta / 2) = x; the amplification matrix is
    // a rotation by theta, so u[n] = u0 cos(n theta) exactly, at any w dt.
    for (double wdt : {0.1, 0.5, 10.0}) {
        auto s = makeSdof(kMass, kStiff, 0.0);
        AlphaOS in(0.0);
        const double dt = wdt / kOmega, u0 = 0.01;
        const auto u = run(*s, in, dt, 2000, u0);
        QCOMPARE(int(u.size()), 2001);
        const double theta = 2.0 * std::atan(wdt / 2.0);
        // Roundoff only (the recursion is an exact rotation): 1e-10 u0.
        const double err = maxError(u, dt, [&](double t) { return u0 * std::cos(theta * t / dt); });
        QVERIFY2(err <= 1e-10 * u0, qPrintable(QString("w dt %1: error %2").arg(wdt).arg(err)));
    }
}

void TestAlphaOS::alphaZeroConservesEnergy() {
    // Undamped linear 2-DOF, w_max dt ~ 3 (beyond the explicit limit): the trapezoidal rule
    // conserves 1/2 v^T M v + 1/2 u^T K u exactly; roundoff over 2000 steps stays < 1e-10.
    auto s = makeChain(2.0, 1.0, 300.0, 200.0, 150.0, 0.0);
    const double dt = 3.0 / s->frequencies().maxCoeff();
    AlphaOS in(0.0);
    const Eigen::Vector2d u0(0.02, -0.01), v0(0.1, 0.3);
    s->setTrial(u0);
    const Eigen::VectorXd r0 = s->restoringForce();
    s->commit();
    in.initialize(*s, dt, u0, v0, 0.0, r0);
    const double e0 = energy(*s, u0, v0);
    double worst = 0.0;
    for (int n = 0; n < 2000; ++n) {
        s->setTrial(in.predict());
        QVERIFY(in.correct(s->restoringForce(), 0.0));
        s->commit();
        worst = std::max(worst, std::abs(energy(*s, in.displacement(), in.velocity()) - e0) / e0);
    }
    QVERIFY2(worst <= 1e-10, qPrintable(QString("relative energy drift %1").arg(worst)));
}

void TestAlphaOS::numericalDissipationForNegativeAlpha() {
    // HHT-alpha with alpha < 0 damps high frequencies: at w dt = 10 the amplitude decays and
    // never exceeds its start (spectral radius ~ (1 + alpha) / (1 - alpha) < 1).
    auto s = makeSdof(kMass, kStiff, 0.0);
    AlphaOS in(-0.1);
    const double u0 = 0.01;
    const auto u = run(*s, in, 10.0 / kOmega, 200, u0);
    QCOMPARE(int(u.size()), 201);
    QVERIFY2(peak(u) <= u0 * (1.0 + 1e-12), qPrintable(QString::number(peak(u) / u0)));
    QVERIFY2(std::abs(u.back()[0]) < 0.01 * u0, qPrintable(QString::number(u.back()[0] / u0)));
}

void TestAlphaOS::freeVibrationConvergesAsDtSquared() {
    const double zeta = 0.05, u0 = 0.01, v0 = 0.1, duration = 1.0;
    auto exact = [&](double t) { return freeVibration(kOmega, zeta, u0, v0, t); };
    double err[2];
    for (int i = 0; i < 2; ++i) {
        const double dt = 0.005 / (1 << i); // w dt = 0.1, 0.05
        auto s = makeSdof(kMass, kStiff, zeta);
        AlphaOS in(-0.05);
        const auto u = run(*s, in, dt, int(std::lround(duration / dt)),
                           Eigen::VectorXd::Constant(1, u0), Eigen::VectorXd::Constant(1, v0));
        err[i] = maxError(u, dt, exact);
    }
    // Period elongation ~ (w dt)^2 / 12 over ~20 rad: ~2 % of the amplitude at w dt = 0.1.
    QVERIFY2(err[0] < 0.03 * u0, qPrintable(QString::number(err[0])));
    const double ratio = err[0] / err[1];
    // Second order: halving dt divides the error by ~4.
    QVERIFY2(ratio >= 3.0 && ratio <= 5.0, qPrintable(QString("error ratio %1").arg(ratio)));
}

void TestAlphaOS::harmonicGroundMotionConvergesAsDtSquared() {
    const double zeta = 0.05, amp = 2.0, bigW = 12.0, duration = 3.0;
    auto ag = [&](double t) { return amp * std::sin(bigW * t); };
    auto exact = [&](double t) { return harmonicFromRest(kOmega, zeta, amp, bigW, t); };
    double err[2], umax = 0.0;
    for (int i = 0; i < 2; ++i) {
        const double dt = 0.005 / (1 << i);
        auto s = makeSdof(kMass, kStiff, zeta);
        AlphaOS in(-0.05);
        const auto u = run(*s, in, dt, int(std::lround(duration / dt)), Eigen::VectorXd::Zero(1),
                           Eigen::VectorXd::Zero(1), ag);
        err[i] = maxError(u, dt, exact);
        umax = peak(u);
    }
    QVERIFY(umax > 0.006); // steady-state amplitude ~ 7.8 mm
    // O((w dt)^2) phase and amplitude errors: a few % of the peak at w dt = 0.1.
    QVERIFY2(err[0] < 0.03 * umax, qPrintable(QString("error %1 of %2").arg(err[0]).arg(umax)));
    const double ratio = err[0] / err[1];
    QVERIFY2(ratio >= 3.0 && ratio <= 5.0, qPrintable(QString("error ratio %1").arg(ratio)));
}

void TestAlphaOS::agreesWithExplicitNewmarkOnTwoDof() {
    // Both schemes are second order, so their difference on a linear 2-DOF system under a
    // harmonic ground motion is O(dt^2) too: it must shrink ~4x when dt halves.
    auto ag = [](double t) { return 3.0 * std::sin(9.0 * t); };
    double diff[2], umax = 0.0;
    for (int i = 0; i < 2; ++i) {
        auto s1 = makeChain(2.0, 1.0, 300.0, 200.0, 150.0, 0.03);
        auto s2 = makeChain(2.0, 1.0, 300.0, 200.0, 150.0, 0.03);
        const double dt = 0.1 / s1->frequencies().maxCoeff() / (1 << i); // w_max dt = 0.1, 0.05
        const int steps = int(std::lround(4.0 / dt));
        ExplicitNewmark explicitScheme;
        AlphaOS alphaScheme(-0.05);
        const Eigen::VectorXd zero = Eigen::VectorXd::Zero(2);
        const auto ue = run(*s1, explicitScheme, dt, steps, zero, zero, ag);
        const auto ua = run(*s2, alphaScheme, dt, steps, zero, zero, ag);
        QCOMPARE(ue.size(), ua.size());
        diff[i] = 0.0;
        for (std::size_t n = 0; n < ue.size(); ++n)
            diff[i] = std::max(diff[i], (ue[n] - ua[n]).cwiseAbs().maxCoeff());
        umax = peak(ue);
    }
    QVERIFY(umax > 0.005);
    QVERIFY2(diff[1] < 0.01 * umax, qPrintable(QString("diff %1 of %2").arg(diff[1]).arg(umax)));
    const double ratio = diff[0] / diff[1];
    QVERIFY2(ratio >= 3.0 && ratio <= 5.0, qPrintable(QString("difference ratio %1").arg(ratio)));
}

QTEST_APPLESS_MAIN(TestAlphaOS)
#include "TestAlphaOS.moc"
