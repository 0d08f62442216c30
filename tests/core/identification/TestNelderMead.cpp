// Tests of NelderMead (core/identification/NelderMead.h) on standard test functions with
// known minima: Rosenbrock in 2-D and 4-D, a shifted quadratic, a bounded problem whose
// minimum lies on a bound; the evaluation budget is a hard limit; invalid input is reported.
// NelderMeadStop is compared with QVERIFY(a == b): QCOMPARE would look for a toString by ADL.

#include "core/identification/NelderMead.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace hsmu;
using Vector = Eigen::VectorXd;

namespace {

double rosenbrock(const Vector& x) {
    double f = 0.0;
    for (Eigen::Index i = 0; i + 1 < x.size(); ++i) {
        f += 100.0 * std::pow(x(i + 1) - x(i) * x(i), 2) + std::pow(1.0 - x(i), 2);
    }
    return f;
}

Vector vec(std::initializer_list<double> values) {
    Vector v(static_cast<Eigen::Index>(values.size()));
    Eigen::Index i = 0;
    for (const double x : values) {
        v(i++) = x;
    }
    return v;
}

} // namespace

class TestNelderMead : public QObject {
    Q_OBJECT

private slots:
    void rosenbrock2d();
    void rosenbrock4d();
    void shiftedQuadratic();
    void minimumOnABound();
    void respectsMaxEvaluations();
    void nonFiniteValuesAndInvalidInput();
};

void TestNelderMead::rosenbrock2d() {
    NelderMeadSettings s;
    s.maxEvaluations = 2000;
    const NelderMeadResult r = NelderMead(s).minimize(rosenbrock, vec({-1.2, 1.0}));
    qInfo("Rosenbrock 2-D: f %.3g after %d evaluations, %d restarts", r.f, r.evaluations,
          r.restarts);
    QVERIFY(r.stop == NelderMeadStop::Converged);
    // Tolerance: the valley is flat along x1 = x0^2; 1e-5 is far above the tolerances' effect.
    QVERIFY2((r.x - vec({1.0, 1.0})).cwiseAbs().maxCoeff() <= 1e-5,
             qPrintable(QString("%1 %2").arg(r.x(0)).arg(r.x(1))));
    QVERIFY(r.f <= 1e-10);
}

void TestNelderMead::rosenbrock4d() {
    NelderMeadSettings s;
    s.maxEvaluations = 20000;
    const NelderMeadResult r = NelderMead(s).minimize(rosenbrock, vec({-1.2, 1.0, -1.2, 1.0}));
    qInfo("Rosenbrock 4-D: f %.3g after %d evaluations, %d restarts", r.f, r.evaluations,
          r.restarts);
    QVERIFY(r.stop == NelderMeadStop::Converged);
    QVERIFY2((r.x - Vector::Ones(4)).cwiseAbs().maxCoeff() <= 1e-4,
             qPrintable(QString("%1 %2 %3 %4").arg(r.x(0)).arg(r.x(1)).arg(r.x(2)).arg(r.x(3))));
    QVERIFY(r.f <= 1e-8);
}

void TestNelderMead::shiftedQuadratic() {
    // f = sum_i (i + 1) (x_i - c_i)^2 in 5-D, minimum 3 at c.
    const Vector c = vec({0.5, -2.0, 3.0, 10.0, -0.25});
    const auto f = [&](const Vector& x) {
        double v = 3.0;
        for (Eigen::Index i = 0; i < x.size(); ++i) {
            v += double(i + 1) * (x(i) - c(i)) * (x(i) - c(i));
        }
        return v;
    };
    NelderMeadSettings s;
    s.maxEvaluations = 5000;
    const NelderMeadResult r = NelderMead(s).minimize(f, Vector::Zero(5));
    QVERIFY(r.stop == NelderMeadStop::Converged);
    QVERIFY2((r.x - c).cwiseAbs().maxCoeff() <= 1e-5, qPrintable(QString::number(r.f)));
    QVERIFY(std::abs(r.f - 3.0) <= 1e-9);
}

