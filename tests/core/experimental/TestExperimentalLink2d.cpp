// Tests of the multi-DOF experimental element (core/experimental/ExperimentalLink2d.h), its
// basic system (core/structure/Link2dKinematics.h, eq. L1-L2), the numerical twin
// (Link2dElement) and the in-process virtual lab of N actuators (VirtualActuatorLab), on a
// one-bay frame (docs/setups.md, "Multi-DOF elements"). Units: kN, m, s, t.
//
// Frame: columns 3 m (nodes 1-3 left, 2-4 right, bases fixed, axially rigid: no vertical
// DOFs), beam 5 m (3-4). DOFs: x3, x4 (20 t each), theta3, theta4 (0.05 t m^2). Left column:
// the specimen, a lateral actuator on the shear DOF (displacement control, Bouc-Wen) and a
// vertical one on the axial DOF holding a constant axial load of -500 kN (force control,
// elastic 2e5 kN/m), OpenFresco's `expSetup NoTransformation 1 -dir 1 2 -sizeTrialOut 3 3`;
// its rotation carries no actuator. Reference: the same column as a numerical Link2dElement
// (held axial force, the same Bouc-Wen law on the shear DOF, a free rotation).

#include "core/experimental/ExperimentalLink2d.h"
#include "core/experimental/VirtualActuatorLab.h"
#include "core/experimental/setup/NoTransformation.h"
#include "core/experimental/setup/PlanarSetups.h"
#include "core/experiment/HybridTest.h"
#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/LinearElastic.h"
#include "core/integration/AlphaOS.h"
#include "core/structure/Link2dElement.h"
#include "core/structure/Structure.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace hsmu;

namespace {

constexpr double kH = 3.0, kB = 5.0, kP = -500.0, kVertical = 2e5;

std::unique_ptr<HysteresisLaw> columnShearLaw()
{
    BoucWenParameters p;
    p.k0 = 1.0;
    p.alpha = 0.05;
    p.uRef = 0.01;  // [m]
    p.fRef = 100.0; // [kN]: initial stiffness 1e4 kN/m
    return std::make_unique<BoucWen>(p);
}

struct Recorder final : StepObserver {
    std::vector<StepRecord> records;
    void onStep(const StepRecord& r) override { records.push_back(r); }
};

GroundMotion sine()
{
    GroundMotion gm;
    gm.name = "sine";
    gm.dt = 0.01;
    for (int i = 0; i <= 400; ++i)
        gm.acceleration.push_back(4.0 * std::sin(2.0 * std::numbers::pi * 1.5 * i * gm.dt));
    return gm;
}

// DOF indices: 0 x3, 1 x4, 2 theta3, 3 theta4.
Link2dGeometry leftColumn() { return {{-1, -1, -1, 0, -1, 2}, kH, 90.0}; }

std::vector<ActuatorChannelSpec> channels()
{
    ActuatorChannelSpec vertical{"vertical", ActuatorMode::Force, kP, {}, 0.0};
    vertical.limits.maxForce = 1000.0;
    vertical.limits.maxDeformation = 0.01;
    ActuatorChannelSpec lateral{"lateral", ActuatorMode::Displacement, 0.0, {}, 1e4};
    lateral.limits.maxDeformation = 0.2;
    lateral.limits.maxForce = 1000.0;
    lateral.limits.maxIncrement = 0.05;
    return {vertical, lateral};
}

std::unique_ptr<ExperimentalSetup> columnSetup()
{
    std::string error;
    auto s = NoTransformation::create({1, 2}, 3, error);
    if (!s)
        qFatal("%s", error.c_str());
    return s;
}

// The specimen on the in-process virtual lab; *lab, when given, points at its lab.
std::unique_ptr<Element> specimen(VirtualActuatorLab** lab,
                                  std::vector<ActuatorChannelSpec> ch = channels())
{
    std::vector<VirtualActuator> acts;
    acts.push_back({"vertical", ActuatorMode::Force, std::make_unique<LinearElastic>(kVertical)});
    acts.push_back({"lateral", ActuatorMode::Displacement, columnShearLaw()});
    auto control = std::make_unique<VirtualActuatorLab>(std::move(acts));
    if (lab)
        *lab = control.get();
    return std::make_unique<ExperimentalLink2d>("Column L", leftColumn(), columnSetup(),
                                                std::move(ch), std::move(control));
}

std::unique_ptr<Element> numericalColumn()
{
    std::array<Link2dBasicDof, 3> dofs;
    dofs[0].heldForce = kP;
    dofs[1].law = columnShearLaw();
    return std::make_unique<Link2dElement>("Column L", leftColumn(), std::move(dofs));
}

std::unique_ptr<Structure> frame(std::unique_ptr<Element> left)
{
    auto s = std::make_unique<Structure>();
    s->addDof("x3", 20.0);
    s->addDof("x4", 20.0);
    s->addDof("theta3", 0.05, 0.0); // rotations: not shaken by the record
    s->addDof("theta4", 0.05, 0.0);
    s->addElement(std::move(left));
    std::array<Link2dBasicDof, 3> right; // numerical right column
    right[0].heldForce = kP;
    right[1].law = columnShearLaw();
    right[2].law = std::make_unique<LinearElastic>(5000.0);
    s->addElement(std::make_unique<Link2dElement>(
        "Column R", Link2dGeometry{{-1, -1, -1, 1, -1, 3}, kH, 90.0}, std::move(right)));
    std::array<Link2dBasicDof, 3> beam;
    beam[0].law = std::make_unique<LinearElastic>(1e6);
    beam[1].law = std::make_unique<LinearElastic>(480.0);
    beam[2].law = std::make_unique<LinearElastic>(4000.0);
    s->addElement(std::make_unique<Link2dElement>(
        "Beam", Link2dGeometry{{0, -1, 2, 1, -1, 3}, kB, 0.0}, std::move(beam)));
    s->setModalDamping(0.02, 1, 2);
    return s;
}

std::unique_ptr<HybridTest> makeTest(std::unique_ptr<Element> left, Recorder& rec)
{
    HybridTestOptions o;
    o.dt = 0.01;
    auto t = std::make_unique<HybridTest>(frame(std::move(left)), std::make_unique<AlphaOS>(),
                                          sine(), o);
    t->addObserver(&rec);
    return t;
}

HybridTest::StepResult runToStop(HybridTest& t)
{
    HybridTest::StepResult r;
    while ((r = t.step()) == HybridTest::StepResult::Advanced) {
    }
    return r;
}

const Alarm* findAlarm(const HybridTest& t, AlarmKind kind)
{
    for (const Alarm& a : t.alarms())
        if (a.kind == kind)
            return &a;
    return nullptr;
}

} // namespace

