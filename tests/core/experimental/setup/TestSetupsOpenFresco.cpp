// The setups against the real OpenFresco 2.8 (../shared/tools/opensees; QSKIP with the reason
// where it is absent). Each case drives one `expSetup` with `expControl SimUniaxialMaterials`
// through a basic-displacement history (u up to 0.08 m, v up to 0.03 m, theta up to 0.3 rad;
// OpenFrescoSetupRun.h) and drives HSMU's setup with the same history and the same virtual
// actuators:
// - strokes: HSMU's strokes(d) against OpenFresco's actuator commands;
// - measured basic displacements: HSMU's basicDisplacements(OpenFresco's actuator
//   displacements) against OpenFresco's element daqDisp;
// - basic forces: HSMU's basicForces(those, OpenFresco's actuator forces) against OpenFresco's
//   element daqForce; the elastic actuators' forces are also checked as k s;
// each to 1e-10 of the peak of its component. Where OpenFresco departs from exact geometry
// (docs/setups.md, "Differences from OpenFresco") HSMU is checked against the exact statics
// computed here from the deformed positions (cross products, independent of the Jacobian) and
// OpenFresco's value against the departure the issue describes, to the same tolerance.

#include "OpenFrescoSetupCases.h"
#include "OpenFrescoSetupRun.h"
#include "core/experimental/setup/SetupScript.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace hsmu;

using namespace ofcases;

namespace {

double columnPeak(const ofsetup::Table& t, std::size_t col) {
    double p = 0.0;
    for (const auto& row : t)
        p = std::max(p, std::abs(row.at(col)));
    return p;
}

} // namespace

class TestSetupsOpenFresco : public QObject {
    Q_OBJECT
private slots:
    void againstOpenFresco_data();
    void againstOpenFresco();
    void lowerCaseNlGeomIsIgnoredByOpenFresco();
    void twoActuatorsNlGeomIgnoresV();
};

void TestSetupsOpenFresco::againstOpenFresco_data() {
    QTest::addColumn<int>("index");
    const auto all = cases();
    for (int i = 0; i < static_cast<int>(all.size()); ++i)
        QTest::newRow(all[i].label.toUtf8().constData()) << i;
}

