// Tests of the experimental setups (core/experimental/setup; docs/setups.md):
// - every setup of SetupCatalog.h at basic displacements up to 0.15 m and 0.35 rad: the
//   Jacobian against a central finite difference (h = 1e-6; |J - J_fd| <= 1e-8 max(1, |J|)),
//   the round trip d -> strokes -> d (|error| <= 1e-12 m or rad), virtual work
//   (|q . dd - f . ds| <= 1e-9 |f| |ds|, ds from a central difference of the strokes, not from
//   the Jacobian), and the small-displacement limit of the exact geometry (|s(eps d)/eps -
//   J(0) d| <= 1e-5 |d| at eps = 1e-6);
// - closed forms derived by hand (docs/setups.md equations) for each family: strokes in the
//   linear formulation, pure translations and known rigid rotations in the exact one, the
//   moment of an inclined actuator about the control point;
// - singular or bad geometry refused with an error that names the setup and the parameter.

#include "SetupCatalog.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace hsmu;

namespace {

std::vector<Eigen::VectorXd> samples(int n) {
    // deterministic, up to 0.15 m and 0.35 rad, signs mixed; the third entry of a planar
    // setup is the rotation
    const double table[][3] = {{0.0, 0.0, 0.0},    {0.05, 0.0, 0.0},   {0.0, 0.03, 0.0},
                               {0.0, 0.0, 0.2},    {0.1, -0.02, 0.25}, {-0.15, 0.04, -0.35},
                               {0.08, 0.06, -0.3}, {-0.03, -0.05, 0.1}};
    std::vector<Eigen::VectorXd> out;
    for (const auto& row : table) {
        Eigen::VectorXd d(n);
        for (int k = 0; k < n; ++k)
            d(k) = row[k % 3] * (1.0 + 0.1 * (k / 3));
        out.push_back(d);
    }
    return out;
}

Eigen::VectorXd strokesOf(const ExperimentalSetup& s, const Eigen::VectorXd& d) {
    Eigen::VectorXd out;
    const SetupResult r = s.strokes(d, out);
    if (!r.ok)
        qWarning("%s", r.reason.c_str());
    return out;
}

Eigen::MatrixXd finiteDifferenceJacobian(const ExperimentalSetup& s, const Eigen::VectorXd& d,
                                         double h) {
    Eigen::MatrixXd J(s.actuatorCount(), s.basicSize());
    for (int k = 0; k < s.basicSize(); ++k) {
        Eigen::VectorXd dp = d, dm = d;
        dp(k) += h;
        dm(k) -= h;
        J.col(k) = (strokesOf(s, dp) - strokesOf(s, dm)) / (2.0 * h);
    }
    return J;
}

} // namespace

class TestExperimentalSetups : public QObject {
    Q_OBJECT
private slots:
    void everySetup_data();
    void everySetup();
    void twoActuatorsClosedForms();
    void threeActuatorsClosedForms();
    void jointOffsetClosedForms();
    void fourActuatorsClosedForms();
    void noTransformationPicksAndScatters();
    void aggregatorIsBlockDiagonal();
    void singularGeometryIsRefused();
    void runtimeFaultsNameTheSetup();
};

void TestExperimentalSetups::everySetup_data() {
    QTest::addColumn<int>("index");
    const auto cases = setupcatalog::all();
    for (int i = 0; i < static_cast<int>(cases.size()); ++i)
        QTest::newRow(cases[i].label.c_str()) << i;
}

