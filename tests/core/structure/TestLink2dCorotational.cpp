// Tests of the link2d element's corotational geometry (core/structure/Link2dKinematics.h,
// eq. L3-L5; docs/setups.md "Multi-DOF elements"): closed forms of the basic deformations
// (rigid-body motions of any size, a pure stretch, a known large rotation), the tangent
// against a central finite difference of the nodal forces, K0 at rest with held forces, and a
// two-node cantilever under a large tip load against its exact equilibrium (closed form,
// everywhere) and against the real OpenSees 3.8 (a corotational elasticBeamColumn, where the
// kit of ../shared/tools/opensees is). Units: kN, m, rad.

#include "core/hysteresis/LinearElastic.h"
#include "core/structure/Link2dElement.h"

#include <Eigen/LU>

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

#include "../../comms/OpenSeesRunner.h"

using namespace hsmu;

namespace {

constexpr double kPi = std::numbers::pi;

Link2dGeometry corotational(double length, double angleDeg,
                            std::array<int, 6> dofs = {0, 1, 2, 3, 4, 5})
{
    return {dofs, length, angleDeg, Link2dTransformation::Corotational};
}

// u_e of a rigid-body motion: translation (tx, ty) and rotation th about node i.
Link2dVector6 rigid(double length, double angleDeg, double tx, double ty, double th)
{
    const double phi = angleDeg * kPi / 180.0;
    const Eigen::Vector2d x0(length * std::cos(phi), length * std::sin(phi));
    const Eigen::Vector2d xj(std::cos(th) * x0.x() - std::sin(th) * x0.y(),
                             std::sin(th) * x0.x() + std::cos(th) * x0.y());
    Link2dVector6 ue;
    ue << tx, ty, th, tx + xj.x() - x0.x(), ty + xj.y() - x0.y(), th;
    return ue;
}

std::unique_ptr<HysteresisLaw> elastic(double k)
{
    return std::make_unique<LinearElastic>(k);
}

Eigen::VectorXd nodalForces(const Element& e, const Eigen::VectorXd& u)
{
    Eigen::VectorXd r = Eigen::VectorXd::Zero(u.size());
    e.addNodalForces(r);
    return r;
}

// The cantilever: base (node i) fixed, node j's translations free (DOFs 0 x, 1 y), its
// rotation fixed; a column (90 deg) of length kL, axial spring kA on the chord elongation,
// shear spring kS on L beta (the chord's rotation: a base rotational spring kS L^2), a tip
// load (kH, kV) at node j.
constexpr double kL = 2.0, kA = 1e4, kS = 100.0, kH = 150.0, kV = -50.0;

Link2dElement cantilever()
{
    std::array<Link2dBasicDof, 3> dofs;
    dofs[0].law = elastic(kA);
    dofs[1].law = elastic(kS);
    return Link2dElement("C", corotational(kL, 90.0, {-1, -1, -1, 0, 1, -1}), std::move(dofs));
}

// The tip displacement under load fraction lambda of (kH, kV), by Newton with the element's
// own forces and tangent, in 20 load steps; false when it does not converge.
bool solveCantilever(Link2dElement& e, Eigen::Vector2d& u)
{
    u.setZero();
    for (int step = 1; step <= 20; ++step) {
        const Eigen::Vector2d p = (step / 20.0) * Eigen::Vector2d(kH, kV);
        int it = 0;
        for (;; ++it) {
            if (it == 50 || !e.setTrial(u).ok)
                return false;
            const Eigen::Vector2d r = p - nodalForces(e, u);
            if (r.norm() <= 1e-10 * p.norm())
                break;
            const Eigen::Matrix2d k = e.tangentStiffness().block<2, 2>(3, 3);
            u += k.inverse() * r; // 2 x 2
        }
        if (!e.commit().ok)
            return false;
    }
    return true;
}

// The same equilibrium from the potential kA/2 (Ln - L)^2 + kS/2 (L a)^2 - kH x - kV y of a
// chord turned by a from vertical (x = -Ln sin a, y = Ln cos a): Ln from the axial balance,
// then the moment balance kS L^2 a = Ln (-kH cos a - kV sin a) by bisection on a in
// [-pi/2, 0] (the sway to +x turns the chord clockwise).
Eigen::Vector2d closedFormCantilever()
{
    auto lengthAt = [](double a) { return kL + (-kH * std::sin(a) + kV * std::cos(a)) / kA; };
    auto moment = [&](double a) {
        return kS * kL * kL * a - lengthAt(a) * (-kH * std::cos(a) - kV * std::sin(a));
    };
    double lo = -kPi / 2, hi = 0.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (moment(mid) > 0.0 ? hi : lo) = mid;
    }
    const double a = 0.5 * (lo + hi), ln = lengthAt(a);
    return {-ln * std::sin(a), ln * std::cos(a) - kL};
}

} // namespace

