// FourActuators3d's axial-load rods (docs/setups.md, "FourActuators3d", eqs. S6-S9): their share
// of the basic forces against the hand-derived statics (linear: eq. S9 written out; exact: the
// rod force at the deformed pin and its moment about the control point, by cross products, for
// motions in the x-z and y-z planes, rotations to 0.3 rad), the rods' Jacobian against central
// differences of their lengths, and the refusals naming the setup and the parameter.

#include "SetupCatalog.h"

#include <QtTest>

#include <array>
#include <cmath>

using namespace hsmu;

namespace {

constexpr double kH1 = 0.45;                        // SetupCatalog's four(): rods' top pins
constexpr std::array<double, 2> kLrod = {1.6, 1.9}; // north, south

std::unique_ptr<FourActuators3d> make(SetupGeometry g, double phi = 0.0) {
    std::string e;
    auto s = FourActuators3d::create(setupcatalog::four(g, phi), e);
    if (!s)
        qFatal("%s", e.c_str());
    return s;
}

// q of the rods alone: basicForces with OpenFresco's six daq forces minus the actuators' share
Eigen::VectorXd rodShare(const FourActuators3d& s, const Eigen::VectorXd& d, double fN, double fS) {
    Eigen::VectorXd f6(6), f4(4), q6, q4;
    f4 << 310.0, -120.0, 95.0, 40.0; // any actuator forces: their share cancels
    f6 << fN, fS, f4;
    if (!s.basicForces(d, f6, q6).ok || !s.basicForces(d, f4, q4).ok)
        qFatal("basicForces failed");
    return q6 - q4;
}

// OpenFresco's basic DOFs from the platform's (ux, uy, uz, phix, phiy) at phiLocX = 0:
// d = (uz, -ux, -phiy, -uy, -phix, 0) (FourActuators3d.h), and the conjugate forces likewise.
Eigen::VectorXd basicOf(double ux, double uy, double uz, double phix, double phiy) {
    Eigen::VectorXd d(6);
    d << uz, -ux, -phiy, -uy, -phix, 0.0;
    return d;
}

} // namespace

class TestFourActuatorsRods : public QObject {
    Q_OBJECT
private slots:
    void atRestTheRodsCarryTheAxialLoadOnly();
    void linearMatchesTheSecondOrderClosedForm();
    void exactMatchesTheStaticsInTheXzPlane();
    void exactMatchesTheStaticsInTheYzPlane();
    void rodJacobianMatchesFiniteDifferences();
    void refusalsNameTheSetupAndParameter();
};

void TestFourActuatorsRods::atRestTheRodsCarryTheAxialLoadOnly() {
    for (SetupGeometry g : {SetupGeometry::Linear, SetupGeometry::Exact}) {
        const Eigen::VectorXd q =
            rodShare(*make(g, 25.0), Eigen::VectorXd::Zero(6), -400.0, -350.0);
        Eigen::VectorXd expected = Eigen::VectorXd::Zero(6);
        expected(0) = -750.0; // both rods in tension pull the platform down: axial load
        QVERIFY2((q - expected).cwiseAbs().maxCoeff() == 0.0, "rods at rest: axial load only");
    }
}