void TestNelderMead::minimumOnABound() {
    // Unconstrained minimum at (2, -1); the box [-1, 1] x [0, 3] puts it at (1, 0). Every
    // evaluated point must be inside the box.
    bool outside = false;
    const auto f = [&](const Vector& x) {
        outside = outside || x(0) < -1.0 || x(0) > 1.0 || x(1) < 0.0 || x(1) > 3.0;
        return std::pow(x(0) - 2.0, 2) + 3.0 * std::pow(x(1) + 1.0, 2) + 0.5 * x(0) * x(1);
    };
    const NelderMeadResult r =
        NelderMead().minimize(f, vec({0.0, 2.0}), vec({-1.0, 0.0}), vec({1.0, 3.0}));
    QVERIFY(!outside);
    QVERIFY(r.stop == NelderMeadStop::Converged);
    QVERIFY2((r.x - vec({1.0, 0.0})).cwiseAbs().maxCoeff() <= 1e-6,
             qPrintable(QString("%1 %2").arg(r.x(0)).arg(r.x(1))));
    // A start outside the box is clamped into it.
    const NelderMeadResult r2 =
        NelderMead().minimize(f, vec({5.0, -4.0}), vec({-1.0, 0.0}), vec({1.0, 3.0}));
    QVERIFY(!outside);
    QVERIFY((r2.x - vec({1.0, 0.0})).cwiseAbs().maxCoeff() <= 1e-6);
}

void TestNelderMead::respectsMaxEvaluations() {
    for (const int budget : {1, 2, 3, 7, 50, 137}) {
        int calls = 0;
        const auto f = [&](const Vector& x) {
            ++calls;
            return rosenbrock(x);
        };
        NelderMeadSettings s;
        s.maxEvaluations = budget;
        const NelderMeadResult r = NelderMead(s).minimize(f, vec({-1.2, 1.0, 0.5}));
        QCOMPARE(calls, budget);
        QCOMPARE(r.evaluations, budget);
        QVERIFY(r.stop == NelderMeadStop::MaxEvaluations);
        QVERIFY(r.f <= rosenbrock(vec({-1.2, 1.0, 0.5})));
        QVERIFY(std::abs(rosenbrock(r.x) - r.f) <= 1e-12 * (1.0 + r.f));
    }
}

void TestNelderMead::nonFiniteValuesAndInvalidInput() {
    // NaN outside the disc of radius 2 around the origin; the minimum (1.5, 0) is inside.
    const auto f = [](const Vector& x) {
        return x.norm() > 2.0 ? std::numeric_limits<double>::quiet_NaN()
                              : std::pow(x(0) - 1.5, 2) + x(1) * x(1);
    };
    const NelderMeadResult r = NelderMead().minimize(f, vec({0.0, 0.0}));
    QVERIFY(std::isfinite(r.f));
    QVERIFY((r.x - vec({1.5, 0.0})).norm() <= 1e-5);

    const NelderMead nm;
    QVERIFY(nm.minimize(f, vec({0.0, 0.0}), vec({1.0, 0.0}), vec({0.0, 1.0})).stop ==
            NelderMeadStop::InvalidInput);
    QVERIFY(nm.minimize(f, vec({std::numeric_limits<double>::quiet_NaN(), 0.0})).stop ==
            NelderMeadStop::InvalidInput);
    QVERIFY(nm.minimize(f, vec({0.0, 0.0}), vec({0.0}), vec({1.0})).stop ==
            NelderMeadStop::InvalidInput);
    QCOMPARE(std::string(nelderMeadStopName(NelderMeadStop::MaxEvaluations)),
             std::string("maximum number of evaluations"));
}

QTEST_APPLESS_MAIN(TestNelderMead)
#include "TestNelderMead.moc"
