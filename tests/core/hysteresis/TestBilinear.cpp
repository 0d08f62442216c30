// Tests of Bilinear (core/hysteresis/Bilinear.h): every branch against the closed-form
// piecewise-linear response. The return mapping is exact, so tolerances are round-off only.
// LawStatus is compared with QVERIFY(a == b): QCOMPARE would pick hsmu::toString by ADL.

#include "core/hysteresis/Bilinear.h"
#include "tests/support/LawByName.h"

#include "LawTestSupport.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace hsmu;
using namespace hsmu::testsupport;

namespace {

// The paper's first example: stiffness 1.015 kN/mm, yield 2.8 kN, post-yield ratio 0.1.
const BilinearParameters kPaper{1.015, 2.8, 0.1};

bool near(double a, double b, double scale) {
    return std::abs(a - b) <= 1e-12 * scale;
}

} // namespace

class TestBilinear : public QObject {
    Q_OBJECT

private slots:
    void elasticBranch();
    void yieldAndPostYieldSlope();
    void unloadingAndKinematicHardening();
    void energyPerCycleIsTheParallelogram();
    void perfectlyPlasticWhenBIsZero();
    void stateAndParameters();
};

void TestBilinear::elasticBranch() {
    Bilinear law(kPaper);
    QCOMPARE(law.lawName(), std::string("bilinear"));
    QCOMPARE(law.initialTangent(), kPaper.k0);
    for (const double u : {1.0, -2.0, 0.5 * kPaper.fy / kPaper.k0}) {
        QVERIFY(law.setTrialDeformation(u) == LawStatus::Ok);
        QVERIFY(near(law.trialForce(), kPaper.k0 * u, kPaper.fy));
        QCOMPARE(law.trialTangent(), kPaper.k0);
    }
}

void TestBilinear::yieldAndPostYieldSlope() {
    const double k0 = kPaper.k0, fy = kPaper.fy, b = kPaper.b, uy = fy / k0;
    Bilinear law(kPaper);
    QVERIFY(law.setTrialDeformation(0.999 * uy) == LawStatus::Ok);
    QCOMPARE(law.trialTangent(), k0);
    QVERIFY(near(law.trialForce(), 0.999 * fy, fy));
    // Monotonic loading in steps of 0.1 uy up to 5 uy: F = fy + b k0 (u - uy) beyond yield.
    for (int i = 1; i <= 50; ++i) {
        const double u = 0.1 * i * uy;
        QVERIFY(law.setTrialDeformation(u) == LawStatus::Ok);
        const double expected = u <= uy ? k0 * u : fy + b * k0 * (u - uy);
        QVERIFY2(near(law.trialForce(), expected, fy), qPrintable(QString::number(u)));
        if (u > 1.001 * uy) {
            QVERIFY(near(law.trialTangent(), b * k0, k0));
        }
        law.commit();
    }
    // The same end point in one step gives the same force (exact return mapping).
    Bilinear oneStep(kPaper);
    QVERIFY(oneStep.setTrialDeformation(5.0 * uy) == LawStatus::Ok);
    QVERIFY(near(oneStep.trialForce(), law.committedForce(), fy));
}

void TestBilinear::unloadingAndKinematicHardening() {
    const double k0 = kPaper.k0, fy = kPaper.fy, b = kPaper.b, uy = fy / k0;
    const double um = 5.0 * uy, fm = fy + b * k0 * (um - uy);
    Bilinear law(kPaper);
    QVERIFY(law.setTrialDeformation(um) == LawStatus::Ok);
    law.commit();
    QVERIFY(near(law.committedForce(), fm, fy));
    // Unloading is elastic (slope k0) until the force has changed by 2 fy, i.e. until
    // u = um - 2 uy; then reverse yielding follows the slope b k0 (kinematic hardening: the
    // yield surface moved up by the back force fm - fy).
    for (int i = 1; i <= 400; ++i) {
        const double u = um - 0.01 * i * uy;
        QVERIFY(law.setTrialDeformation(u) == LawStatus::Ok);
        const double du = um - u;
        const bool elastic = du <= 2.0 * uy;
        const double expected = elastic ? fm - k0 * du : fm - 2.0 * fy - b * k0 * (du - 2.0 * uy);
        QVERIFY2(near(law.trialForce(), expected, fy), qPrintable(QString::number(du / uy)));
        if (std::abs(du - 2.0 * uy) > 1e-9 * uy) {
            QVERIFY(near(law.trialTangent(), elastic ? k0 : b * k0, k0));
        }
        law.commit();
    }
}

