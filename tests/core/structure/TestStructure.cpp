// Tests of Structure, SpringElement and FlexibleColumnSpring (core/structure) against hand
// assembly and closed forms: a 2-DOF chain (two lateral springs k1, k2 and a truss k3),
// equal-DOF constraints, Rayleigh / modal damping, rigid and flexible column base springs.
// Units: kN, m, s, t.

#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/LinearElastic.h"
#include "core/structure/FlexibleColumnSpring.h"
#include "core/structure/SpringElement.h"
#include "core/structure/Structure.h"

#include <QtTest>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

using namespace hsmu;

namespace {

constexpr double kM1 = 2.0, kM2 = 3.0;                 // [t]
constexpr double kK1 = 100.0, kK2 = 200.0, kK3 = 50.0; // [kN/m]

std::unique_ptr<HysteresisLaw> elastic(double k) {
    return std::make_unique<LinearElastic>(k);
}

// Two masses, lateral springs k1 (DOF 0) and k2 (DOF 1), truss k3 between them.
std::unique_ptr<Structure> chain() {
    auto s = std::make_unique<Structure>();
    const int d0 = s->addDof("DOF 1", kM1);
    const int d1 = s->addDof("DOF 2", kM2);
    s->addElement(SpringElement::lateral("k1", d0, elastic(kK1)));
    s->addElement(SpringElement::lateral("k2", d1, elastic(kK2)));
    s->addElement(SpringElement::truss("k3", d0, d1, elastic(kK3)));
    return s;
}

// Closed-form eigenpairs of K phi = w^2 M phi for K = [[a, b], [b, d]], M = diag(m1, m2):
// w^2 = roots of m1 m2 x^2 - (a m2 + d m1) x + (a d - b^2); phi = [-b, a - x m1].
struct Mode {
    double omega;
    Eigen::Vector2d phi;
};
Mode closedFormMode(int i, double a, double b, double d, double m1, double m2) {
    const double p = a / m1 + d / m2;
    const double q = (a * d - b * b) / (m1 * m2);
    const double disc = std::sqrt(p * p / 4.0 - q);
    const double x = i == 0 ? p / 2.0 - disc : p / 2.0 + disc;
    return {std::sqrt(x), Eigen::Vector2d(-b, a - x * m1)};
}

// Catches std::invalid_argument from finalize() and returns its message ("" if none thrown).
QString finalizeError(Structure& s) {
    try {
        s.finalize();
    } catch (const std::invalid_argument& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

BoucWenParameters paperSpring() {
    BoucWenParameters p; // paper-like normalized law, uRef 0.02 rad, fRef 20 kN m
    p.k0 = 1.0;
    p.alpha = 0.02;
    p.n = 2.0;
    p.beta = 3.0;
    p.gamma = 1.0;
    p.deltaNu = 0.02;
    p.deltaEta = 0.02;
    p.uRef = 0.02;
    p.fRef = 20.0;
    return p;
}

} // namespace

class TestStructure : public QObject {
    Q_OBJECT
private slots:
    void assemblesMassAndStiffness();
    void restoringForceIsK0TimesU();
    void frequenciesMatchClosedForm();
    void equalDofMergesDofs();
    void equalDofChainResolves();
    void constraintErrors_data();
    void constraintErrors();
    void finalizeErrors();
    void rayleighFromRatio();
    void modalDampingReproducesZeta();
    void modalDampingClampsModes();
    void trialCommitRevert();
    void rotationalRigidSpring();
    void flexibleColumnElasticSeries();
    void flexibleColumnBoucWenCompatibility();
};

void TestStructure::assemblesMassAndStiffness() {
    auto s = chain();
    s->finalize();
    QCOMPARE(s->fullDofCount(), 2);
    QCOMPARE(s->freeDofCount(), 2);
    // Sums of small integers: exact in floating point.
    Eigen::Matrix2d k0;
    k0 << kK1 + kK3, -kK3, -kK3, kK2 + kK3;
    QVERIFY(Eigen::MatrixXd(s->initialStiffness()) == Eigen::MatrixXd(k0));
    QVERIFY(Eigen::MatrixXd(s->mass()) == Eigen::MatrixXd(Eigen::Vector2d(kM1, kM2).asDiagonal()));
    QVERIFY(s->influence() == Eigen::VectorXd(Eigen::Vector2d(kM1, kM2)));
    QVERIFY(Eigen::MatrixXd(s->transform()) == Eigen::MatrixXd::Identity(2, 2));
    QVERIFY(Eigen::MatrixXd(s->damping()).isZero(0.0)); // no damping requested
}

void TestStructure::restoringForceIsK0TimesU() {
    auto s = chain();
    s->finalize();
    const Eigen::Vector2d u(0.1, 0.3);
    QVERIFY(s->setTrial(u).ok);
    const Eigen::VectorXd r = s->restoringForce();
    const Eigen::VectorXd expected = s->initialStiffness() * u;
    // A few products of exact binary fractions: 1e-13 relative covers any reordering.
    QVERIFY2((r - expected).norm() <= 1e-13 * expected.norm(), "R(u) != K0 u for elastic laws");
    // The truss is in tension (u2 > u1): q = u2 - u1, force k3 q pulls DOF 1 right (-P on DOF 1).
    QVERIFY(std::abs(s->element("k3")->deformation() - 0.2) < 1e-15);
    QVERIFY(std::abs(s->element("k3")->force() - kK3 * 0.2) < 1e-12);
    QVERIFY(s->element("nope") == nullptr);
}

void TestStructure::frequenciesMatchClosedForm() {
    auto s = chain();
    s->finalize();
    const Eigen::VectorXd& w = s->frequencies();
    QCOMPARE(w.size(), Eigen::Index(2));
    for (int i = 0; i < 2; ++i) {
        const Mode m = closedFormMode(i, kK1 + kK3, -kK3, kK2 + kK3, kM1, kM2);
        // Eigen's generalized solver on a well-conditioned 2x2: 1e-12 relative.
        QVERIFY2(std::abs(w[i] - m.omega) <= 1e-12 * m.omega,
                 qPrintable(QString("mode %1: %2 vs %3").arg(i + 1).arg(w[i]).arg(m.omega)));
    }
    QVERIFY(w[0] < w[1]);
}

void TestStructure::equalDofMergesDofs() {
    auto s = chain();
    s->addEqualDof(0, 1); // u2 = u1: the truss no longer deforms
    s->finalize();
    QCOMPARE(s->fullDofCount(), 2);
    QCOMPARE(s->freeDofCount(), 1);
    QVERIFY(Eigen::MatrixXd(s->transform()) == Eigen::MatrixXd::Ones(2, 1));
    QCOMPARE(s->mass().coeff(0, 0), kM1 + kM2);
    QCOMPARE(s->influence()[0], kM1 + kM2);
    QCOMPARE(s->initialStiffness().coeff(0, 0), kK1 + kK2); // truss: c^T T = -1 + 1 = 0
    QVERIFY(std::abs(s->frequencies()[0] - std::sqrt((kK1 + kK2) / (kM1 + kM2))) < 1e-12);

    Eigen::VectorXd u(1);
    u << 0.05;
    QVERIFY(s->toFull(u) == Eigen::VectorXd(Eigen::Vector2d(0.05, 0.05)));
    QVERIFY(s->setTrial(u).ok);
    QCOMPARE(s->element("k3")->deformation(), 0.0);
    QVERIFY(std::abs(s->restoringForce()[0] - (kK1 + kK2) * 0.05) < 1e-12);
}

void TestStructure::equalDofChainResolves() {
    // DOF 3 follows DOF 2 which follows DOF 1; DOF 4 is free. Slaves with zero mass are fine.
    Structure s;
    for (double m : {1.0, 0.0, 2.0, 4.0})
        s.addDof("d", m);
    s.addElement(SpringElement::lateral("a", 0, elastic(10.0)));
    s.addElement(SpringElement::lateral("b", 3, elastic(40.0)));
    s.addEqualDof(1, 2);
    s.addEqualDof(0, 1);
    s.finalize();
    QCOMPARE(s.freeDofCount(), 2);
    Eigen::MatrixXd t(4, 2);
    t << 1, 0, 1, 0, 1, 0, 0, 1;
    QVERIFY(Eigen::MatrixXd(s.transform()) == t);
    QVERIFY(Eigen::MatrixXd(s.mass()) == Eigen::MatrixXd(Eigen::Vector2d(3.0, 4.0).asDiagonal()));
    QVERIFY(s.influence() == Eigen::VectorXd(Eigen::Vector2d(3.0, 4.0)));
}

void TestStructure::constraintErrors_data() {
    QTest::addColumn<int>("master1");
    QTest::addColumn<int>("slave1");
    QTest::addColumn<int>("master2");
    QTest::addColumn<int>("slave2");
    QTest::addColumn<QString>("expected");
    // -1 in the second pair: no second constraint.
    QTest::newRow("slave index out of range") << 0 << 5 << -1 << -1 << "DOF index 5";
    QTest::newRow("negative master") << -1 << 1 << -1 << -1 << "DOF index -1";
    QTest::newRow("master equals slave") << 1 << 1 << -1 << -1 << "both DOF 1";
    QTest::newRow("slave constrained twice") << 0 << 1 << 2 << 1 << "constrained twice";
    QTest::newRow("cycle") << 0 << 1 << 1 << 0 << "cycle";
}

void TestStructure::constraintErrors() {
    QFETCH(int, master1);
    QFETCH(int, slave1);
    QFETCH(int, master2);
    QFETCH(int, slave2);
    QFETCH(QString, expected);
    Structure s;
    for (int i = 0; i < 3; ++i)
        s.addDof("d", 1.0);
    s.addEqualDof(master1, slave1);
    if (master2 >= 0)
        s.addEqualDof(master2, slave2);
    const QString msg = finalizeError(s);
    QVERIFY2(!msg.isEmpty(), "finalize() accepted an invalid constraint");
    QVERIFY2(msg.contains(expected), qPrintable(msg));
}

void TestStructure::finalizeErrors() {
    Structure empty;
    QVERIFY2(finalizeError(empty).contains("no DOFs"), qPrintable(finalizeError(empty)));

    Structure negative;
    negative.addDof("heavy", -1.0);
    const QString m1 = finalizeError(negative);
    QVERIFY2(m1.contains("'heavy'") && m1.contains("mass"), qPrintable(m1));

    Structure massless; // a free DOF without mass cannot be integrated explicitly
    massless.addDof("a", 1.0);
    massless.addDof("b", 0.0);
    const QString m2 = finalizeError(massless);
    QVERIFY2(m2.contains("free DOF 1") && m2.contains("no mass"), qPrintable(m2));

    Structure badElement;
    badElement.addDof("a", 1.0);
    badElement.addElement(SpringElement::lateral("k9", 4, elastic(1.0)));
    const QString m3 = finalizeError(badElement);
    QVERIFY2(m3.contains("element 'k9'") && m3.contains("DOF index 4"), qPrintable(m3));
}

void TestStructure::rayleighFromRatio() {
    const double zeta = 0.03, w1 = 5.0, w2 = 20.0;
    const RayleighDamping d = RayleighDamping::fromRatio(zeta, w1, w2);
    for (double w : {w1, w2}) {
        const double z = d.a0 / (2.0 * w) + d.a1 * w / 2.0;
        QVERIFY2(std::abs(z - zeta) < 1e-15, "zeta not reproduced at w1, w2"); // a few flops
    }
    // Between the anchors Rayleigh damping is below zeta (a0/(2w) + a1 w/2 is convex).
    QVERIFY(d.a0 / (2.0 * 10.0) + d.a1 * 10.0 / 2.0 < zeta);
    const RayleighDamping same = RayleighDamping::fromRatio(zeta, w1, w1);
    QVERIFY(std::abs(same.a0 / (2.0 * w1) + same.a1 * w1 / 2.0 - zeta) < 1e-15);
}

void TestStructure::modalDampingReproducesZeta() {
    const double zeta = 0.02;
    auto s = chain();
    s->setModalDamping(zeta, 1, 2);
    s->finalize();
    const RayleighDamping& r = s->rayleigh();
    QVERIFY((s->damping() - (r.a0 * s->mass() + r.a1 * s->initialStiffness())).norm() <=
            1e-14 * s->damping().norm());
    for (int i = 0; i < 2; ++i) {
        const Mode m = closedFormMode(i, kK1 + kK3, -kK3, kK2 + kK3, kM1, kM2);
        const Eigen::VectorXd phi = m.phi;
        const double z = phi.dot(s->damping() * phi) / (2.0 * m.omega * phi.dot(s->mass() * phi));
        // Rayleigh C is diagonal in the modal basis; roundoff in w and phi: 1e-12 relative.
        QVERIFY2(std::abs(z - zeta) <= 1e-12 * zeta,
                 qPrintable(QString("mode %1: zeta %2").arg(i + 1).arg(z, 0, 'g', 17)));
    }
}

void TestStructure::modalDampingClampsModes() {
    Structure s; // one DOF: mode 2 is clamped to mode 1, so a0 = zeta w, a1 = zeta / w
    s.addDof("d", 2.0);
    s.addElement(SpringElement::lateral("k", 0, elastic(800.0)));
    s.setModalDamping(0.05, 1, 2);
    s.finalize();
    const double w = 20.0, c = 2.0 * 0.05 * w * 2.0;
    QVERIFY(std::abs(s.damping().coeff(0, 0) - c) < 1e-12 * c);
}

void TestStructure::trialCommitRevert() {
    auto s = chain();
    s->finalize();
    QVERIFY(s->setTrial(Eigen::Vector2d(0.1, 0.0)).ok);
    QVERIFY(s->commit().ok);
    QVERIFY(s->setTrial(Eigen::Vector2d(0.4, 0.2)).ok);
    s->revert();
    // After revert the trial state is the committed one (u = (0.1, 0)).
    const Eigen::VectorXd r = s->restoringForce();
    QVERIFY(std::abs(r[0] - (kK1 + kK3) * 0.1) < 1e-12);
    QVERIFY(std::abs(r[1] + kK3 * 0.1) < 1e-12);
}

void TestStructure::rotationalRigidSpring() {
    const double kTheta = 1200.0, height = 3.0; // [kN m/rad], [m]
    Structure s;
    s.addDof("top", 4.0);
    s.addElement(SpringElement::rotationalRigid("base", 0, height, elastic(kTheta)));
    s.finalize();
    QVERIFY(std::abs(s.initialStiffness().coeff(0, 0) - kTheta / (height * height)) < 1e-12);
    Eigen::VectorXd u(1);
    u << 0.03; // theta = 0.01 rad, M = 12 kN m, V = M / L = 4 kN
    QVERIFY(s.setTrial(u).ok);
    const Element& e = *s.element("base");
    QVERIFY(std::abs(e.deformation() - 0.01) < 1e-15);
    QVERIFY(std::abs(e.force() - 12.0) < 1e-12);
    QVERIFY(std::abs(s.restoringForce()[0] - 4.0) < 1e-12);
    QCOMPARE(QString::fromStdString(e.typeName()), QString("rotationalBaseSpring"));
}

void TestStructure::flexibleColumnElasticSeries() {
    const double kTheta = 1200.0, height = 3.0, ei = 2500.0;
    Structure s;
    s.addDof("top", 4.0);
    auto spring = std::make_unique<FlexibleColumnSpring>("base", 0, height, ei, elastic(kTheta));
    QVERIFY(std::abs(spring->columnFlexibility() - height / (3.0 * ei)) < 1e-18);
    s.addElement(std::move(spring));
    s.finalize();
    const double kSeries = 1.0 / (height * height / kTheta + height * height * height / (3.0 * ei));
    // Only a few divisions: 1e-13 relative.
    QVERIFY2(std::abs(s.initialStiffness().coeff(0, 0) - kSeries) <= 1e-13 * kSeries,
             qPrintable(QString::number(s.initialStiffness().coeff(0, 0), 'g', 17)));
    for (double u0 : {0.02, -0.05, 0.11}) {
        Eigen::VectorXd u(1);
        u << u0;
        QVERIFY(s.setTrial(u).ok);
        // The compatibility solve stops at |g| <= 1e-13 |q|: the secant force is exact to
        // ~1e-12 relative.
        QVERIFY2(std::abs(s.restoringForce()[0] - kSeries * u0) <= 1e-12 * std::abs(kSeries * u0),
                 qPrintable(QString::number(s.restoringForce()[0], 'g', 17)));
        const Element& e = *s.element("base");
        QVERIFY(std::abs(e.force() - kTheta * e.deformation()) <= 1e-12 * std::abs(e.force()));
        QVERIFY(s.commit().ok);
    }
}

void TestStructure::flexibleColumnBoucWenCompatibility() {
    // Physical spring stiffness k0 fRef / uRef = 1000 kN m/rad; column L/(3EI) = 1e-3 rad/(kN m)
    // gives the same flexibility, so the column takes a good share of the chord rotation.
    const double height = 3.0, ei = 1000.0;
    Structure s;
    s.addDof("top", 4.0);
    s.addElement(std::make_unique<FlexibleColumnSpring>("base", 0, height, ei,
                                                        std::make_unique<BoucWen>(paperSpring())));
    s.finalize();
    const double flex = height / (3.0 * ei);
    // Cyclic chord rotation of growing amplitude up to 0.08 rad (well past yield), 3 cycles.
    const int perCycle = 200;
    double maxSpring = 0.0;
    for (int i = 1; i <= 3 * perCycle; ++i) {
        const double q =
            0.08 * (i / (3.0 * perCycle)) * std::sin(2.0 * std::numbers::pi * i / perCycle);
        Eigen::VectorXd u(1);
        u << q * height;
        const ElementStatus st = s.setTrial(u);
        QVERIFY2(st.ok, st.message.c_str());
        const Element& e = *s.element("base");
        const double theta = e.deformation(), moment = e.force();
        // Compatibility solved to 1e-13 max(1, |q|); 1e-10 leaves room for the law's rounding.
        QVERIFY2(std::abs(q - (theta + moment * flex)) <= 1e-10,
                 qPrintable(
                     QString("step %1: q %2 theta %3 M %4").arg(i).arg(q).arg(theta).arg(moment)));
        QVERIFY(std::abs(s.restoringForce()[0] - moment / height) <=
                1e-12 * (1.0 + std::abs(moment)));
        maxSpring = std::max(maxSpring, std::abs(theta));
        QVERIFY(s.commit().ok);
    }
    QVERIFY2(maxSpring > 0.02, "the history never yielded the spring: the test is too weak");
}

QTEST_APPLESS_MAIN(TestStructure)
#include "TestStructure.moc"