void TestExperimentalSetups::everySetup() {
    QFETCH(int, index);
    std::string error;
    const auto setup = setupcatalog::all()[index].make(error);
    QVERIFY2(setup, error.c_str());
    const int n = setup->basicSize(), m = setup->actuatorCount();
    for (const Eigen::VectorXd& d : samples(n)) {
        // Jacobian against a central difference
        Eigen::MatrixXd J;
        QVERIFY(setup->jacobian(d, J).ok);
        QCOMPARE(J.rows(), m);
        QCOMPARE(J.cols(), n);
        const Eigen::MatrixXd Jfd = finiteDifferenceJacobian(*setup, d, 1e-6);
        const double scale = std::max(1.0, J.cwiseAbs().maxCoeff());
        QVERIFY2((J - Jfd).cwiseAbs().maxCoeff() <= 1e-8 * scale,
                 qPrintable(QString("J - J_fd = %1").arg((J - Jfd).cwiseAbs().maxCoeff())));

        // round trip d -> s -> d (the basic DOFs no actuator fixes are given: the trial's)
        Eigen::VectorXd s, back;
        QVERIFY(setup->strokes(d, s).ok);
        const SetupResult r = setup->basicDisplacements(s, d, back);
        QVERIFY2(r.ok, r.reason.c_str());
        QVERIFY2((back - d).cwiseAbs().maxCoeff() <= 1e-12,
                 qPrintable(QString("round trip error %1").arg((back - d).cwiseAbs().maxCoeff())));
        if (m == n) { // every DOF fixed by the actuators: no given value needed, from rest too
            const SetupResult r0 = setup->basicDisplacements(s, Eigen::VectorXd::Zero(n), back);
            QVERIFY2(r0.ok, r0.reason.c_str());
            QVERIFY((back - d).cwiseAbs().maxCoeff() <= 1e-12);
        }

        // virtual work with ds from the strokes themselves (central difference)
        Eigen::VectorXd f(m), dd(n);
        for (int i = 0; i < m; ++i)
            f(i) = 1e5 * (i + 1) * (i % 2 ? -1.0 : 1.0); // [N]
        for (int k = 0; k < n; ++k)
            dd(k) = 0.3 + 0.2 * k * (k % 2 ? -1.0 : 1.0);
        Eigen::VectorXd q;
        QVERIFY(setup->basicForces(d, f, q).ok);
        const double h = 1e-6;
        const Eigen::VectorXd ds =
            (strokesOf(*setup, d + h * dd) - strokesOf(*setup, d - h * dd)) / (2.0 * h);
        const double work = q.dot(dd), actuatorWork = f.dot(ds);
        QVERIFY2(std::abs(work - actuatorWork) <= 1e-9 * f.norm() * std::max(1.0, ds.norm()),
                 qPrintable(QString("q.dd = %1, f.ds = %2")
                                .arg(work, 0, 'g', 17)
                                .arg(actuatorWork, 0, 'g', 17)));
    }
    // small-displacement limit: s(eps d) / eps -> J(0) d
    Eigen::MatrixXd J0;
    QVERIFY(setup->jacobian(Eigen::VectorXd::Zero(n), J0).ok);
    for (const Eigen::VectorXd& d : samples(n)) {
        const double eps = 1e-6;
        const Eigen::VectorXd lin = strokesOf(*setup, eps * d) / eps;
        QVERIFY((lin - J0 * d).cwiseAbs().maxCoeff() <= 1e-5 * std::max(1e-3, d.norm()));
    }
}

