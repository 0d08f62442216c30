// Velocities and accelerations through every setup (docs/setups.md, "Velocities and
// accelerations", eq. S5): along a smooth basic-displacement history d(t) (each DOF a sine of
// 0.05 m or rad at 0.7-2.2 Hz), actuatorRates() at d(t) with the exact v(t), a(t) against
// central differences in time of strokes(d(t)) (step 2e-5 s: truncation ~1e-8 of the peak
// velocity and of the peak acceleration; tolerances 1e-7 and 1e-6 of the peaks), the planar
// family's closed form against the generic Jdot v of ExperimentalSetup, and the size refusals.

#include "SetupCatalog.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace hsmu;

namespace {

struct Motion {
    Eigen::VectorXd d, v, a;
};

Motion at(int n, double t) {
    Motion m{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
    for (int k = 0; k < n; ++k) {
        const double A = 0.05, w = 2 * std::numbers::pi * (0.7 + 0.3 * k), ph = 0.4 * k;
        m.d(k) = A * std::sin(w * t + ph);
        m.v(k) = A * w * std::cos(w * t + ph);
        m.a(k) = -A * w * w * std::sin(w * t + ph);
    }
    return m;
}

Eigen::VectorXd strokesAt(const ExperimentalSetup& s, double t) {
    Eigen::VectorXd out;
    if (!s.strokes(at(s.basicSize(), t).d, out).ok)
        qFatal("strokes failed");
    return out;
}

} // namespace

class TestSetupRates : public QObject {
    Q_OBJECT
private slots:
    void ratesMatchTimeDifferencesOfTheStrokes();
    void planarClosedFormMatchesTheGenericJdot();
    void wrongSizesAreRefused();
};

void TestSetupRates::ratesMatchTimeDifferencesOfTheStrokes() {
    const double tau = 2e-5;
    double worstV = 0.0, worstA = 0.0;
    for (const setupcatalog::Case& c : setupcatalog::all()) {
        std::string e;
        const auto s = c.make(e);
        QVERIFY2(s, e.c_str());
        const int n = s->basicSize();
        double peakV = 0.0, peakA = 0.0, errV = 0.0, errA = 0.0;
        for (double t = 0.05; t < 1.5; t += 0.0731) {
            const Motion m = at(n, t);
            Eigen::VectorXd sv, sa;
            const SetupResult r = s->actuatorRates(m.d, m.v, m.a, sv, sa);
            QVERIFY2(r.ok, r.reason.c_str());
            const Eigen::VectorXd sp = strokesAt(*s, t + tau), s0 = strokesAt(*s, t),
                                  sm = strokesAt(*s, t - tau);
            const Eigen::VectorXd fdV = (sp - sm) / (2 * tau);
            const Eigen::VectorXd fdA = (sp - 2 * s0 + sm) / (tau * tau);
            peakV = std::max(peakV, fdV.cwiseAbs().maxCoeff());
            peakA = std::max(peakA, fdA.cwiseAbs().maxCoeff());
            errV = std::max(errV, (sv - fdV).cwiseAbs().maxCoeff());
            errA = std::max(errA, (sa - fdA).cwiseAbs().maxCoeff());
        }
        QVERIFY2(errV <= 1e-7 * peakV && errA <= 1e-6 * peakA,
                 qPrintable(QString::fromStdString(c.label) +
                            QString(": velocity %1 of %2, acceleration %3 of %4")
                                .arg(errV)
                                .arg(peakV)
                                .arg(errA)
                                .arg(peakA)));
        worstV = std::max(worstV, errV / peakV);
        worstA = std::max(worstA, errA / peakA);
    }
    qInfo("worst relative to the peak: velocity %.2e, acceleration %.2e", worstV, worstA);
}

void TestSetupRates::planarClosedFormMatchesTheGenericJdot() {
    double worst = 0.0;
    for (const setupcatalog::Case& c : setupcatalog::all()) {
        std::string e;
        const auto s = c.make(e);
        if (!dynamic_cast<const PlanarActuatorSetup*>(s.get()))
            continue;
        for (double t : {0.2, 0.9, 1.3}) {
            const Motion m = at(3, t);
            Eigen::VectorXd sv, sa, gv, ga;
            QVERIFY(s->actuatorRates(m.d, m.v, m.a, sv, sa).ok);
            QVERIFY(s->ExperimentalSetup::actuatorRates(m.d, m.v, m.a, gv, ga).ok);
            const double err = std::max((sv - gv).cwiseAbs().maxCoeff() / sv.cwiseAbs().maxCoeff(),
                                        (sa - ga).cwiseAbs().maxCoeff() / sa.cwiseAbs().maxCoeff());
            worst = std::max(worst, err);
            QVERIFY2(err <= 1e-8, qPrintable(QString::fromStdString(c.label) +
                                             QString(" t %1: %2").arg(t).arg(err)));
        }
    }
    qInfo("planar closed form against the generic Jdot v: worst %.2e", worst);
}

void TestSetupRates::wrongSizesAreRefused() {
    std::string e;
    auto planar = makeTwoActuators2d(setupcatalog::two(SetupGeometry::Exact, false), e);
    auto four = FourActuators3d::create(setupcatalog::four(SetupGeometry::Exact), e);
    Eigen::VectorXd sv, sa;
    SetupResult r = planar->actuatorRates(Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(2),
                                          Eigen::VectorXd::Zero(3), sv, sa);
    QVERIFY2(!r.ok && r.reason.rfind("TwoActuators2d: 3 basic displacements", 0) == 0,
             r.reason.c_str());
    r = four->actuatorRates(Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6),
                            Eigen::VectorXd::Zero(3), sv, sa);
    QVERIFY2(!r.ok && r.reason == "FourActuators3d: actuatorRates wants 6 basic displacements, "
                                  "velocities and accelerations, got 6, 6 and 3",
             r.reason.c_str());
}

QTEST_APPLESS_MAIN(TestSetupRates)
#include "TestSetupRates.moc"