class TestExperimentalLink2d : public QObject {
    Q_OBJECT

private slots:
    // Eq. L1: rigid-body motions give d = 0; a column top's sway gives shear -u, its lift the
    // axial deformation, its turn the rotation; eq. L2: A^T q is in equilibrium.
    void kinematicsClosedForm()
    {
        for (double angle : {90.0, 0.0, 33.0}) {
            Link2dKinematics k("e", {{0, 1, 2, 3, 4, 5}, 2.5, angle});
            const double c = std::cos(angle * std::numbers::pi / 180.0);
            const double s = std::sin(angle * std::numbers::pi / 180.0);
            Eigen::VectorXd u(6);
            u << 0.3, -0.2, 0.0, 0.3, -0.2, 0.0; // translation
            QVERIFY(k.basic(u).norm() <= 1e-15);
            const double th = 0.01; // rotation about node i
            u << 0.0, 0.0, th, -th * 2.5 * s, th * 2.5 * c, th;
            QVERIFY(k.basic(u).norm() <= 1e-15);
            Eigen::VectorXd r = Eigen::VectorXd::Zero(6);
            k.addNodalForces(Eigen::Vector3d(10.0, -3.0, 7.0), r);
            QVERIFY(std::abs(r[0] + r[3]) <= 1e-12 && std::abs(r[1] + r[4]) <= 1e-12);
            // moment about node i: node j's force at (L c, L s) plus both nodal moments
            const double m = r[2] + r[5] + 2.5 * c * r[4] - 2.5 * s * r[3];
            QVERIFY2(std::abs(m) <= 1e-12, qPrintable(QString::number(m)));
        }
        Link2dKinematics col("c", leftColumn()); // DOFs 0 x3, 2 theta3
        Eigen::VectorXd u(4);
        u << 0.02, 0.0, 0.003, 0.0;
        const Eigen::Vector3d d = col.basic(u);
        QCOMPARE(d[0], 0.0);
        QVERIFY(std::abs(d[1] + 0.02) <= 1e-17); // local y of a column points to -x
        QCOMPARE(d[2], 0.003);
    }

