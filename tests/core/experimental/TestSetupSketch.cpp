// The console's sketch of a link2d specimen and its setup (core/experimental/SetupSketch.h,
// eqs. K1-K3), against node and actuator positions worked out by hand:
//  - TwoActuators2d La1 1.5, La2 1.2, L 0.6 -phiLocX 90 on a 3 m column (the setup frame is
//    then the global one): node j, both bases and attachments at rest and at a magnified
//    deformed state, to 1e-12 m;
//  - the preset's NoTransformation -dir 1 2 on the same column: the vertical actuator above
//    node j, the lateral one beside it;
//  - with exact geometry at scale 1 every drawn actuator's length minus its rest length is the
//    setup's own stroke (S1), for a column and for a ThreeActuators2d -phiLocX -20 on an
//    element at 30 deg: the drawing's frames agree with the setup's, to 1e-12 m;
//  - a 3-D setup is not drawn, and says so naming it; sketchScale's round values.

#include "core/experimental/SetupSketch.h"
#include "core/experimental/setup/SetupScript.h"

#include <QtTest>

#include <cmath>

using namespace hsmu;

namespace {

std::unique_ptr<ExperimentalSetup> setupOf(const std::string& line) {
    SetupsByTag tags;
    std::string error;
    if (!parseSetupScript(line, tags, error) || tags.empty())
        qFatal("%s", error.c_str());
    return std::move(tags.begin()->second);
}

Link2dGeometry column(double length = 3.0, double angle = 90.0) {
    Link2dGeometry g;
    g.length = length;
    g.angleDeg = angle;
    return g;
}

std::vector<SketchSegment> partsOf(const SetupSketch& s, SketchPart part) {
    std::vector<SketchSegment> out;
    for (const SketchSegment& seg : s.segments)
        if (seg.part == part)
            out.push_back(seg);
    return out;
}

void near(const Eigen::Vector2d& got, const Eigen::Vector2d& want, const char* what) {
    if ((got - want).norm() > 1e-12)
        QFAIL(qPrintable(QStringLiteral("%1: (%2, %3), expected (%4, %5)")
                             .arg(QLatin1String(what))
                             .arg(got.x(), 0, 'g', 17)
                             .arg(got.y(), 0, 'g', 17)
                             .arg(want.x(), 0, 'g', 17)
                             .arg(want.y(), 0, 'g', 17)));
}

} // namespace

class TestSetupSketch : public QObject {
    Q_OBJECT
private slots:
    void twoActuatorsColumnClosedForm() {
        auto setup = setupOf("expSetup TwoActuators2d 1 1.5 1.2 0.6 -phiLocX 90");
        const SetupSketch rest = setupSketch(*setup, column(), Eigen::Vector3d::Zero(), 1.0);
        QVERIFY(rest.drawable);
        near(rest.nodeJ, {0.0, 3.0}, "node j at rest");
        auto acts = partsOf(rest, SketchPart::Actuator);
        QCOMPARE(int(acts.size()), 2);
        near(acts[0].from, {-1.5, 3.0}, "base 1");
        near(acts[0].to, {0.0, 3.0}, "attachment 1 at rest");
        near(acts[1].from, {-1.2, 3.6}, "base 2");
        near(acts[1].to, {0.0, 3.6}, "attachment 2 at rest");
        QCOMPARE(int(partsOf(rest, SketchPart::Platform).size()), 1); // the arm to actuator 2

        // axial 0.002 m, shear -0.05 m (a sway of +0.05 m in x), rotation 0.03 rad, x 10
        const double m = 10.0;
        const SetupSketch s = setupSketch(*setup, column(), Eigen::Vector3d(0.002, -0.05, 0.03), m);
        near(s.nodeJ, {0.5, 3.02}, "node j deformed");
        acts = partsOf(s, SketchPart::Actuator);
        near(acts[0].from, {-1.5, 3.0}, "base 1 stays");
        near(acts[0].to, {0.5, 3.02}, "attachment 1 at node j");
        near(acts[1].from, {-1.2, 3.6}, "base 2 stays");
        near(acts[1].to, {0.5 - 0.6 * std::sin(0.3), 3.02 + 0.6 * std::cos(0.3)}, "attachment 2");
        const auto tick = partsOf(s, SketchPart::Rotation);
        QCOMPARE(int(tick.size()), 1);
        near(tick[0].to - tick[0].from, 0.45 * Eigen::Vector2d(-std::sin(0.3), std::cos(0.3)),
             "rotation tick");
        near(partsOf(s, SketchPart::Element)[0].from, {0.0, 0.0}, "node i");
    }