void TestBilinear::energyPerCycleIsTheParallelogram() {
    // k0 = 1, fy = 2 (uy = 2), b = 0.1; cycles between +-um = +-6 in steps of 0.5 so that every
    // corner of the loop (u = 2, -2 and +-6) is a history point and the trapezoidal integral
    // is exact. Closed form of the loop area: 4 fy (1 - b)(um - uy) = 28.8.
    const BilinearParameters p{1.0, 2.0, 0.1};
    std::vector<double> u{0.0};
    for (int i = 1; i <= 12; ++i) {
        u.push_back(0.5 * i); // 0 -> 6
    }
    for (int cycle = 0; cycle < 2; ++cycle) {
        for (int i = 1; i <= 24; ++i) {
            u.push_back(6.0 - 0.5 * i); // 6 -> -6
        }
        for (int i = 1; i <= 24; ++i) {
            u.push_back(-6.0 + 0.5 * i); // -6 -> 6
        }
    }
    Bilinear law(p);
    const Run run = drive(law, std::vector<double>(u.begin() + 1, u.end()));
    QVERIFY(run.ok);
    std::vector<double> f{0.0};
    f.insert(f.end(), run.force.begin(), run.force.end());
    const double expected = 4.0 * p.fy * (1.0 - p.b) * (6.0 - p.fy / p.k0);
    for (std::size_t cycle = 0; cycle < 2; ++cycle) {
        const double w = work(u, f, 12 + 48 * cycle, 12 + 48 * (cycle + 1));
        QVERIFY2(near(w, expected, expected), qPrintable(QString::number(w)));
    }
    // Symmetric peaks: +-(fy + b k0 (um - uy)) = +-2.4.
    QVERIFY(near(f[12], 2.4, 1.0) && near(f[36], -2.4, 1.0) && near(f.back(), 2.4, 1.0));
}

void TestBilinear::perfectlyPlasticWhenBIsZero() {
    Bilinear law(BilinearParameters{2.0, 1.0, 0.0});
    for (const double u : {0.25, 1.0, 3.0, 10.0}) {
        QVERIFY(law.setTrialDeformation(u) == LawStatus::Ok);
        QVERIFY(near(law.trialForce(), std::min(2.0 * u, 1.0), 1.0));
        law.commit();
    }
    QCOMPARE(law.trialTangent(), 0.0);
    QVERIFY(near(law.committedState().plasticDeformation, 9.5, 10.0));
    QVERIFY(law.setTrialDeformation(9.25) == LawStatus::Ok); // elastic unloading from 10
    QVERIFY(near(law.trialForce(), -0.5, 1.0));
    QCOMPARE(law.trialTangent(), 2.0);
}

void TestBilinear::stateAndParameters() {
    Bilinear law(kPaper);
    QVERIFY(law.setTrialDeformation(10.0) == LawStatus::Ok);
    law.commit();
    const double f = law.committedForce();
    const BilinearState s = law.committedState();
    QVERIFY(law.setTrialDeformation(3.0) == LawStatus::Ok);
    const double fTrial = law.trialForce();
    QVERIFY(law.committedForce() == f);
    auto copy = law.clone();
    QVERIFY(copy->trialForce() == fTrial && copy->committedForce() == f);
    law.revert();
    QVERIFY(law.trialForce() == f && law.trialDeformation() == 10.0);
    for (const double bad :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        QVERIFY(law.setTrialDeformation(bad) == LawStatus::InvalidInput);
        QVERIFY(law.trialForce() == f && law.committedForce() == f);
    }
    QVERIFY(law.parameterNames() == (std::vector<std::string>{"k0", "fy", "b"}));
    QCOMPARE(*test::parameterNamed(law, "fy"), kPaper.fy);
    QVERIFY(!test::parameterNamed(law, "E").has_value());
    QVERIFY(!test::setParameterNamed(law, "b", 1.0));
    QVERIFY(!test::setParameterNamed(law, "fy", 0.0));
    QVERIFY(!test::setParameterNamed(law, "k0", std::numeric_limits<double>::quiet_NaN()));
    QVERIFY(!test::setParameterNamed(law, "E", 1.0));
    // A new k0 keeps (up, q): the committed force is re-evaluated as k0 (u - up).
    QVERIFY(test::setParameterNamed(law, "k0", 2.0 * kPaper.k0));
    QVERIFY(law.committedState().plasticDeformation == s.plasticDeformation);
    QVERIFY(near(law.committedForce(), 2.0 * kPaper.k0 * (10.0 - s.plasticDeformation), f));
    law.revertToStart();
    QVERIFY(law.committedForce() == 0.0 && law.committedState().backForce == 0.0);
}

QTEST_APPLESS_MAIN(TestBilinear)
#include "TestBilinear.moc"