    // The configuration's errors name the element, the setup and the counts.
    void configurationErrors()
    {
        std::string error;
        auto two = NoTransformation::create({1}, 2, error); // 2 basic DOFs, the element has 3
        std::vector<VirtualActuator> acts;
        acts.push_back({"lateral", ActuatorMode::Displacement, columnShearLaw()});
        try {
            ExperimentalLink2d e("C", leftColumn(), std::move(two), {channels()[1]},
                                 std::make_unique<VirtualActuatorLab>(std::move(acts)));
            QFAIL("a setup of 2 basic DOFs was taken");
        } catch (const std::invalid_argument& x) {
            QVERIFY2(QString(x.what()).contains("setup NoTransformation serves 2 basic DOFs"),
                     x.what());
        }
        acts.clear();
        acts.push_back({"lateral", ActuatorMode::Displacement, columnShearLaw()});
        try { // one channel configured, the setup has two actuators
            ExperimentalLink2d e("C", leftColumn(), columnSetup(), {channels()[1]},
                                 std::make_unique<VirtualActuatorLab>(std::move(acts)));
            QFAIL("a channel count mismatch was taken");
        } catch (const std::invalid_argument& x) {
            QVERIFY2(QString(x.what()).contains("has 2 actuators, 1 channels configured"),
                     x.what());
        }
        // Singular geometry at configuration time: TwoActuators2d with L = 0.
        TwoActuators2dParams p{1.5, 1.2, 0.0};
        QVERIFY(!makeTwoActuators2d(p, error));
        QVERIFY2(QString::fromStdString(error).contains("TwoActuators2d: L"), error.c_str());
    }

    // Acceptance (b): the frame on the in-process virtual lab equals the all-numerical run to
    // 1e-9 of the peak; the vertical actuator held -500 kN throughout.
    void frameEqualsNumerical()
    {
        Recorder a, b;
        auto ref = makeTest(numericalColumn(), a);
        VirtualActuatorLab* lab = nullptr;
        auto hyb = makeTest(specimen(&lab), b);
        QVERIFY2(ref->prepare(), ref->lastError().c_str());
        QVERIFY2(hyb->prepare(), hyb->lastError().c_str());
        QCOMPARE(runToStop(*ref), HybridTest::StepResult::Finished);
        QCOMPARE(runToStop(*hyb), HybridTest::StepResult::Finished);
        QCOMPARE(a.records.size(), b.records.size());
        // T^T M iota: the record shakes the translations only (influence 0 on the rotations)
        QCOMPARE(hyb->structure().influence(), Eigen::Vector4d(20.0, 20.0, 0.0, 0.0).eval());
        double peakU = 0, peakF = 0, du = 0, dF = 0;
        for (std::size_t i = 0; i < a.records.size(); ++i) {
            peakU = std::max(peakU, a.records[i].u.cwiseAbs().maxCoeff());
            du = std::max(du, (a.records[i].u - b.records[i].u).cwiseAbs().maxCoeff());
            peakF = std::max(peakF, std::abs(a.records[i].elements[0].force));
            dF = std::max(dF, std::abs(a.records[i].elements[0].force -
                                       b.records[i].elements[0].force));
        }
        qInfo("peak |u| %.6g m, max |du| %.3g; peak shear %.6g kN, max |dF| %.3g", peakU, du,
              peakF, dF);
        QVERIFY(peakU > 0.02); // the column yields (u_y about 0.005 m)
        QVERIFY(du <= 1e-9 * peakU);
        QVERIFY(dF <= 1e-9 * peakF);
        const auto& x = static_cast<const ExperimentalLink2d&>(*hyb->structure().elements()[0]);
        QVERIFY(std::abs(x.basicForces()[0] - kP) <= 1e-12 * std::abs(kP));
        QVERIFY(std::abs(x.strokes()[0] - kP / kVertical) <= 1e-15);
        QCOMPARE(x.basicForces()[2], 0.0);
        QVERIFY(std::abs(lab->committedForce(0) - kP) <= 1e-12 * std::abs(kP));
    }

