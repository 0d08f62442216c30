// Tests of ExplicitNewmark (core/integration/ExplicitNewmark.h) on linear SDOF systems
// (an elastic lateral spring on a Structure) against closed forms: the exact discrete
// solution of the undamped recursion, and the continuous free and forced responses with the
// error shrinking as O(dt^2).

#include "core/integration/ExplicitNewmark.h"

#include "IntegrationFixture.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>

using namespace hsmu;
using namespace hsmu::testing;

namespace {
constexpr double kMass = 2.0;    // [t]
constexpr double kStiff = 800.0; // [kN/m] -> omega = 20 rad/s, T = 0.314 s
constexpr double kOmega = 20.0;
} // namespace

class TestExplicitNewmark : public QObject {
    Q_OBJECT
private slots:
    void initialAccelerationFromEquilibrium();
    void undampedMatchesDiscreteClosedForm();
    void freeVibrationConvergesAsDtSquared_data();
    void freeVibrationConvergesAsDtSquared();
    void harmonicGroundMotionConvergesAsDtSquared();
    void predictIsTheNextDisplacement();
    void nonFiniteForceIsRefused();
};

void TestExplicitNewmark::initialAccelerationFromEquilibrium() {
    const double zeta = 0.05, u0 = 0.01, v0 = 0.2, ag0 = 1.5;
    auto s = makeSdof(kMass, kStiff, zeta);
    ExplicitNewmark in;
    in.initialize(*s, 0.01, Eigen::VectorXd::Constant(1, u0), Eigen::VectorXd::Constant(1, v0), ag0,
                  Eigen::VectorXd::Constant(1, kStiff * u0));
    const double c = 2.0 * zeta * kOmega * kMass;
    const double a0 = (-kMass * ag0 - c * v0 - kStiff * u0) / kMass;
    QVERIFY(std::abs(in.acceleration()[0] - a0) < 1e-12 * std::abs(a0));
    QCOMPARE(in.displacement()[0], u0);
    QCOMPARE(in.velocity()[0], v0);
    QCOMPARE(in.dt(), 0.01);
}

void TestExplicitNewmark::undampedMatchesDiscreteClosedForm() {
    // Undamped, beta = 0, gamma = 1/2 is the central difference recursion
    // u[n+1] - 2 u[n] + u[n-1] = -(w dt)^2 u[n] with u[1] = u0 (1 - (w dt)^2 / 2), whose
    // solution is u[n] = u0 cos(n theta), cos(theta) = 1 - (w dt)^2 / 2.
    for (double wdt : {0.1, 1.0, 1.9}) {
        auto s = makeSdof(kMass, kStiff, 0.0);
        ExplicitNewmark in;
        const double dt = wdt / kOmega, u0 = 0.01;
        const auto u = run(*s, in, dt, 2000, u0);
        QCOMPARE(int(u.size()), 2001);
        const double theta = std::acos(1.0 - wdt * wdt / 2.0);
        // The recursion is neutrally stable: roundoff grows ~ n eps; 1e-10 u0 is generous.
        const double err = maxError(u, dt, [&](double t) { return u0 * std::cos(theta * t / dt); });
        QVERIFY2(err <= 1e-10 * u0, qPrintable(QString("w dt %1: error %2").arg(wdt).arg(err)));
    }
}

void TestExplicitNewmark::freeVibrationConvergesAsDtSquared_data() {
    QTest::addColumn<double>("zeta");
    QTest::addColumn<double>("v0");
    QTest::newRow("undamped") << 0.0 << 0.0;
    QTest::newRow("damped 5 %") << 0.05 << 0.1;
}

