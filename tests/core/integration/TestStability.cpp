// Tests of checkStability (core/integration/StabilityCheck.h) and of the stability of the
// schemes themselves: explicit Newmark is stable for omega dt <= 2 and blows up beyond it;
// alpha-OS is unconditionally stable on linear systems.

#include "core/integration/AlphaOS.h"
#include "core/integration/ExplicitNewmark.h"
#include "core/integration/StabilityCheck.h"

#include "IntegrationFixture.h"

#include <QtTest>

#include <cmath>

using namespace hsmu;
using namespace hsmu::testing;

namespace {
constexpr double kMass = 2.0;    // [t]
constexpr double kStiff = 800.0; // [kN/m] -> omega = 20 rad/s
constexpr double kOmega = 20.0;
} // namespace

class TestStability : public QObject {
    Q_OBJECT
private slots:
    void explicitFlaggedAboveTwo();
    void explicitAcceptedBelowTwo();
    void twoDofUsesHighestFrequency();
    void alphaOSIsNeverFlagged();
    void explicitRunGrowsPastTheLimit();
    void explicitRunStaysBoundedBelowTheLimit();
    void alphaOSRunStaysBoundedAtLargeOmegaDt();
};

void TestStability::explicitFlaggedAboveTwo() {
    auto s = makeSdof(kMass, kStiff, 0.0);
    const ExplicitNewmark in;
    const StabilityReport r = checkStability(*s, in, 2.1 / kOmega);
    QVERIFY(!r.stable);
    // omega from Eigen's generalized solver: 1e-12 relative.
    QVERIFY(std::abs(r.omegaMax - kOmega) < 1e-12 * kOmega);
    QVERIFY(std::abs(r.omegaDt - 2.1) < 1e-12);
    QCOMPARE(r.limit, 2.0);
    QVERIFY(std::abs(r.maxStableDt - 0.1) < 1e-14);
    const QString msg = QString::fromStdString(r.message);
    QVERIFY2(msg.contains("unstable"), qPrintable(msg));
    QVERIFY2(msg.contains("0.1 s"), qPrintable(msg)); // the largest stable dt
}

void TestStability::explicitAcceptedBelowTwo() {
    auto s = makeSdof(kMass, kStiff, 0.0);
    const ExplicitNewmark in;
    const StabilityReport r = checkStability(*s, in, 1.9 / kOmega);
    QVERIFY(r.stable);
    QVERIFY(std::abs(r.omegaDt - 1.9) < 1e-12);
    QVERIFY(!QString::fromStdString(r.message).contains("unstable"));
}

void TestStability::twoDofUsesHighestFrequency() {
    auto s = makeChain(2.0, 1.0, 300.0, 200.0, 150.0, 0.0);
    const double wMax = s->frequencies().maxCoeff(), wMin = s->frequencies().minCoeff();
    QVERIFY(wMax > 1.5 * wMin);
    const ExplicitNewmark in;
    // Stable for the first mode, unstable for the second: must be flagged.
    const double dt = 2.2 / wMax;
    QVERIFY(wMin * dt < 2.0 && wMax * dt > 2.0);
    const StabilityReport r = checkStability(*s, in, dt);
    QVERIFY(!r.stable);
    QVERIFY(std::abs(r.omegaMax - wMax) < 1e-12 * wMax);
    QVERIFY(std::abs(r.maxStableDt - 2.0 / wMax) < 1e-12 * r.maxStableDt);
}

void TestStability::alphaOSIsNeverFlagged() {
    auto s = makeSdof(kMass, kStiff, 0.0);
    const AlphaOS in(-0.05);
    const StabilityReport r = checkStability(*s, in, 10.0 / kOmega);
    QVERIFY(r.stable);
    QVERIFY(std::isinf(r.limit));
}

void TestStability::explicitRunGrowsPastTheLimit() {
    // omega dt = 2.1: cos(theta) = 1 - 2.205 < -1, the recursion has a root of modulus ~1.88;
    // after 100 steps the response exceeds 1e6 times its start (if it has not overflowed,
    // in which case correct() refuses the step and the history is cut short).
    auto s = makeSdof(kMass, kStiff, 0.0);
    ExplicitNewmark in;
    const double u0 = 0.01;
    const auto u = run(*s, in, 2.1 / kOmega, 100, u0);
    QVERIFY2(peak(u) > 1e6 * u0, qPrintable(QString::number(peak(u) / u0)));
}

void TestStability::explicitRunStaysBoundedBelowTheLimit() {
    // omega dt = 1.9 from rest at u0: the exact discrete solution is u0 cos(n theta).
    auto s = makeSdof(kMass, kStiff, 0.0);
    ExplicitNewmark in;
    const double u0 = 0.01;
    const auto u = run(*s, in, 1.9 / kOmega, 10000, u0);
    QCOMPARE(int(u.size()), 10001);
    QVERIFY2(peak(u) <= u0 * (1.0 + 1e-9), qPrintable(QString::number(peak(u) / u0)));
}

void TestStability::alphaOSRunStaysBoundedAtLargeOmegaDt() {
    // Same system, omega dt = 10 (five times the explicit limit), also on a 2-DOF chain.
    auto s = makeSdof(kMass, kStiff, 0.0);
    AlphaOS in(-0.05);
    const double u0 = 0.01;
    const auto u = run(*s, in, 10.0 / kOmega, 10000, u0);
    QCOMPARE(int(u.size()), 10001);
    QVERIFY2(peak(u) <= u0 * (1.0 + 1e-9), qPrintable(QString::number(peak(u) / u0)));

    auto chain = makeChain(2.0, 1.0, 300.0, 200.0, 150.0, 0.02);
    AlphaOS in2(-0.05);
    const Eigen::Vector2d u0v(0.01, -0.01);
    const auto u2 = run(*chain, in2, 10.0 / chain->frequencies().maxCoeff(), 5000, u0v,
                        Eigen::VectorXd::Zero(2));
    QCOMPARE(int(u2.size()), 5001);
    QVERIFY2(peak(u2) < 2.0 * 0.01, qPrintable(QString::number(peak(u2))));
}

QTEST_APPLESS_MAIN(TestStability)
#include "TestStability.moc"