    void directSetupOfThePreset() {
        auto setup = setupOf("expSetup NoTransformation 1 -dir 1 2 -sizeTrialOut 3 3");
        const SetupSketch s =
            setupSketch(*setup, column(), Eigen::Vector3d(-0.001, 0.02, 0.0), 5.0);
        QVERIFY(s.drawable);
        near(s.nodeJ, {-0.1, 2.995}, "node j");
        const auto acts = partsOf(s, SketchPart::Actuator);
        QCOMPARE(int(acts.size()), 2);
        QCOMPARE(acts[0].actuator, 0);
        near(acts[0].from, {0.0, 4.2}, "vertical actuator's base, 0.4 L above node j");
        near(acts[1].from, {-1.2, 3.0}, "lateral actuator's base, 0.4 L beside node j");
        near(acts[1].to, s.nodeJ, "lateral actuator on node j");
    }

    void exactLengthsAreTheSetupsStrokes_data() {
        QTest::addColumn<QString>("line");
        QTest::addColumn<double>("angle");
        QTest::newRow("two actuators, column")
            << "expSetup TwoActuators2d 1 1.5 1.2 0.6 -nlGeom -phiLocX 90" << 90.0;
        QTest::newRow("two actuators right, column")
            << "expSetup TwoActuators2d 1 1.5 1.2 0.6 -nlGeom -posAct right -phiLocX 90" << 90.0;
        QTest::newRow("three actuators, 30 deg")
            << "expSetup ThreeActuators2d 1 1.6 1.1 1.3 0.7 0.5 -nlGeom -phiLocX -20" << 30.0;
        QTest::newRow("inverted V, beam")
            << "expSetup InvertedVBrace2d 1 1.6 1.1 1.3 0.7 0.5 -nlGeom" << 0.0;
        QTest::newRow("jntoff, 120 deg") << "expSetup ThreeActuatorsJntOff2d 1 1.6 1.1 1.3 0.2 0.5 "
                                            "0.4 0.3 0.1 0.15 -nlGeom -phiLocX 45"
                                         << 120.0;
    }
    void exactLengthsAreTheSetupsStrokes() {
        QFETCH(QString, line);
        QFETCH(double, angle);
        auto setup = setupOf(line.toStdString());
        const Eigen::Vector3d d(0.03, -0.07, 0.2);
        Eigen::VectorXd strokes;
        QVERIFY(setup->strokes(d, strokes).ok);
        const SetupSketch rest =
            setupSketch(*setup, column(2.5, angle), Eigen::Vector3d::Zero(), 0.0);
        const SetupSketch s = setupSketch(*setup, column(2.5, angle), d, 1.0);
        const auto restActs = partsOf(rest, SketchPart::Actuator);
        const auto acts = partsOf(s, SketchPart::Actuator);
        QCOMPARE(int(acts.size()), setup->actuatorCount());
        for (std::size_t i = 0; i < acts.size(); ++i) {
            const double drawn =
                (acts[i].to - acts[i].from).norm() - (restActs[i].to - restActs[i].from).norm();
            QVERIFY2(std::abs(drawn - strokes[Eigen::Index(i)]) < 1e-12,
                     qPrintable(QStringLiteral("actuator %1: drawn %2, stroke %3")
                                    .arg(i)
                                    .arg(drawn, 0, 'g', 17)
                                    .arg(strokes[Eigen::Index(i)], 0, 'g', 17)));
        }
    }

    void threeDimensionalSetupIsNotDrawn() {
        auto setup =
            setupOf("expSetup FourActuators3d 1 1.1 1.2 1.3 1.4 0.2 0.2 0.2 0.2 0.8 0.3 0.3 "
                    "0.1 0.1 1.0 1.0 0.4");
        const SetupSketch s = setupSketch(*setup, column(), Eigen::Vector3d::Zero(), 1.0);
        QVERIFY(!s.drawable);
        QVERIFY2(QString::fromStdString(s.reason).startsWith(QLatin1String("FourActuators3d")),
                 s.reason.c_str());
    }

    void roundScale() {
        QCOMPARE(sketchScale(0.02, 3.0), 10.0);    // 0.1 L / peak = 15
        QCOMPARE(sketchScale(0.005, 3.0), 50.0);   // 60
        QCOMPARE(sketchScale(0.0013, 3.0), 200.0); // 230.8
        QCOMPARE(sketchScale(1.0, 3.0), 1.0);      // never below 1
        QCOMPARE(sketchScale(0.0, 3.0), 1.0);
        QCOMPARE(sketchScale(std::nan(""), 3.0), 1.0);
    }
};

QTEST_APPLESS_MAIN(TestSetupSketch)
#include "TestSetupSketch.moc"