void TestExperimentalSetups::twoActuatorsClosedForms() {
    const double La1 = 1.5, La2 = 1.2, L = 0.6;
    std::string e;
    for (bool right : {false, true}) {
        const double sg = right ? -1.0 : 1.0;
        // linear: s1 = +-u, s2 = +-(u - L theta)
        auto lin = makeTwoActuators2d(setupcatalog::two(SetupGeometry::Linear, right), e);
        QVERIFY(lin);
        const Eigen::Vector3d d(0.04, 0.01, 0.07);
        const Eigen::VectorXd s = strokesOf(*lin, d);
        QCOMPARE(s(0), sg * 0.04);
        QVERIFY(std::abs(s(1) - sg * (0.04 - L * 0.07)) <= 1e-15);
        // exact, translation with v: s1 = sqrt((La1 +- u)^2 + v^2) - La1
        auto ex = makeTwoActuators2d(setupcatalog::two(SetupGeometry::Exact, right), e);
        QVERIFY(ex);
        const Eigen::VectorXd st = strokesOf(*ex, Eigen::Vector3d(0.1, 0.05, 0.0));
        QVERIFY(std::abs(st(0) - (std::hypot(La1 + sg * 0.1, 0.05) - La1)) <= 1e-15);
        QVERIFY(std::abs(st(1) - (std::hypot(La2 + sg * 0.1, 0.05) - La2)) <= 1e-15);
        // exact, rotation theta about the control point: the arm tip at (-L sin, L cos)
        const double th = 0.25;
        const Eigen::VectorXd sr = strokesOf(*ex, Eigen::Vector3d(0.0, 0.0, th));
        QVERIFY(std::abs(sr(0)) <= 1e-15);
        const double rx = -L * std::sin(th) + sg * La2, ry = L * std::cos(th) - L;
        QVERIFY(std::abs(sr(1) - (std::hypot(rx, ry) - La2)) <= 1e-15);
        // statics: the moment of actuator 2's force about the control point,
        // q_theta = f2 (P x n), P the arm tip, n the actuator's unit vector base -> tip
        const Eigen::Vector2d f(2.0e5, -3.0e5);
        Eigen::VectorXd q;
        QVERIFY(ex->basicForces(Eigen::Vector3d(0.0, 0.0, th), f, q).ok);
        const double len = std::hypot(rx, ry);
        const double nx = rx / len, ny = ry / len;
        const double px = -L * std::sin(th), py = L * std::cos(th);
        QVERIFY(std::abs(q(2) - f(1) * (px * ny - py * nx)) <= 1e-9 * std::abs(q(2)));
        QVERIFY(std::abs(q(0) - (sg * f(0) + f(1) * nx)) <= 1e-9);
        QVERIFY(std::abs(q(1) - f(1) * ny) <= 1e-9);
    }
    // a quarter turn with La2 = L brings the arm tip to a point at La2 from its base: s2 = 0
    TwoActuators2dParams p = setupcatalog::two(SetupGeometry::Exact, false);
    p.La2 = p.L;
    auto quarter = makeTwoActuators2d(p, e);
    QVERIFY(quarter);
    QVERIFY(std::abs(strokesOf(*quarter, Eigen::Vector3d(0, 0, std::numbers::pi / 2))(1)) <= 1e-15);
}

void TestExperimentalSetups::threeActuatorsClosedForms() {
    const double La1 = 1.6, La2 = 1.1, La3 = 1.3, L1 = 0.7, L2 = 0.5;
    std::string e;
    for (bool right : {false, true}) {
        const double sg = right ? -1.0 : 1.0;
        auto lin = makeThreeActuators2d(setupcatalog::three(SetupGeometry::Linear, right), e);
        QVERIFY(lin);
        const Eigen::VectorXd s = strokesOf(*lin, Eigen::Vector3d(0.04, 0.01, 0.07));
        QCOMPARE(s(0), sg * 0.04);
        QVERIFY(std::abs(s(1) - (0.01 - L1 * 0.07)) <= 1e-15);
        QVERIFY(std::abs(s(2) - (0.01 + L2 * 0.07)) <= 1e-15);
        auto ex = makeThreeActuators2d(setupcatalog::three(SetupGeometry::Exact, right), e);
        QVERIFY(ex);
        // pure v: the horizontal actuator swings, the vertical ones follow v exactly
        const Eigen::VectorXd sv = strokesOf(*ex, Eigen::Vector3d(0.0, 0.08, 0.0));
        QVERIFY(std::abs(sv(0) - (std::hypot(La1, 0.08) - La1)) <= 1e-15);
        QVERIFY(std::abs(sv(1) - 0.08) <= 1e-15);
        QVERIFY(std::abs(sv(2) - 0.08) <= 1e-15);
        // quarter turn: the beam ends (-L1, 0), (L2, 0) go to (0, -L1), (0, L2)
        const Eigen::VectorXd sq = strokesOf(*ex, Eigen::Vector3d(0, 0, std::numbers::pi / 2));
        QVERIFY(std::abs(sq(1) - (std::hypot(L1, La2 - L1) - La2)) <= 1e-14);
        QVERIFY(std::abs(sq(2) - (std::hypot(L2, La3 + L2) - La3)) <= 1e-14);
        const double hx = right ? L2 : -L1; // horizontal actuator's attachment
        QVERIFY(std::abs(sq(0) - (std::hypot(std::abs(hx) + La1, hx) - La1)) <= 1e-14);
    }
}