class TestLink2dCorotational : public QObject {
    Q_OBJECT

private slots:
    // Eq. L3: a rigid-body motion of any size (rotations to 100 rad) gives d = 0 to 1e-12.
    void rigidBodyMotionGivesZero()
    {
        for (double angle : {0.0, 30.0, 90.0, 135.0, -60.0})
            for (double th : {0.0, 0.3, 1.5, kPi, 4.0, -7.0, 100.0}) {
                Link2dKinematics k("e", corotational(2.5, angle));
                const Eigen::Vector3d d = k.basicAt(rigid(2.5, angle, 0.7, -1.3, th));
                QVERIFY2(d.cwiseAbs().maxCoeff() <= 1e-12,
                         qPrintable(QString("angle %1 theta %2: d = %3 %4 %5")
                                        .arg(angle).arg(th).arg(d[0]).arg(d[1]).arg(d[2])));
            }
        // the linear L1 does not: a 1 rad turn gives shear L (sin 1 - 1) across, not 0
        Link2dKinematics lin("e", {{0, 1, 2, 3, 4, 5}, 2.5, 0.0});
        QVERIFY(lin.basicAt(rigid(2.5, 0.0, 0, 0, 1.0)).cwiseAbs().maxCoeff() > 0.1);
    }

    // A pure stretch along the element: d = (delta, 0, 0) exactly, as L1 gives it.
    void pureAxialStretch()
    {
        const double angle = 30.0, phi = angle * kPi / 180.0, delta = 0.8;
        Link2dKinematics k("e", corotational(2.0, angle));
        Link2dVector6 ue;
        ue << 0.1, 0.2, 0.0, 0.1 + delta * std::cos(phi), 0.2 + delta * std::sin(phi), 0.0;
        const Eigen::Vector3d d = k.basicAt(ue);
        QVERIFY(std::abs(d[0] - delta) <= 1e-15);
        QVERIFY(std::abs(d[1]) <= 1e-15 && d[2] == 0.0);
    }

    // A known large rotation: node j at length L' and turned by g about node i (fixed), node i
    // turned by ti, node j by tj: d = (L' - L, L (g - ti), tj - ti).
    void knownLargeRotation()
    {
        const double l = 3.0, ln = 2.6, g = 1.1, ti = 0.4, tj = -0.5;
        Link2dKinematics k("e", corotational(l, 90.0));
        Link2dVector6 ue;
        ue << 0.0, 0.0, ti, -ln * std::sin(g), ln * std::cos(g) - l, tj;
        const Eigen::Vector3d d = k.basicAt(ue);
        QVERIFY(std::abs(d[0] - (ln - l)) <= 1e-14);
        QVERIFY(std::abs(d[1] - l * (g - ti)) <= 1e-14);
        QCOMPARE(d[2], tj - ti);
        // small motions: L3 is L1 to first order (difference O(|u|^2))
        Link2dKinematics lin("e", {{0, 1, 2, 3, 4, 5}, l, 90.0});
        Link2dVector6 small;
        small << 1e-4, -2e-4, 3e-5, -1e-4, 2e-4, 5e-5;
        QVERIFY((k.basicAt(small) - lin.basicAt(small)).cwiseAbs().maxCoeff() <= 1e-7);
        QVERIFY((k.transformationAt(Link2dVector6::Zero()) - lin.matrix()).cwiseAbs().maxCoeff() ==
                0.0);
    }

    // Eq. L4-L5: the tangent is the derivative of the nodal forces (central difference,
    // h = 1e-6 m or rad, to 1e-6 of the largest entry), with laws on every DOF and with held
    // forces (geometric stiffness only); K0 is the tangent at rest with the held forces.
    void tangentIsTheDerivativeOfTheForces()
    {
        for (int variant = 0; variant < 2; ++variant) {
            std::array<Link2dBasicDof, 3> dofs;
            dofs[1].law = elastic(300.0);
            if (variant == 0) {
                dofs[0].law = elastic(1e4);
                dofs[2].law = elastic(500.0);
            } else {
                dofs[0].heldForce = -200.0;
                dofs[2].heldForce = 30.0;
            }
            Link2dElement e("e", corotational(2.0, 30.0), std::move(dofs));
            Eigen::VectorXd u(6);
            u << 0.1, -0.2, 0.4, 0.5, 0.3, -0.7;
            QVERIFY(e.setTrial(u).ok);
            const Link2dMatrix66 k = e.tangentStiffness();
            const double h = 1e-6;
            double worst = 0.0;
            for (int c = 0; c < 6; ++c) {
                Eigen::VectorXd up = u, um = u;
                up[c] += h;
                um[c] -= h;
                QVERIFY(e.setTrial(up).ok);
                const Eigen::VectorXd rp = nodalForces(e, up);
                QVERIFY(e.setTrial(um).ok);
                const Eigen::VectorXd rm = nodalForces(e, um);
                worst = std::max(worst, ((rp - rm) / (2 * h) - k.col(c)).cwiseAbs().maxCoeff());
            }
            qInfo("variant %d: max |K - dR/du| %.3g of max |K| %.6g", variant, worst,
                  k.cwiseAbs().maxCoeff());
            QVERIFY(worst <= 1e-6 * k.cwiseAbs().maxCoeff());
            QVERIFY(k.isApprox(k.transpose(), 1e-12)); // a potential exists: K is symmetric

            QVERIFY(e.setTrial(Eigen::VectorXd::Zero(6)).ok);
            std::vector<Eigen::Triplet<double>> t;
            e.addInitialStiffness(t, {0, 1, 2, 3, 4, 5});
            Eigen::SparseMatrix<double> k0(6, 6);
            k0.setFromTriplets(t.begin(), t.end());
            QVERIFY((Eigen::MatrixXd(k0) - e.tangentStiffness()).cwiseAbs().maxCoeff() <= 1e-12);
        }
    }

