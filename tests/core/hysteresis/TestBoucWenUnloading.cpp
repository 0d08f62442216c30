// Tests of BoucWen's unloading increments that start beyond the unloading branch's bound
// (core/hysteresis/BoucWen.h, issue 29 item 5), against a fine explicit integration of Eq. 2.

#include "core/hysteresis/BoucWen.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

using namespace hsmu;

namespace {

// z1(e) = (A(e) / (nu(e) (gamma - beta)))^(1/n): the largest |z| from which Eq. 2's unloading
// branch moves z towards 0 (BoucWen.h), written out from the equation.
// fraction 0.5 gives zr, where that rate is half the elastic one.
double unloadingBound(const BoucWenParameters& p, double e, double fraction = 1.0) {
    const double a = p.A0 - p.deltaA * e, nu = 1.0 + p.deltaNu * e;
    return std::pow(fraction * a / (nu * (p.gamma - p.beta)), 1.0 / p.n);
}

// Explicit Euler of Eqs 2-3 over dx in m steps from s; the largest |z| on the way.
double explicitPeak(const BoucWenParameters& p, BoucWenState s, double dx, int m,
                    BoucWenState* end = nullptr) {
    const double h = dx / m, c = (1.0 - p.alpha) * p.k0;
    double peak = std::abs(s.z);
    for (int k = 0; k < m && std::isfinite(s.z); ++k) {
        const double psi = p.gamma + p.beta * (h * s.z > 0.0 ? 1.0 : -1.0);
        const double a = p.A0 - p.deltaA * s.e, nu = 1.0 + p.deltaNu * s.e;
        const double eta = 1.0 + p.deltaEta * s.e;
        const double dz = (a - std::pow(std::abs(s.z), p.n) * psi * nu) / eta * h;
        s.e += c * s.z * h;
        s.z += dz;
        peak = std::max(peak, std::abs(s.z));
    }
    if (end)
        *end = s;
    return std::isfinite(s.z) ? peak : std::numeric_limits<double>::infinity();
}

} // namespace

class TestBoucWenUnloading : public QObject {
    Q_OBJECT
private slots:
    void unloadingFromBeyondItsBound();
};