    // A lateral stroke limit trips before any command leaves: the test holds naming the
    // channel, every actuator keeps its committed stroke and force, and the lab refuses targets.
    void strokeLimitHoldsEveryActuator()
    {
        auto ch = channels();
        ch[1].limits.maxDeformation = 0.015;
        Recorder r;
        VirtualActuatorLab* lab = nullptr;
        auto t = makeTest(specimen(&lab, ch), r);
        QVERIFY(t->prepare());
        QCOMPARE(runToStop(*t), HybridTest::StepResult::Held);
        const Alarm* a = findAlarm(*t, AlarmKind::LimitExceeded);
        QVERIFY(a);
        QVERIFY2(QString::fromStdString(a->message).contains("actuator 'lateral'"),
                 a->message.c_str());
        QVERIFY(lab->holding());
        const auto& x = static_cast<const ExperimentalLink2d&>(*t->structure().elements()[0]);
        QVERIFY(std::abs(lab->committedStroke(1)) <= 0.015);
        QCOMPARE(lab->actuator(1).law->trialDeformation(), lab->committedStroke(1));
        QCOMPARE(lab->actuator(0).law->trialForce(), lab->committedForce(0));
        QVERIFY(std::abs(lab->committedForce(0) - kP) <= 1e-12 * std::abs(kP));
        QVERIFY(!lab->setTargets(Eigen::Vector2d(kP, 0.0)).ok);
        QCOMPARE(x.strokes()[1], lab->committedStroke(1));
        QCOMPARE(int(r.records.size()), t->currentStep() + 1); // every committed step recorded
    }

    // A force-controlled actuator whose measured stroke crosses its displacement limit holds at
    // the first step, naming the vertical channel; nothing is committed.
    void forceChannelDisplacementLimit()
    {
        auto ch = channels();
        ch[0].limits.maxDeformation = 0.001; // the load needs 0.0025 m
        Recorder r;
        VirtualActuatorLab* lab = nullptr;
        auto t = makeTest(specimen(&lab, ch), r);
        QVERIFY(t->prepare());
        QCOMPARE(t->step(), HybridTest::StepResult::Held);
        const Alarm* a = findAlarm(*t, AlarmKind::LimitExceeded);
        QVERIFY(a);
        QVERIFY2(QString::fromStdString(a->message).contains("actuator 'vertical'"),
                 a->message.c_str());
        QCOMPARE(t->currentStep(), 0);
        QVERIFY(lab->holding());
        QCOMPARE(lab->committedStroke(0), 0.0);
    }