    // A collapsed chord is refused naming the element; a linear element never is.
    void collapsedChordFails()
    {
        std::array<Link2dBasicDof, 3> dofs;
        dofs[1].law = elastic(1.0);
        Link2dElement e("Brace", corotational(2.0, 0.0), std::move(dofs));
        Eigen::VectorXd u(6);
        u << 0.0, 0.0, 0.0, -2.0, 0.0, 0.0; // node j onto node i
        const ElementStatus s = e.setTrial(u);
        QVERIFY(!s.ok);
        QVERIFY2(QString::fromStdString(s.message).contains("Brace") &&
                     QString::fromStdString(s.message).contains("chord"),
                 s.message.c_str());
    }

    // The cantilever under a large tip load (chord turned about 0.74 rad): the element's own
    // Newton equals the exact equilibrium to 1e-9 m.
    void cantileverAgainstClosedForm()
    {
        Link2dElement e = cantilever();
        Eigen::Vector2d u;
        QVERIFY(solveCantilever(e, u));
        const Eigen::Vector2d x = closedFormCantilever();
        qInfo("tip (%.12f, %.12f) m, closed form (%.12f, %.12f) m; chord turned %.4f rad", u.x(),
              u.y(), x.x(), x.y(), e.basicDeformations()[1] / kL);
        QVERIFY(std::abs(e.basicDeformations()[1] / kL) > 0.5); // a large rotation
        QVERIFY((u - x).cwiseAbs().maxCoeff() <= 1e-9);
    }

    // The same cantilever in the real OpenSees 3.8: a base rotational spring kS L^2
    // (zeroLength) under an elasticBeamColumn with geomTransf Corotational, EA / L = kA, EI
    // 1e7 times the spring's (so that the beam stays straight to 1e-7), the tip load in 20
    // LoadControl steps with Newton. Tip displacements equal to 1e-6 of the peak.
    void cantileverAgainstOpenSees()
    {
        if (!opensees::available())
            QSKIP(qPrintable(opensees::reason()));
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const double e = 1e6, area = kA * kL / e, inertia = 1e7 * kS * kL * kL * kL / e;
        const QString script =
            QString("model BasicBuilder -ndm 2 -ndf 3\n"
                    "node 1 0.0 0.0\nnode 2 0.0 0.0\nnode 3 0.0 %1\n"
                    "fix 1 1 1 1\nequalDOF 1 2 1 2\n"
                    "uniaxialMaterial Elastic 1 %2\n"
                    "element zeroLength 1 1 2 -mat 1 -dir 3\n"
                    "geomTransf Corotational 1\n"
                    "element elasticBeamColumn 2 2 3 %3 %4 %5 1\n"
                    "timeSeries Linear 1\n"
                    "pattern Plain 1 1 { load 3 %6 %7 0.0 }\n"
                    "system BandGeneral\nnumberer Plain\nconstraints Transformation\n"
                    "test NormDispIncr 1e-14 100\nalgorithm Newton\n"
                    "integrator LoadControl 0.05\nanalysis Static\n"
                    "if {[analyze 20] != 0} { exit 1 }\n"
                    "set f [open tip.out w]\n"
                    "puts $f \"[format %.17g [nodeDisp 3 1]] [format %.17g [nodeDisp 3 2]]\"\n"
                    "close $f\n")
                .arg(kL)
                .arg(kS * kL * kL, 0, 'g', 17)
                .arg(area, 0, 'g', 17)
                .arg(e, 0, 'g', 17)
                .arg(inertia, 0, 'g', 17)
                .arg(kH)
                .arg(kV);
        const opensees::Result r = opensees::run(dir.path(), "cantilever.tcl", script);
        const auto tip = opensees::table(dir.filePath("tip.out"));
        QVERIFY2(r.finished && tip.size() == 1 && tip[0].size() == 2, qPrintable(r.output));
        Link2dElement el = cantilever();
        Eigen::Vector2d u;
        QVERIFY(solveCantilever(el, u));
        qInfo("OpenSees tip (%.12f, %.12f) m, HSMU (%.12f, %.12f) m", tip[0][0], tip[0][1], u.x(),
              u.y());
        QVERIFY(std::abs(tip[0][0] - u.x()) <= 1e-6 * u.norm());
        QVERIFY(std::abs(tip[0][1] - u.y()) <= 1e-6 * u.norm());
    }
};

QTEST_APPLESS_MAIN(TestLink2dCorotational)
#include "TestLink2dCorotational.moc"
