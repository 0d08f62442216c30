// Tests of the specimen simulated as a whole in its basic system behind its setup
// (core/experimental/CantileverColumn.h eq. W1-W3, SpecimenBehindSetup.h eq. W4) and of the
// per-channel actuator models of the virtual lab (ActuatorTracker.h), docs/setups.md "The
// specimen as a whole" and "Actuator models per channel". Units: kN, m, s, rad.

#include "core/experimental/VirtualActuatorLab.h"
#include "core/experimental/setup/NoTransformation.h"
#include "core/experimental/setup/PlanarSetups.h"
#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/LinearElastic.h"

#include <QtTest>

#include <cmath>

using namespace hsmu;

namespace {

constexpr double kL = 3.0, kEI = 2e5, kHinge = 1.6e5, kAxial = 2e5;

std::unique_ptr<HysteresisLaw> boucWenHinge() {
    BoucWenParameters p;
    p.alpha = 0.05;
    p.uRef = 0.001875; // [rad]
    p.fRef = 300.0;    // [kN m]: initial 1.6e5 kN m/rad
    return std::make_unique<BoucWen>(p);
}

std::unique_ptr<CantileverColumn> column(std::unique_ptr<HysteresisLaw> hinge) {
    return std::make_unique<CantileverColumn>(std::make_unique<LinearElastic>(kAxial),
                                              std::move(hinge), kL, kEI);
}

// Vertical actuator (force) on the axial DOF, lateral (displacement) on the shear DOF; the
// top rotation carries no actuator: a free top.
std::unique_ptr<VirtualActuatorLab> columnLab(std::unique_ptr<HysteresisLaw> hinge,
                                              ActuatorModel lateral = {}) {
    std::string error;
    auto setup = NoTransformation::create({1, 2}, 3, error);
    auto whole = std::make_unique<SpecimenBehindSetup>(
        std::move(setup), column(std::move(hinge)),
        std::vector<ActuatorMode>{ActuatorMode::Force, ActuatorMode::Displacement});
    std::vector<VirtualActuator> acts;
    acts.push_back({"vertical", ActuatorMode::Force, nullptr});
    acts.push_back({"lateral", ActuatorMode::Displacement, nullptr, lateral});
    return std::make_unique<VirtualActuatorLab>(std::move(acts), std::move(whole));
}

double freeTopStiffness() {
    return 1.0 / (kL * kL / kHinge + kL * kL * kL / (3.0 * kEI));
}

} // namespace

class TestWholeSpecimen : public QObject {
    Q_OBJECT

private slots:
    // A cantilever with an elastic hinge and a free top under a constant axial load P: the
    // lateral stiffness is k - P / L (P-Delta), k = 1 / (L^2 / k_h + L^3 / (3 EI)).
    void pDeltaLateralStiffnessClosedForm() {
        double worst = 0.0;
        for (double p : {0.0, 500.0, 2000.0, -800.0}) { // compression > 0; -800: tension
            auto lab = columnLab(std::make_unique<LinearElastic>(kHinge));
            QVERIFY(lab->prepare(0.01).ok);
            for (double d : {0.004, -0.02, 0.05}) {
                QVERIFY(lab->setTargets(Eigen::Vector2d(-p, d)).ok);
                Eigen::VectorXd s, f;
                QVERIFY(lab->measureChannels(s, f).ok);
                const double expected = (freeTopStiffness() - p / kL) * d;
                worst = std::max(worst, std::abs(f[1] - expected) / std::abs(expected));
                QVERIFY2(std::abs(f[1] - expected) <= 1e-9 * std::abs(expected),
                         qPrintable(
                             QString("P %1 d %2: %3 vs %4").arg(p).arg(d).arg(f[1]).arg(expected)));
                QVERIFY(std::abs(f[0] + p) <= 1e-12 * std::max(1.0, p));
                QVERIFY(std::abs(s[0] + p / kAxial) <= 1e-15 + 1e-12 * std::abs(p / kAxial));
                QVERIFY(std::abs(s[1] - d) <= 1e-15);
                // the free top carries no moment (eq. W4's third row)
                const auto& q = lab->wholeSpecimen()->specimen().trialForces();
                QVERIFY(std::abs(q[2]) <= 1e-9 * std::abs(expected) * kL);
                QVERIFY(lab->commit().ok);
            }
        }
        qInfo("k - P/L: worst relative error %.3g", worst);
    }