// eq. S8's length l_k = Lrod_k + uz - h1 |phi|^2 / 2 + (ex^2 + ey^2) / (2 Lrod_k), ex = ux + h1
// phiy, ey = uy - h1 phix; its gradient times f_k (eq. S9) written out here, in the element's DOFs
void TestFourActuatorsRods::linearMatchesTheSecondOrderClosedForm() {
    const double fN = -420.0, fS = -380.0;
    for (double phi : {0.0, 25.0}) {
        const auto s = make(SetupGeometry::Linear, phi);
        for (int k = 0; k < 5; ++k) {
            const double ux = 0.03 * (k - 2), uy = -0.02 * k + 0.01, uz = 0.002 * k;
            const double px = 0.04 * (k % 3 - 1), py = -0.05 + 0.03 * k;
            const Eigen::VectorXd d = basicOf(ux, uy, uz, px, py);
            // (ux, uy) and (phix, phiy) turn together by phiLocX: the form is invariant
            const double ex = ux + kH1 * py, ey = uy - kH1 * px;
            double qux = 0, quy = 0, quz = 0, qpx = 0, qpy = 0;
            for (int r = 0; r < 2; ++r) {
                const double f = r == 0 ? fN : fS, L = kLrod[r];
                qux += f * ex / L;
                quy += f * ey / L;
                quz += f;
                qpx += f * (-kH1 * ey / L - kH1 * px);
                qpy += f * (kH1 * ex / L - kH1 * py);
            }
            Eigen::VectorXd expected(6);
            expected << quz, -qux, -qpy, -quy, -qpx, 0.0;
            const Eigen::VectorXd q = rodShare(*s, d, fN, fS);
            const double peak = expected.cwiseAbs().maxCoeff();
            QVERIFY2((q - expected).cwiseAbs().maxCoeff() <= 1e-12 * peak,
                     qPrintable(QString("phiLocX %1, point %2: max |dq| %3 of %4")
                                    .arg(phi)
                                    .arg(k)
                                    .arg((q - expected).cwiseAbs().maxCoeff())
                                    .arg(peak)));
        }
    }
}