void TestExperimentalSetups::jointOffsetClosedForms() {
    const auto p = setupcatalog::jntOff(SetupGeometry::Exact, false);
    std::string e;
    auto lin = makeThreeActuatorsJntOff2d(setupcatalog::jntOff(SetupGeometry::Linear, false), e);
    QVERIFY(lin);
    // linear: the vertical offsets L5, L6 do not enter vertical actuators' strokes
    const Eigen::VectorXd s = strokesOf(*lin, Eigen::Vector3d(0.04, 0.01, 0.07));
    QCOMPARE(s(0), 0.04);
    QVERIFY(std::abs(s(1) - (0.01 - p.L2 * 0.07)) <= 1e-15);
    QVERIFY(std::abs(s(2) - (0.01 + p.L3 * 0.07)) <= 1e-15);
    // exact rotation: attachment (-L2, -L5) turns to (-L2 c + L5 s, -L2 s - L5 c)
    auto ex = makeThreeActuatorsJntOff2d(p, e);
    QVERIFY(ex);
    const double th = 0.3, c = std::cos(th), sn = std::sin(th);
    const Eigen::VectorXd sr = strokesOf(*ex, Eigen::Vector3d(0, 0, th));
    const double s2 = std::hypot(p.L2 * (1 - c) + p.L5 * sn, p.La2 + p.L5 - p.L2 * sn - p.L5 * c);
    QVERIFY(std::abs(sr(1) - (s2 - p.La2)) <= 1e-15);
    const double a = p.L1 + p.L2; // horizontal actuator at (-(L1 + L2), 0)
    QVERIFY(std::abs(sr(0) - (std::hypot(p.La1 + a * (1 - c), a * sn) - p.La1)) <= 1e-15);
}

void TestExperimentalSetups::fourActuatorsClosedForms() {
    const auto p = setupcatalog::four(SetupGeometry::Exact);
    std::string e;
    auto ex = FourActuators3d::create(p, e);
    QVERIFY2(ex, e.c_str());
    // OpenFresco's mapping: ux = -d(1), uy = -d(3), phix = -d(4), phiy = -d(2)
    Eigen::VectorXd d = Eigen::VectorXd::Zero(6);
    d(1) = -0.05; // ux = 0.05: the x actuators follow it, the y actuators swing
    Eigen::VectorXd s = strokesOf(*ex, d);
    QVERIFY(std::abs(s(0) - 0.05) <= 1e-15);
    QVERIFY(std::abs(s(2) - 0.05) <= 1e-15);
    QVERIFY(std::abs(s(1) - (std::hypot(0.05, p.L2) - p.L2)) <= 1e-15);
    QVERIFY(std::abs(s(3) - (std::hypot(0.05, p.L4) - p.L4)) <= 1e-15);
    // phiy = 0.3 about the control point: R a = (ax c + az s, ay, -ax s + az c)
    d.setZero();
    const double phi = 0.3, c = std::cos(phi), sn = std::sin(phi);
    d(2) = -phi;
    s = strokesOf(*ex, d);
    const double s1 = std::hypot(p.a1 * (1 - c) + p.L1, p.a1 * sn) - p.L1;
    const double s3 =
        std::hypot(-p.a3 * c + p.h * sn + p.a3 + p.L3, p.a3 * sn + p.h * c - p.h) - p.L3;
    QVERIFY(std::abs(s(0) - s1) <= 1e-15);
    QVERIFY(std::abs(s(2) - s3) <= 1e-15);
    // linear: s = (ux, uy, ux + h phiy, uy - h phix)
    auto lin = FourActuators3d::create(setupcatalog::four(SetupGeometry::Linear), e);
    QVERIFY(lin);
    d << 0.0, -0.01, -0.02, -0.03, -0.04, 0.0; // ux 0.01, uy 0.03, phix 0.04, phiy 0.02
    s = strokesOf(*lin, d);
    QVERIFY(std::abs(s(0) - 0.01) <= 1e-15);
    QVERIFY(std::abs(s(1) - 0.03) <= 1e-15);
    QVERIFY(std::abs(s(2) - (0.01 + p.h * 0.02)) <= 1e-15);
    QVERIFY(std::abs(s(3) - (0.03 - p.h * 0.04)) <= 1e-15);
    // no actuator on d(0) (axial) and d(5) (twist): zero force there
    Eigen::VectorXd q;
    QVERIFY(ex->basicForces(d, Eigen::Vector4d(1e5, -2e5, 3e5, 4e5), q).ok);
    QCOMPARE(q(0), 0.0);
    QCOMPARE(q(5), 0.0);
}