    // The stiffness an actuator sees (OpenFresco's element server, the lab's K0): k for the
    // lateral actuator at rest.
    void channelStiffnessAtRest() {
        auto lab = columnLab(std::make_unique<LinearElastic>(kHinge));
        QVERIFY(std::abs(lab->channelStiffness(1, true) - freeTopStiffness()) <=
                1e-12 * freeTopStiffness());
        QVERIFY(std::abs(lab->channelStiffness(0, true) - kAxial) <= 1e-12 * kAxial);
    }

    // A Bouc-Wen hinge behind an exact two-actuator setup (TwoActuators2d -nlGeom -phiLocX 90:
    // lateral at the top and on an arm, both displacement-controlled; the axial DOF free): the
    // strokes are the commands and the specimen's basic forces balance the actuators'
    // (q = J(d)^T f) along a cyclic history to large rotations.
    void boucWenHingeBehindExactSetupIsInEquilibrium() {
        std::string error;
        TwoActuators2dParams tp;
        tp.La1 = 1.5;
        tp.La2 = 1.2;
        tp.L = 0.6;
        tp.geometry = SetupGeometry::Exact;
        tp.phiLocX = 90.0;
        auto setup = makeTwoActuators2d(tp, error);
        QVERIFY2(setup, error.c_str());
        std::string e2;
        auto probe = makeTwoActuators2d(tp, e2);
        SpecimenBehindSetup whole(std::move(setup), column(boucWenHinge()),
                                  {ActuatorMode::Displacement, ActuatorMode::Displacement});
        whole.setTimeIncrement(0.01);
        double worstEq = 0.0, worstS = 0.0;
        for (int k = 1; k <= 60; ++k) {
            const double u = 0.06 * std::sin(0.2 * k), th = 0.05 * std::sin(0.2 * k + 0.5);
            Eigen::VectorXd d0 = Eigen::Vector3d(0.0, u, th), a;
            QVERIFY(probe->strokes(d0, a).ok);
            const std::string why = whole.solve(a);
            QVERIFY2(why.empty(), why.c_str());
            Eigen::MatrixXd j;
            const Eigen::VectorXd d = whole.basicDisplacements();
            QVERIFY(probe->jacobian(d, j).ok);
            const Eigen::Vector3d q = whole.specimen().trialForces();
            const Eigen::Vector3d jtf = j.transpose() * whole.forces();
            const double eq =
                (q - jtf).cwiseAbs().maxCoeff() / std::max(1.0, q.cwiseAbs().maxCoeff());
            QVERIFY(eq <= 1e-9);
            QVERIFY((whole.strokes() - a).cwiseAbs().maxCoeff() <= 1e-14);
            worstEq = std::max(worstEq, eq);
            worstS = std::max(worstS, (whole.strokes() - a).cwiseAbs().maxCoeff());
            whole.commit();
        }
        qInfo("exact setup: worst |q - J^T f| %.3g relative, worst |s - a| %.3g m; hinge %.4g rad",
              worstEq, worstS, whole.specimen().hingeRotation());
    }

    // A lag per channel: a step command c from rest reaches c (1 - exp(-n dt / tau)) after n
    // steps (the exact first-order response), on the whole-specimen lab and on a lab of one
    // material per actuator; a hold keeps the committed position.
    void lagChannelFirstOrderResponse() {
        ActuatorModel lag;
        lag.type = ActuatorModel::Type::Lag;
        lag.timeConstant = 0.05;
        const double dt = 0.01, c = 0.01;
        auto whole = columnLab(std::make_unique<LinearElastic>(kHinge), lag);
        std::vector<VirtualActuator> acts;
        acts.push_back({"vertical", ActuatorMode::Force, std::make_unique<LinearElastic>(kAxial)});
        acts.push_back(
            {"lateral", ActuatorMode::Displacement, std::make_unique<LinearElastic>(1e4), lag});
        VirtualActuatorLab perMaterial(std::move(acts));
        for (VirtualActuatorLab* lab : {whole.get(), &perMaterial}) {
            QVERIFY(lab->prepare(dt).ok);
            for (int n = 1; n <= 20; ++n) {
                QVERIFY(lab->setTargets(Eigen::Vector2d(-500.0, c)).ok);
                Eigen::VectorXd s, f;
                lab->measureChannels(s, f);
                const double expected = c * (1.0 - std::exp(-n * dt / lag.timeConstant));
                QVERIFY2(std::abs(s[1] - expected) <= 1e-15 + 1e-12 * expected,
                         qPrintable(QString("step %1: %2 vs %3").arg(n).arg(s[1]).arg(expected)));
                if (n == 10) { // a hold drops the trial; the resumed step is the same again
                    lab->hold("test");
                    QVERIFY(!lab->setTargets(Eigen::Vector2d(-500.0, c)).ok);
                    lab->resume();
                    QVERIFY(lab->setTargets(Eigen::Vector2d(-500.0, c)).ok);
                    lab->measureChannels(s, f);
                    QVERIFY(std::abs(s[1] - expected) <= 1e-15 + 1e-12 * expected);
                }
                QVERIFY(lab->commit().ok);
            }
        }
    }