void TestExplicitNewmark::freeVibrationConvergesAsDtSquared() {
    QFETCH(double, zeta);
    QFETCH(double, v0);
    const double u0 = 0.01, duration = 1.0; // about three periods
    auto exact = [&](double t) { return freeVibration(kOmega, zeta, u0, v0, t); };
    double err[2];
    for (int i = 0; i < 2; ++i) {
        const double dt = 0.005 / (1 << i); // w dt = 0.1, 0.05
        auto s = makeSdof(kMass, kStiff, zeta);
        ExplicitNewmark in;
        const auto u = run(*s, in, dt, int(std::lround(duration / dt)),
                           Eigen::VectorXd::Constant(1, u0), Eigen::VectorXd::Constant(1, v0));
        err[i] = maxError(u, dt, exact);
    }
    // Period error (w dt)^2 / 24 over w t = 20 rad: ~8e-3 of the amplitude at w dt = 0.1.
    QVERIFY2(err[0] < 0.02 * u0, qPrintable(QString::number(err[0])));
    const double ratio = err[0] / err[1];
    // Second order: halving dt divides the error by 4; [3, 5] allows for higher-order terms.
    QVERIFY2(ratio >= 3.0 && ratio <= 5.0, qPrintable(QString("error ratio %1").arg(ratio)));
}

void TestExplicitNewmark::harmonicGroundMotionConvergesAsDtSquared() {
    // m u'' + c u' + k u = -m A sin(W t) from rest, W = 12 rad/s (below resonance).
    const double zeta = 0.05, amp = 2.0, bigW = 12.0, duration = 3.0;
    auto ag = [&](double t) { return amp * std::sin(bigW * t); };
    auto exact = [&](double t) { return harmonicFromRest(kOmega, zeta, amp, bigW, t); };
    double err[2], umax = 0.0;
    for (int i = 0; i < 2; ++i) {
        const double dt = 0.005 / (1 << i);
        auto s = makeSdof(kMass, kStiff, zeta);
        ExplicitNewmark in;
        const auto u = run(*s, in, dt, int(std::lround(duration / dt)), Eigen::VectorXd::Zero(1),
                           Eigen::VectorXd::Zero(1), ag);
        err[i] = maxError(u, dt, exact);
        umax = peak(u);
    }
    // Steady-state amplitude A / sqrt(D) = 2 / 256.6 m ~ 7.8 mm; the response must be there.
    QVERIFY(umax > 0.006);
    // Errors of order (w dt)^2 times the response: 2 % of the peak at w dt = 0.1.
    QVERIFY2(err[0] < 0.02 * umax, qPrintable(QString("error %1 of %2").arg(err[0]).arg(umax)));
    const double ratio = err[0] / err[1];
    QVERIFY2(ratio >= 3.0 && ratio <= 5.0, qPrintable(QString("error ratio %1").arg(ratio)));
}

void TestExplicitNewmark::predictIsTheNextDisplacement() {
    auto s = makeSdof(kMass, kStiff, 0.05);
    ExplicitNewmark in;
    const double dt = 0.01;
    run(*s, in, dt, 10, 0.01, 0.3);
    const Eigen::VectorXd u = in.displacement(), v = in.velocity(), a = in.acceleration();
    const Eigen::VectorXd predicted = in.predict();
    // u[n+1] = u[n] + dt v[n] + dt^2/2 a[n], the displacement the specimen receives.
    QVERIFY((predicted - (u + dt * v + 0.5 * dt * dt * a)).norm() < 1e-15);
    s->setTrial(predicted);
    QVERIFY(in.correct(s->restoringForce(), 0.0));
    QVERIFY(in.displacement() == predicted); // explicit: no correction of u
}

void TestExplicitNewmark::nonFiniteForceIsRefused() {
    auto s = makeSdof(kMass, kStiff, 0.05);
    ExplicitNewmark in;
    run(*s, in, 0.01, 5, 0.01);
    const Eigen::VectorXd u = in.displacement(), v = in.velocity(), a = in.acceleration();
    const Eigen::VectorXd bad =
        Eigen::VectorXd::Constant(1, std::numeric_limits<double>::quiet_NaN());
    QVERIFY(!in.correct(bad, 0.0));
    QVERIFY(in.displacement() == u);
    QVERIFY(in.velocity() == v);
    QVERIFY(in.acceleration() == a);
}

QTEST_APPLESS_MAIN(TestExplicitNewmark)
#include "TestExplicitNewmark.moc"