void TestExperimentalSetups::noTransformationPicksAndScatters() {
    std::string e;
    auto nt = NoTransformation::create({3, 1}, 4, e);
    QVERIFY(nt);
    const Eigen::Vector4d d(0.1, 0.2, 0.3, 0.4);
    const Eigen::VectorXd s = strokesOf(*nt, d);
    QCOMPARE(s.size(), Eigen::Index(2));
    QCOMPARE(s(0), 0.3);
    QCOMPARE(s(1), 0.1);
    Eigen::VectorXd q;
    QVERIFY(nt->basicForces(d, Eigen::Vector2d(5.0, 7.0), q).ok);
    QCOMPARE(q(0), 7.0);
    QCOMPARE(q(1), 0.0);
    QCOMPARE(q(2), 5.0);
    QCOMPARE(q(3), 0.0);
    auto one = OneActuator::create(2, 3, e);
    QVERIFY(one);
    QCOMPARE(one->typeName(), std::string("OneActuator"));
    QCOMPARE(strokesOf(*one, Eigen::Vector3d(1, 2, 3))(0), 2.0);
}

void TestExperimentalSetups::aggregatorIsBlockDiagonal() {
    std::string e;
    std::vector<std::unique_ptr<ExperimentalSetup>> parts;
    parts.push_back(OneActuator::create(1, 1, e));
    parts.push_back(makeTwoActuators2d(setupcatalog::two(SetupGeometry::Exact, false), e));
    auto agg = Aggregator::create(std::move(parts), e);
    QVERIFY(agg);
    QCOMPARE(agg->basicSize(), 4);
    QCOMPARE(agg->actuatorCount(), 3);
    Eigen::VectorXd d(4);
    d << 0.02, 0.05, 0.01, 0.2;
    const Eigen::VectorXd s = strokesOf(*agg, d);
    QCOMPARE(s(0), 0.02);
    const Eigen::VectorXd s2 = strokesOf(agg->part(1), d.tail(3));
    QCOMPARE(s.tail(2), s2);
    Eigen::MatrixXd J;
    QVERIFY(agg->jacobian(d, J).ok);
    QCOMPARE(J.block(0, 1, 1, 3).cwiseAbs().maxCoeff(), 0.0);
    QCOMPARE(J.block(1, 0, 2, 1).cwiseAbs().maxCoeff(), 0.0);
}