    // Through an exact (-nlGeom) setup: a column top (x3, y3, theta3) driven by OpenFresco's
    // `expSetup TwoActuators2d 1 1.5 1.2 0.6 -nlGeom -phiLocX 90` with elastic actuators. The
    // commands are S1's closed-form strokes; the measured basic displacements are the commanded
    // ones (S4's Newton, v given); the basic forces do the actuators' virtual work (central
    // difference of s, eq. S3) and the nodal forces the basic forces' (eq. L2).
    void exactSetupThroughTheElement()
    {
        std::string error;
        TwoActuators2dParams p{1.5, 1.2, 0.6, SetupGeometry::Exact, false, 90.0};
        auto setup = makeTwoActuators2d(p, error);
        QVERIFY2(setup, error.c_str());
        const ExperimentalSetup* setupView = setup.get();
        std::vector<VirtualActuator> acts;
        acts.push_back({"lower", ActuatorMode::Displacement, std::make_unique<LinearElastic>(2e4)});
        acts.push_back({"upper", ActuatorMode::Displacement, std::make_unique<LinearElastic>(3e4)});
        std::vector<ActuatorChannelSpec> ch{{"lower", ActuatorMode::Displacement, 0, {}, 2e4},
                                            {"upper", ActuatorMode::Displacement, 0, {}, 3e4}};
        ExperimentalLink2d e("C", {{-1, -1, -1, 0, 1, 2}, kH, 90.0}, std::move(setup), ch,
                             std::make_unique<VirtualActuatorLab>(std::move(acts)));
        Eigen::VectorXd u(3);
        u << 0.05, 0.002, 0.1; // x3 [m], y3 [m], theta3 [rad]
        QVERIFY(e.setTrial(u).ok);
        // setup frame: (u, v) = R(90) (axial, shear) = (-shear, axial) = (x3, y3)
        const double us = 0.05, vs = 0.002, th = 0.1;
        const double s1 = std::hypot(us + 1.5, vs) - 1.5;
        const double s2 = std::hypot(us - 0.6 * std::sin(th) + 1.2, vs + 0.6 * std::cos(th) - 0.6) - 1.2;
        QVERIFY(std::abs(e.commands()[0] - s1) <= 1e-15);
        QVERIFY(std::abs(e.commands()[1] - s2) <= 1e-15);
        QVERIFY((e.basicDeformations() - e.commandedBasic()).cwiseAbs().maxCoeff() <= 1e-13);
        const Eigen::Vector2d f(2e4 * s1, 3e4 * s2);
        QVERIFY((e.actuatorForces() - f).cwiseAbs().maxCoeff() <= 1e-9);
        const Eigen::VectorXd d = e.commandedBasic();
        for (int k = 0; k < 3; ++k) {
            const double h = 1e-6;
            Eigen::VectorXd dp = d, dm = d, sp, sm;
            dp[k] += h;
            dm[k] -= h;
            QVERIFY(setupView->strokes(dp, sp).ok && setupView->strokes(dm, sm).ok);
            const double work = f.dot(sp - sm) / (2 * h);
            QVERIFY2(std::abs(e.basicForces()[k] - work) <= 1e-6 * f.cwiseAbs().maxCoeff(),
                     qPrintable(QString("basic DOF %1: %2 vs %3").arg(k)
                                    .arg(e.basicForces()[k]).arg(work)));
        }
        Eigen::VectorXd r = Eigen::VectorXd::Zero(3);
        e.addNodalForces(r);
        const Link2dKinematics kinematics("C", {{-1, -1, -1, 0, 1, 2}, kH, 90.0});
        const Eigen::Matrix<double, 3, 6>& A = kinematics.matrix();
        const Eigen::Vector3d expected = A.rightCols(3).transpose() * Eigen::Vector3d(
            e.basicForces()[0], e.basicForces()[1], e.basicForces()[2]);
        QVERIFY((r - expected).cwiseAbs().maxCoeff() <= 1e-12 * expected.cwiseAbs().maxCoeff());
    }

    // An emergency hold mid-test: every actuator keeps its committed stroke and force; after
    // resume the test finishes and equals the uninterrupted numerical run.
    void emergencyHoldThenResume()
    {
        Recorder a, b;
        auto ref = makeTest(numericalColumn(), a);
        VirtualActuatorLab* lab = nullptr;
        auto t = makeTest(specimen(&lab), b);
        QVERIFY(ref->prepare() && t->prepare());
        QCOMPARE(runToStop(*ref), HybridTest::StepResult::Finished);
        for (int i = 0; i < 150; ++i)
            QCOMPARE(t->step(), HybridTest::StepResult::Advanced);
        const double s1 = lab->committedStroke(1), f0 = lab->committedForce(0);
        t->emergencyHold("operator");
        QCOMPARE(t->step(), HybridTest::StepResult::Held);
        QVERIFY(lab->holding());
        QCOMPARE(lab->committedStroke(1), s1);
        QCOMPARE(lab->actuator(1).law->trialDeformation(), s1);
        QCOMPARE(lab->committedForce(0), f0);
        QVERIFY(!lab->setTargets(Eigen::Vector2d(kP, s1 + 0.001)).ok);
        t->resume();
        QVERIFY(!lab->holding());
        QCOMPARE(runToStop(*t), HybridTest::StepResult::Finished);
        double peak = 0, du = 0;
        for (std::size_t i = 0; i < a.records.size(); ++i) {
            peak = std::max(peak, a.records[i].u.cwiseAbs().maxCoeff());
            du = std::max(du, (a.records[i].u - b.records[i].u).cwiseAbs().maxCoeff());
        }
        QCOMPARE(a.records.size(), b.records.size());
        QVERIFY(du <= 1e-9 * peak);
    }
};

QTEST_GUILESS_MAIN(TestExperimentalLink2d)
#include "TestExperimentalLink2d.moc"
