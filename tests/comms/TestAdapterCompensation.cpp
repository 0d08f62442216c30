// AdapterCompensation against an exactly solvable penalty (docs/openfresco.md "The adapter's
// penalty and its compensation"): a spring behind OpenSees' adapter sits where its force
// balances KB (s - db); for a linear spring k that is db = KB s / (KB + k) and the adapter's
// force q = KB (s - db). The compensation must estimate KB from [db, q] and put the spring on
// the console's target, so that the corrected force is k d to rounding; without it the spring
// sits F / KB short (force error k^2 d / KB). The real adapter: TestOpenSeesPairings.
#include "comms/openfresco/AdapterCompensation.h"

#include <QtTest>

#include <cmath>

using hsmu::comms::of::AdapterCompensation;

namespace {

/// The adapter with a linear spring k behind the penalty kb: [db, q] for a command s.
struct LinearAdapter {
    double k, kb;
    void answer(double s, double& db, double& q) const {
        db = kb * s / (kb + k);
        q = kb * (s - db);
    }
};

/// The adapter with a hardening spring F = k u + c u^3, db by Newton to convergence.
struct CubicAdapter {
    double k, c, kb;
    double force(double u) const { return k * u + c * u * u * u; }
    void answer(double s, double& db, double& q) const {
        db = s;
        for (int i = 0; i < 50; ++i) {
            const double r = force(db) + kb * (db - s);
            const double t = k + 3.0 * c * db * db + kb;
            const double next = db - r / t;
            if (next == db)
                break;
            db = next;
        }
        q = kb * (s - db);
    }
};

double target(int i) {
    return 0.03 * std::sin(0.07 * i) + 0.01 * std::sin(0.23 * i); // reversals at two rates
}

/// 300 steps of target() through the adapter a; the largest |F - force(d)| from step `from`
/// on; every corrected step is handed to check(step, target, sent, corrected).
template <class Adapter, class Force, class Check>
double drive(const Adapter& a, AdapterCompensation& comp, Force force, int from, Check check) {
    double worst = 0.0;
    for (int i = 1; i <= 300; ++i) {
        const double d = target(i);
        double db = 0.0, q = 0.0;
        const double s = comp.command(d);
        a.answer(s, db, q);
        const auto c = comp.correct(db, q);
        comp.commit();
        check(d, s, db, c);
        if (i >= from)
            worst = std::max(worst, std::abs(c.force - force(d)));
    }
    return worst;
}

} // namespace

class TestAdapterCompensation : public QObject {
    Q_OBJECT
private slots:
    void linearSpringSitsOnTheTarget() {
        const LinearAdapter a{40.0, 5.0e7};
        AdapterCompensation comp;
        bool onTarget = true;
        // KB is known from the second step on.
        const double worst = drive(
            a, comp, [&](double d) { return a.k * d; }, 2,
            [&](double d, double, double, const AdapterCompensation::Corrected& c) {
                onTarget = onTarget && c.deformation == d;
            });
        QVERIFY(onTarget);
        QVERIFY2(std::abs(comp.penalty() / a.kb - 1.0) < 1e-12,
                 qPrintable(QString::number(comp.penalty(), 'g', 17)));
        QVERIFY2(std::abs(comp.tangent() / a.k - 1.0) < 1e-6,
                 qPrintable(QString::number(comp.tangent())));
        // The rounding of db (ulp 0.04 = 7e-18) times KB: about 3e-10.
        QVERIFY2(worst <= 1e-9, qPrintable(QString::number(worst)));
    }

    void uncompensatedSpringSitsShortOfTheTarget() {
        const LinearAdapter a{40.0, 5.0e7};
        AdapterCompensation comp({false, false});
        bool asIs = true; // sent and read as they are
        const double worst = drive(
            a, comp, [&](double d) { return a.k * d; }, 1,
            [&](double d, double s, double db, const AdapterCompensation::Corrected& c) {
                asIs = asIs && s == d && c.deformation == db;
            });
        QVERIFY(asIs);
        // k^2 d / KB = 1600 x 0.04 / 5e7 = 1.3e-6 at the peak.
        QVERIFY2(worst > 1e-6 && worst < 2e-6, qPrintable(QString::number(worst)));
    }

    void nonlinearSpringThroughReversals() {
        // A force that is not linear in the deformation: the parabola predicts it to second
        // order (the worst step, a reversal, reads 8.3e-10 kN off; uncompensated 1e-6).
        const CubicAdapter a{40.0, 2.0e4, 5.0e7};
        AdapterCompensation comp;
        // From step 2: the first step is read with the secant from rest (2.7e-9 here).
        const double worst =
            drive(a, comp, [&](double d) { return a.force(d); }, 2,
                  [](double, double, double, const AdapterCompensation::Corrected&) {});
        QVERIFY2(worst <= 2e-9, qPrintable(QString::number(worst)));
    }
};

QTEST_GUILESS_MAIN(TestAdapterCompensation)
#include "TestAdapterCompensation.moc"