void TestSetupsOpenFresco::againstOpenFresco() {
    if (!opensees::available())
        QSKIP(qPrintable(opensees::reason()));
    QFETCH(int, index);
    const Case c = cases()[index];
    std::string error;
    const auto setup = c.make(error);
    QVERIFY2(setup, error.c_str());
    const int m = setup->actuatorCount();
    // the very line OpenFresco runs, read by HSMU (SetupScript.h), gives the same setup
    SetupsByTag parsed;
    QVERIFY2(parseSetupScript(c.tcl.toStdString(), parsed, error), error.c_str());
    QVERIFY(parsed.count(1) && parsed.at(1)->typeName() == setup->typeName());
    QStringList materials;
    for (int i = 0; i < m; ++i)
        materials
            << (c.k.empty()
                    ? QString("uniaxialMaterial Steel01 %1 %2 %3 0.02")
                          .arg(i + 1)
                          .arg(4.0e5)
                          .arg(2.0e7)
                    : QString("uniaxialMaterial Elastic %1 %2").arg(i + 1).arg(c.k[i], 0, 'g', 17));
    QTemporaryDir dir;
    const auto h = history(c.withV);
    const ofsetup::Run of = ofsetup::run(dir.path(), c.tcl, materials, h);
    QVERIFY2(of.ran, qPrintable(of.output.right(2000)));

    const double tol = 1e-10;
    std::vector<double> peakS(m), peakD(3), peakQ(3);
    for (int i = 0; i < m; ++i)
        peakS[i] = columnPeak(of.actuatorCommand, i);
    for (int j = 0; j < 3; ++j) {
        peakD[j] = std::max(columnPeak(of.basicDisp, j), 1e-3);
        peakQ[j] = std::max(columnPeak(of.basicForce, j), 1e-6 * columnPeak(of.actuatorForce, 0));
    }
    double worstS = 0, worstD = 0, worstQ = 0;
    Eigen::Vector3d departure = Eigen::Vector3d::Zero(); // max |OpenFresco - exact| [N, N m]
    Eigen::Vector3d peakExact = Eigen::Vector3d::Zero(); // max |exact|
    const auto* planar = dynamic_cast<const PlanarActuatorSetup*>(setup.get());
    for (std::size_t k = 0; k < h.size(); ++k) {
        const Eigen::Vector3d d(h[k][0], h[k][1], h[k][2]);
        for (int j = 0; j < 3; ++j)
            QVERIFY(std::abs(of.trial[k][j] - d(j)) <= 1e-15); // OpenFresco got this history
        Eigen::VectorXd s, sOf(m), fOf(m), dMeas, q;
        QVERIFY(setup->strokes(d, s).ok);
        Eigen::VectorXd sParsed;
        QVERIFY(parsed.at(1)->strokes(d, sParsed).ok);
        QVERIFY(sParsed == s);
        for (int i = 0; i < m; ++i) {
            sOf(i) = of.actuatorDisp[k][i];
            fOf(i) = of.actuatorForce[k][i];
            worstS = std::max(worstS, std::abs(s(i) - of.actuatorCommand[k][i]) / peakS[i]);
            if (!c.k.empty()) // the same virtual actuators
                QVERIFY(std::abs(fOf(i) - c.k[i] * sOf(i)) <= 1e-12 * c.k[i] * peakS[i]);
        }
        const SetupResult r = setup->basicDisplacements(sOf, d, dMeas);
        QVERIFY2(r.ok, r.reason.c_str());
        QVERIFY(setup->basicForces(dMeas, fOf, q).ok);
        Eigen::Vector3d expected = q;
        if (c.departure) {
            // HSMU against exact statics, OpenFresco against the departure
            const Eigen::Vector3d exact = statics(*planar, dMeas, fOf);
            for (int j = 0; j < 3; ++j)
                QVERIFY2(
                    std::abs(q(j) - exact(j)) <= tol * peakQ[j],
                    qPrintable(
                        QString("step %1 q%2 %3 exact %4").arg(k).arg(j).arg(q(j)).arg(exact(j))));
            expected = c.departure(q, sOf, fOf, dMeas);
            for (int j = 0; j < 3; ++j) {
                departure(j) = std::max(departure(j), std::abs(expected(j) - q(j)));
                peakExact(j) = std::max(peakExact(j), std::abs(q(j)));
            }
        }
        Eigen::Vector3d dOf = dMeas;
        for (int j : c.undriven)
            dOf(j) = 0.0;
        expected += kInit * (d - dOf);
        for (int j = 0; j < 3; ++j) {
            worstD = std::max(worstD, std::abs(dOf(j) - of.basicDisp[k][j]) / peakD[j]);
            worstQ = std::max(worstQ, std::abs(expected(j) - of.basicForce[k][j]) / peakQ[j]);
        }
    }
    qInfo("%s: worst / peak: strokes %.3g, basic displacements %.3g, basic forces %.3g",
          qPrintable(c.label), worstS, worstD, worstQ);
    if (c.departure) {
        qInfo("  OpenFresco departs from exact statics by up to %.4g N, %.4g N, %.4g N m (peaks of "
              "the exact basic forces %.4g N, %.4g N, %.4g N m)",
              departure(0), departure(1), departure(2), peakExact(0), peakExact(1), peakExact(2));
        // the departure is real, not round-off
        QVERIFY(departure.maxCoeff() > 1e-3 * peakExact.maxCoeff());
    }
    QVERIFY2(worstS <= tol, qPrintable(QString("strokes off by %1 of the peak").arg(worstS)));
    QVERIFY2(worstD <= tol, qPrintable(QString("basic displacements off by %1").arg(worstD)));
    QVERIFY2(worstQ <= tol, qPrintable(QString("basic forces off by %1").arg(worstQ)));
}