void TestExperimentalSetups::singularGeometryIsRefused() {
    std::string e;
    auto contains = [&](const char* a, const char* b) {
        return QString::fromStdString(e).contains(a) && QString::fromStdString(e).contains(b);
    };
    TwoActuators2dParams two = setupcatalog::two(SetupGeometry::Exact, false);
    two.L = 0.0; // both actuators at the control point: parallel and coincident
    QVERIFY(!makeTwoActuators2d(two, e));
    QVERIFY2(contains("TwoActuators2d", "L = 0"), e.c_str());
    two = setupcatalog::two(SetupGeometry::Linear, false);
    two.La2 = 0.0;
    QVERIFY(!makeTwoActuators2d(two, e));
    QVERIFY2(contains("TwoActuators2d", "La2"), e.c_str());
    ThreeActuators2dParams three = setupcatalog::three(SetupGeometry::Exact, false);
    three.L2 = -three.L1; // vertical actuators on one line
    QVERIFY(!makeThreeActuators2d(three, e));
    QVERIFY2(contains("ThreeActuators2d", "L1 + L2"), e.c_str());
    QVERIFY(!makeInvertedVBrace2d(three, e));
    QVERIFY2(contains("InvertedVBrace2d", "L1 + L2"), e.c_str());
    ThreeActuatorsJntOff2dParams jo = setupcatalog::jntOff(SetupGeometry::Linear, true);
    jo.L3 = -jo.L2;
    QVERIFY(!makeThreeActuatorsJntOff2d(jo, e));
    QVERIFY2(contains("ThreeActuatorsJntOff2d", "L2 + L3"), e.c_str());
    jo = setupcatalog::jntOff(SetupGeometry::Linear, true);
    jo.La3 = std::numeric_limits<double>::quiet_NaN();
    QVERIFY(!makeInvertedVBraceJntOff2d(jo, e));
    QVERIFY2(contains("InvertedVBraceJntOff2d", "La3"), e.c_str());
    FourActuators3dParams four = setupcatalog::four(SetupGeometry::Exact);
    four.h = 0.0;
    QVERIFY(!FourActuators3d::create(four, e));
    QVERIFY2(contains("FourActuators3d", "h = 0"), e.c_str());
    four = setupcatalog::four(SetupGeometry::Exact);
    four.L3 = -1.0;
    QVERIFY(!FourActuators3d::create(four, e));
    QVERIFY2(contains("FourActuators3d", "L3"), e.c_str());
    QVERIFY(!NoTransformation::create({2, 2}, 3, e));
    QVERIFY2(contains("NoTransformation", "dir 2"), e.c_str());
    QVERIFY(!OneActuator::create(4, 3, e));
    QVERIFY2(contains("OneActuator", "dir 4"), e.c_str());
    QVERIFY(!Aggregator::create({}, e));
    QVERIFY2(contains("Aggregator", "-setup"), e.c_str());
}

void TestExperimentalSetups::runtimeFaultsNameTheSetup() {
    std::string e;
    auto two = makeTwoActuators2d(setupcatalog::two(SetupGeometry::Exact, false), e);
    QVERIFY(two);
    Eigen::VectorXd s, d;
    // the control point driven onto actuator 1's base: zero length
    SetupResult r = two->strokes(Eigen::Vector3d(-1.5, 0.0, 0.0), s);
    QVERIFY(!r.ok);
    QVERIFY2(QString::fromStdString(r.reason).contains("TwoActuators2d: actuator 1"),
             r.reason.c_str());
    // a stroke beyond reach: actuator 2 cannot be longer than |base - centre| + L
    r = two->basicDisplacements(Eigen::Vector2d(0.0, 5.0), Eigen::Vector3d::Zero(), d);
    QVERIFY(!r.ok);
    QVERIFY2(QString::fromStdString(r.reason).startsWith("TwoActuators2d: "), r.reason.c_str());
    // wrong sizes
    r = two->strokes(Eigen::Vector2d(0.0, 0.0), s);
    QVERIFY(!r.ok);
    QVERIFY(QString::fromStdString(r.reason).contains("3 basic displacements"));
}

QTEST_APPLESS_MAIN(TestExperimentalSetups)
#include "TestExperimentalSetups.moc"