    // A delay per channel: the stroke is the command of round(delay / dt) steps before.
    void delayChannel() {
        ActuatorModel delay;
        delay.type = ActuatorModel::Type::Delay;
        delay.delay = 0.03;
        auto lab = columnLab(std::make_unique<LinearElastic>(kHinge), delay);
        QVERIFY(lab->prepare(0.01).ok);
        for (int n = 1; n <= 10; ++n) {
            QVERIFY(lab->setTargets(Eigen::Vector2d(-500.0, 0.001 * n)).ok);
            Eigen::VectorXd s, f;
            lab->measureChannels(s, f);
            QCOMPARE(s[1], n > 3 ? 0.001 * (n - 3) : 0.0);
            QVERIFY(lab->commit().ok);
        }
    }

    // A servo-hydraulic actuator per channel: the lateral stroke is the servo-controlled plant's
    // position after dt of its loop toward the command (rths::ServoActuator, a standalone copy
    // advanced with the same commands as the reference), also across a hold and resume.
    void servoHydraulicChannel()
    {
        ActuatorModel servo;
        servo.type = ActuatorModel::Type::ServoHydraulic;
        auto lab = columnLab(std::make_unique<LinearElastic>(kHinge), servo);
        QVERIFY(lab->prepare(0.01).ok);
        rths::ServoActuator reference(servo.servo);
        reference.reset(0.0);
        double worstLag = 0.0;
        for (int n = 1; n <= 50; ++n) {
            const double c = 1e-4 * n;
            if (n == 20) { // a hold drops the trial: the servo starts the step again
                QVERIFY(lab->setTargets(Eigen::Vector2d(-500.0, c)).ok);
                lab->hold("test");
                lab->resume();
            }
            QVERIFY(lab->setTargets(Eigen::Vector2d(-500.0, c)).ok);
            Eigen::VectorXd s, f;
            lab->measureChannels(s, f);
            QCOMPARE(s[1], reference.advance(c, 0.01));
            worstLag = std::max(worstLag, std::abs(s[1] - c));
            QVERIFY(lab->commit().ok);
        }
        QVERIFY(worstLag > 0.0 && worstLag < 1e-3); // it tracks, with a tracking error
    }

    void errorsNameThePart() {
        auto message = [](auto&& make) {
            try {
                make();
            } catch (const std::invalid_argument& e) {
                return QString::fromStdString(e.what());
            }
            return QString();
        };
        QVERIFY(message([] {
                    CantileverColumn(std::make_unique<LinearElastic>(1.0),
                                     std::make_unique<LinearElastic>(1.0), kL, INFINITY);
                }).contains("ei"));
        QVERIFY(message([] {
                    CantileverColumn(std::make_unique<LinearElastic>(1.0),
                                     std::make_unique<LinearElastic>(1.0), 0.0, kEI);
                }).contains("length"));
        QString e = message([] {
            std::string error;
            SpecimenBehindSetup(NoTransformation::create({1, 2}, 2, error),
                                column(std::make_unique<LinearElastic>(kHinge)),
                                {ActuatorMode::Force, ActuatorMode::Displacement});
        });
        QVERIFY2(e.contains("NoTransformation serves 2 basic DOFs"), qPrintable(e));
        e = message([] {
            ActuatorModel servo;
            servo.type = ActuatorModel::Type::ServoHydraulic;
            std::vector<VirtualActuator> acts;
            acts.push_back(
                {"vertical", ActuatorMode::Force, std::make_unique<LinearElastic>(1.0), servo});
            VirtualActuatorLab lab(std::move(acts));
        });
        QVERIFY2(e.contains("'vertical'") && e.contains("servoHydraulic"), qPrintable(e));
        // No equilibrium: a hinge law that refuses (here: a NaN stroke) is a fault, nothing moves.
        auto lab = columnLab(std::make_unique<LinearElastic>(kHinge));
        QVERIFY(lab->prepare(0.01).ok);
        const ControlResult r = lab->setTargets(Eigen::Vector2d(-500.0, NAN));
        QVERIFY(!r.ok);
        QVERIFY2(QString::fromStdString(r.reason).contains("NoTransformation"), r.reason.c_str());
        QCOMPARE(lab->committedStroke(1), 0.0);
    }
};

QTEST_APPLESS_MAIN(TestWholeSpecimen)
#include "TestWholeSpecimen.moc"