void TestSetupsOpenFresco::lowerCaseNlGeomIsIgnoredByOpenFresco() {
    // OpenFresco parses options by exact string: "-nlgeom" is silently ignored and the setup
    // stays linear. HSMU's setups take the geometry as an enum; the configuration (issue 24,
    // later) must reject unknown words. Asserted here so the documented departure stays true.
    if (!opensees::available())
        QSKIP(qPrintable(opensees::reason()));
    const auto p = setupcatalog::three(SetupGeometry::Linear, false);
    QTemporaryDir dir;
    const auto h = history(true);
    const ofsetup::Run of =
        ofsetup::run(dir.path(),
                     QString("expSetup ThreeActuators2d 1 -control 1 %1 %2 %3 %4 %5 -nlgeom")
                         .arg(p.La1)
                         .arg(p.La2)
                         .arg(p.La3)
                         .arg(p.L1)
                         .arg(p.L2),
                     {"uniaxialMaterial Elastic 1 2e7", "uniaxialMaterial Elastic 2 2e7",
                      "uniaxialMaterial Elastic 3 2e7"},
                     h);
    QVERIFY2(of.ran, qPrintable(of.output.right(2000)));
    std::string e;
    const auto linear = makeThreeActuators2d(p, e);
    auto exactParams = p;
    exactParams.geometry = SetupGeometry::Exact;
    const auto exact = makeThreeActuators2d(exactParams, e);
    double offLinear = 0, offExact = 0;
    for (std::size_t k = 0; k < h.size(); ++k) {
        Eigen::VectorXd sl, se;
        QVERIFY(linear->strokes(Eigen::Vector3d(h[k][0], h[k][1], h[k][2]), sl).ok);
        QVERIFY(exact->strokes(Eigen::Vector3d(h[k][0], h[k][1], h[k][2]), se).ok);
        for (int i = 0; i < 3; ++i) {
            offLinear = std::max(offLinear, std::abs(sl(i) - of.actuatorCommand[k][i]));
            offExact = std::max(offExact, std::abs(se(i) - of.actuatorCommand[k][i]));
        }
    }
    QVERIFY(offLinear <= 1e-15);
    QVERIFY(offExact > 1e-3); // 0.3 rad makes the exact strokes differ by millimetres
}

void TestSetupsOpenFresco::twoActuatorsNlGeomIgnoresV() {
    // docs/setups.md, difference 3: with v != 0 OpenFresco commands s1 = u (La1 unused) and
    // leaves v out of actuator 2's stroke; HSMU keeps both (S1). Both asserted to 1e-15 m.
    if (!opensees::available())
        QSKIP(qPrintable(opensees::reason()));
    const auto p = setupcatalog::two(SetupGeometry::Exact, false);
    QTemporaryDir dir;
    const auto h = history(true);
    const ofsetup::Run of =
        ofsetup::run(dir.path(),
                     QString("expSetup TwoActuators2d 1 -control 1 %1 %2 %3 -nlGeom")
                         .arg(p.La1)
                         .arg(p.La2)
                         .arg(p.L),
                     {"uniaxialMaterial Elastic 1 2e7", "uniaxialMaterial Elastic 2 3e7"}, h);
    QVERIFY2(of.ran, qPrintable(of.output.right(2000)));
    std::string e;
    const auto setup = makeTwoActuators2d(p, e);
    double largest = 0;
    for (std::size_t k = 0; k < h.size(); ++k) {
        const double u = h[k][0], v = h[k][1], th = h[k][2];
        QVERIFY(std::abs(of.actuatorCommand[k][0] - u) <= 1e-15);
        const double ofS2 =
            std::hypot(u - p.L * std::sin(th) + p.La2, p.L * std::cos(th) - p.L) - p.La2;
        QVERIFY(std::abs(of.actuatorCommand[k][1] - ofS2) <= 1e-15);
        Eigen::VectorXd s;
        QVERIFY(setup->strokes(Eigen::Vector3d(u, v, th), s).ok);
        QVERIFY(std::abs(s(0) - (std::hypot(u + p.La1, v) - p.La1)) <= 1e-15);
        QVERIFY(std::abs(s(1) -
                         (std::hypot(u - p.L * std::sin(th) + p.La2, p.L * std::cos(th) - p.L + v) -
                          p.La2)) <= 1e-15);
        largest = std::max(largest, std::abs(s(0) - of.actuatorCommand[k][0]));
    }
    qInfo("largest actuator-1 difference (v up to 0.03 m): %.3g m", largest);
    QVERIFY(largest > 1e-4); // v^2 / (2 La1) = 0.3 mm at v = 0.03 m
}

QTEST_APPLESS_MAIN(TestSetupsOpenFresco)
#include "TestSetupsOpenFresco.moc"