// Issue 29 (item 5): unloading increments from a state beyond the unloading branch's bound
// z1(e0), met at the sigma points of the default UKF on a record that starts with 5 s of
// sensor noise (test_identification_ukf_noisy_start: 35 rejected samples): the parameters of a
// sigma point (a larger deltaNu, gamma - beta, or beta < 0) put the state z beyond z1, where
// the continuous law runs away (shown below by a fine explicit integration leaving the
// iterates' bound 10 max(|z0|, ultimate z)), so no step existed and the law failed
// (NoConvergence). It now starts such an increment from zr = 2^(-1/n) z1 (e0 kept; z1 is an
// equilibrium of the unloading branch): the same end state as an increment from that state,
// which ends near a fine explicit reference and within zr.
void TestBoucWenUnloading::unloadingFromBeyondItsBound() {
    struct Case {
        double k0, alpha, n, beta, gamma, deltaNu, deltaEta, z0, e0, dx;
    };
    // Taken from the failures of that run (A0 1, deltaA 0).
    const Case cases[] = {
        {1.24195, 0.585764, 1.40479, -6.68555, 7.67923, 20.0, 0.0, -0.57184831, 0.19960694, 0.794588672},
        {1.24114, 0.541849, 0.820011, 0.110961, 1.11794, 19.98, 0.0200055, 0.0871253839, 1.61220611, -0.648578178},
        {1.37852, 0.424854, 1.86757, -4.75885, 4.75985, 20.0, 0.0, 1.16824715, 1.11694045, -0.0303342784},
        {1.12664, 0.9, 0.2, -1.17729, 5.29625, 0.0, 0.0, 0.000843449994, 7.12804939e-05, -0.0189512611},
        {1.00139, 0.703025, 1.53179, -1.33921, 1.89438, 0.796071, 0.124512, 0.854812317, 0.221292987, -1.4749906},
    };
    std::vector<BoucWenParameters> ps;
    std::vector<BoucWenState> froms;
    std::vector<double> dxs;
    for (const Case& c : cases) {
        BoucWenParameters p;
        p.k0 = c.k0;
        p.alpha = c.alpha;
        p.n = c.n;
        p.beta = c.beta;
        p.gamma = c.gamma;
        p.deltaNu = c.deltaNu;
        p.deltaEta = c.deltaEta;
        const BoucWenState from{c.z0, c.e0};
        const double z1 = unloadingBound(p, c.e0);
        QVERIFY(std::abs(c.z0) > z1 && c.dx * c.z0 < 0.0); // an unloading from beyond z1
        // The continuous law runs away from there: beyond the iterates' bound.
        const double zBound = 10.0 * std::max(std::abs(c.z0), BoucWen::ultimateZ(p));
        QVERIFY2(explicitPeak(p, from, c.dx, 1000000) > zBound,
                 qPrintable(QStringLiteral("case z0 %1: no runaway").arg(c.z0)));
        const BoucWenIncrement inc = BoucWen::integrateState(p, from, c.dx);
        QCOMPARE(inc.status, LawStatus::Ok);
        const double zr = unloadingBound(p, c.e0, 0.5);
        const BoucWenState returned{std::copysign(zr, c.z0), c.e0};
        const BoucWenIncrement fromBound = BoucWen::integrateState(p, returned, c.dx);
        QCOMPARE(fromBound.status, LawStatus::Ok);
        QCOMPARE(inc.state.z, fromBound.state.z);
        QCOMPARE(inc.state.e, fromBound.state.e);
        // z moved with dx from zr: towards 0, and past it at most to -zu(e)
        QVERIFY((inc.state.z - returned.z) * c.dx > 0.0);
        QVERIFY(std::abs(inc.state.z) <= zr || inc.state.z * c.z0 < 0.0);
        // first order against a fine explicit integration from zr (z's scale: z1)
        BoucWenState reference;
        explicitPeak(p, returned, c.dx, 1000000, &reference);
        qInfo("z0 %.4g beyond z1 %.4g: z %.6g (explicit from zr %.6g), e %.6g (%.6g)", c.z0, z1,
              inc.state.z, reference.z, inc.state.e, reference.e);
        QVERIFY2(std::abs(inc.state.z - reference.z) <= 0.1 * z1 + 0.05 * std::abs(reference.z),
                 qPrintable(QStringLiteral("z %1 against %2").arg(inc.state.z).arg(reference.z)));
        ps.push_back(p);
        froms.push_back(from);
        dxs.push_back(c.dx);
    }
    // The batch of sigma points takes the same path (one increment for all: per case here).
    for (std::size_t i = 0; i < ps.size(); ++i) {
        std::vector<BoucWenIncrement> out(1);
        BoucWen::integrateStates(std::span(&ps[i], 1), std::span(&froms[i], 1), dxs[i], out,
                                 BoucWen::BatchMath::Exact);
        const BoucWenIncrement one = BoucWen::integrateState(ps[i], froms[i], dxs[i]);
        QCOMPARE(out[0].status, LawStatus::Ok);
        QCOMPARE(out[0].state.z, one.state.z);
        QCOMPARE(out[0].state.e, one.state.e);
    }
    // An unloading from within z1 is untouched: the same as before (no return), z0 kept as start.
    BoucWenParameters p = ps[1];
    const double z1 = unloadingBound(p, 1.6);
    const BoucWenIncrement inside = BoucWen::integrateState(p, {0.5 * z1, 1.6}, -1e-3);
    QCOMPARE(inside.status, LawStatus::Ok);
    QVERIFY(inside.state.z < 0.5 * z1 && inside.state.z > 0.5 * z1 - 2e-3);
}

QTEST_APPLESS_MAIN(TestBoucWenUnloading)
#include "TestBoucWenUnloading.moc"