// rotation about y by phi: the pin at (ux + h1 sin phi, 0, uz + h1 cos phi); rod k from its
// anchor (0, 0, h1 - Lrod_k) along n, force f n on the platform (f: the load cell's, signed as
// an actuator's); q_ux = sum f n_x, q_uz = sum f n_z, q_phiy = moment about y = sum (Rp x f n)_y
void TestFourActuatorsRods::exactMatchesTheStaticsInTheXzPlane() {
    const auto s = make(SetupGeometry::Exact);
    const double fN = -420.0, fS = -380.0;
    double worst = 0.0;
    for (double ux : {-0.15, 0.02, 0.12})
        for (double phi : {-0.3, 0.05, 0.25}) {
            const double uz = -0.004;
            const Eigen::Vector3d Rp(kH1 * std::sin(phi), 0.0, kH1 * std::cos(phi));
            Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
            for (int r = 0; r < 2; ++r) {
                const Eigen::Vector3d rod =
                    Eigen::Vector3d(ux, 0.0, uz) + Rp - Eigen::Vector3d(0, 0, kH1 - kLrod[r]);
                const Eigen::Vector3d Fr = (r == 0 ? fN : fS) * rod.normalized();
                F += Fr;
                M += Rp.cross(Fr);
            }
            Eigen::VectorXd expected(6);
            expected << F.z(), -F.x(), -M.y(), -F.y(), -M.x(), 0.0;
            const Eigen::VectorXd q = rodShare(*s, basicOf(ux, 0.0, uz, 0.0, phi), fN, fS);
            const double err =
                (q - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff();
            worst = std::max(worst, err);
            QVERIFY2(err <= 1e-12,
                     qPrintable(QString("ux %1 phiy %2: %3").arg(ux).arg(phi).arg(err)));
            // the P-Delta of the inclined rods: in tension they pull the pin back toward the
            // anchors' line (q_ux of the sign of the pin's x)
            QVERIFY(F.x() * (ux + Rp.x()) < 0.0);
        }
    qInfo("x-z plane: worst relative difference %.2e", worst);
}

// rotation about x by phi: the pin at (0, uy - h1 sin phi, uz + h1 cos phi); q_phix = (Rp x F)_x
void TestFourActuatorsRods::exactMatchesTheStaticsInTheYzPlane() {
    const auto s = make(SetupGeometry::Exact);
    const double fN = -500.0, fS = 150.0; // the south rod pushing: a sign the statics must carry
    double worst = 0.0;
    for (double uy : {-0.1, 0.04, 0.13})
        for (double phi : {-0.28, 0.1, 0.3}) {
            const double uz = 0.003;
            const Eigen::Vector3d Rp(0.0, -kH1 * std::sin(phi), kH1 * std::cos(phi));
            Eigen::Vector3d F = Eigen::Vector3d::Zero(), M = Eigen::Vector3d::Zero();
            for (int r = 0; r < 2; ++r) {
                const Eigen::Vector3d rod =
                    Eigen::Vector3d(0.0, uy, uz) + Rp - Eigen::Vector3d(0, 0, kH1 - kLrod[r]);
                const Eigen::Vector3d Fr = (r == 0 ? fN : fS) * rod.normalized();
                F += Fr;
                M += Rp.cross(Fr);
            }
            Eigen::VectorXd expected(6);
            expected << F.z(), -F.x(), -M.y(), -F.y(), -M.x(), 0.0;
            const Eigen::VectorXd q = rodShare(*s, basicOf(0.0, uy, uz, phi, 0.0), fN, fS);
            const double err =
                (q - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff();
            worst = std::max(worst, err);
            QVERIFY2(err <= 1e-12,
                     qPrintable(QString("uy %1 phix %2: %3").arg(uy).arg(phi).arg(err)));
        }
    qInfo("y-z plane: worst relative difference %.2e", worst);
}

void TestFourActuatorsRods::rodJacobianMatchesFiniteDifferences() {
    const double h = 1e-6;
    double worst = 0.0;
    for (SetupGeometry g : {SetupGeometry::Linear, SetupGeometry::Exact})
        for (double phi : {0.0, 25.0}) {
            const auto s = make(g, phi);
            Eigen::VectorXd d(6);
            d << 0.004, -0.08, 0.21, 0.06, -0.17, 0.05;
            Eigen::MatrixXd J;
            QVERIFY(s->rodJacobian(d, J).ok);
            QCOMPARE(J.rows(), Eigen::Index(2));
            QCOMPARE(J.cols(), Eigen::Index(6));
            for (int k = 0; k < 6; ++k) {
                Eigen::VectorXd dp = d, dm = d;
                dp(k) += h;
                dm(k) -= h;
                Eigen::Vector2d lp, lm;
                QVERIFY(s->rodLengths(dp, lp).ok && s->rodLengths(dm, lm).ok);
                const Eigen::Vector2d fd = (lp - lm) / (2 * h);
                const double err = (fd - J.col(k)).cwiseAbs().maxCoeff();
                worst = std::max(worst, err);
                QVERIFY2(err <= 1e-8, qPrintable(QString("column %1: %2").arg(k).arg(err)));
            }
            // the twist d(5) moves no rod
            QCOMPARE(J.col(5).cwiseAbs().maxCoeff(), 0.0);
        }
    qInfo("rods' Jacobian against central differences: worst %.2e", worst);
}

void TestFourActuatorsRods::refusalsNameTheSetupAndParameter() {
    std::string e;
    FourActuators3dParams p = setupcatalog::four(SetupGeometry::Exact);
    p.LrodN = 0.0;
    QVERIFY(!FourActuators3d::create(p, e));
    QVERIFY2(e == "FourActuators3d: LrodN = 0 must be a positive finite length (an axial-load "
                  "rod's pin-to-pin length)",
             e.c_str());
    p = setupcatalog::four(SetupGeometry::Linear);
    p.LrodS = -1.0;
    QVERIFY(!FourActuators3d::create(p, e));
    QVERIFY2(e.rfind("FourActuators3d: LrodS = -1", 0) == 0, e.c_str());
    p = setupcatalog::four(SetupGeometry::Exact);
    p.h1 = std::nan("");
    QVERIFY(!FourActuators3d::create(p, e));
    QVERIFY2(e == "FourActuators3d: h1 must be finite", e.c_str());

    const auto s = make(SetupGeometry::Exact);
    Eigen::VectorXd q;
    SetupResult r = s->basicForces(Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(5), q);
    QVERIFY(!r.ok);
    QVERIFY2(r.reason.find("FourActuators3d: basicForces wants 6 basic displacements and 4 "
                           "actuator forces or OpenFresco's 6 daq forces") == 0,
             r.reason.c_str());
    r = s->basicForces(Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(6), q);
    QVERIFY2(!r.ok && r.reason.find("got 3 and 6") != std::string::npos, r.reason.c_str());
    Eigen::MatrixXd J;
    r = s->rodJacobian(Eigen::VectorXd::Zero(3), J);
    QVERIFY2(!r.ok && r.reason == "FourActuators3d: 6 basic displacements wanted, got 3",
             r.reason.c_str());
    QCOMPARE(s->loadCellCount(), 2);
}

QTEST_APPLESS_MAIN(TestFourActuatorsRods)
#include "TestFourActuatorsRods.moc"
