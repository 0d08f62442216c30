// Tests of ExperimentalElement (core/experimental/ExperimentalElement.h): its target is the
// generalized deformation q = sum c_k u_k, its force the measured one, and a target past its
// safety limits never reaches the control. A recording ExperimentalControl (a test double
// for the seam) keeps every target it receives.

#include "core/experimental/ExperimentalElement.h"

#include <QtTest>

#include <cmath>
#include <memory>
#include <optional>
#include <vector>

using namespace hsmu;

namespace {

// Records every call; answers like an elastic specimen F = k d; can be told to fault.
struct Log {
    std::vector<double> targets;
    int commits = 0;
    bool held = false;
};

class RecordingControl final : public ExperimentalControl {
public:
    RecordingControl(double k, Log& log) : m_k(k), m_log(log) {}
    std::string description() const override { return "recording control"; }
    ControlResult prepare(double) override { return ControlResult::success(); }
    ControlResult setTarget(double d) override {
        m_log.targets.push_back(d);
        m_d = d;
        return failNext ? ControlResult::fault("actuator fault") : ControlResult::success();
    }
    ControlResult measure(ControlMeasurement& out) override {
        out = {reportDeformation.value_or(m_d), m_k * m_d};
        return ControlResult::success();
    }
    ControlResult commit() override {
        ++m_log.commits;
        return ControlResult::success();
    }
    void hold(const std::string&) override { m_log.held = true; }
    void resume() override { m_log.held = false; }
    bool failNext = false;
    std::optional<double> reportDeformation; ///< a lying sensor: reported instead of the target

private:
    double m_k, m_d = 0.0;
    Log& m_log;
};

constexpr double kHeight = 3.0;   // [m] rigid column: q = theta = u / L
constexpr double kKTheta = 900.0; // [kN m / rad]

std::unique_ptr<ExperimentalElement> makeElement(const SafetyLimits& limits, Log& log,
                                                 RecordingControl** control = nullptr) {
    auto c = std::make_unique<RecordingControl>(kKTheta, log);
    if (control)
        *control = c.get();
    return std::make_unique<ExperimentalElement>("Element 1", "rotationalBaseSpring",
                                                 std::vector<DofTerm>{{0, 1.0 / kHeight}},
                                                 std::move(c), limits, kKTheta);
}

Eigen::VectorXd at(double u) {
    return Eigen::VectorXd::Constant(1, u);
}

} // namespace

class TestExperimentalElement : public QObject {
    Q_OBJECT
private slots:
    void targetIsGeneralizedDeformation();
    void neverSendsPastTheDeformationLimit();
    void neverSendsPastTheIncrementLimit();
    void forceLimitFailsTheTrial();
    void impossibleMeasuredDeformationFailsTheTrial();
    void controlFaultIsReported();
    void revertForgetsTheUnacceptedReading();
    void raisedLimitsTakeEffect();
};

void TestExperimentalElement::targetIsGeneralizedDeformation() {
    Log log;
    auto e = makeElement({}, log);
    QVERIFY(e->isExperimental());
    QCOMPARE(QString::fromStdString(e->typeName()), QString("rotationalBaseSpring"));
    QCOMPARE(e->initialGeneralizedStiffness(), kKTheta);
    QVERIFY(e->setTrial(at(0.06)).ok);
    QCOMPARE(int(log.targets.size()), 1);
    QVERIFY(std::abs(log.targets[0] - 0.02) < 1e-17); // theta = u / L
    QCOMPARE(e->commandedDeformation(), log.targets[0]);
    QCOMPARE(e->deformation(), log.targets[0]);
    QCOMPARE(e->force(), kKTheta * log.targets[0]);
    QCOMPARE(e->generalizedForce(), e->force());
    Eigen::VectorXd r = Eigen::VectorXd::Zero(1);
    e->addNodalForces(r);
    QVERIFY(std::abs(r[0] - kKTheta * 0.02 / kHeight) < 1e-12); // lateral force M / L
    QVERIFY(e->commit().ok);
    QCOMPARE(log.commits, 1);
}

void TestExperimentalElement::neverSendsPastTheDeformationLimit() {
    SafetyLimits limits;
    limits.maxDeformation = 0.02; // [rad]
    Log log;
    auto e = makeElement(limits, log);
    int refused = 0;
    // A ramp of the top displacement to 0.09 m (theta 0.03 rad) and back, in 1 mm steps.
    for (int i = 1; i <= 180; ++i) {
        const double u = 0.001 * (i <= 90 ? i : 180 - i);
        const ElementStatus s = e->setTrial(at(u));
        if (s.ok) {
            QVERIFY(e->commit().ok);
            continue;
        }
        ++refused;
        QVERIFY(s.limit); // a safety limit, not a fault
        const QString msg = QString::fromStdString(s.message);
        QVERIFY2(msg.contains("Element 1") && msg.contains("deformation") && msg.contains("0.02") &&
                     msg.contains("limit"),
                 qPrintable(msg));
        QVERIFY(e->targetViolation(Eigen::VectorXd::Constant(1, u)).has_value());
        e->revert();
    }
    QVERIFY2(refused > 0, "the history never reached the limit: the test is too weak");
    for (double d : log.targets)
        QVERIFY2(std::abs(d) <= limits.maxDeformation, qPrintable(QString::number(d)));
    QVERIFY(std::abs(e->commandedDeformation()) <= limits.maxDeformation);
}

void TestExperimentalElement::neverSendsPastTheIncrementLimit() {
    SafetyLimits limits;
    limits.maxIncrement = 0.002; // [rad] per step, measured from the last committed target
    Log log;
    auto e = makeElement(limits, log);
    // Steps of 1, 3, 9 mm (theta 0.00033, 0.001, 0.003): the 9 mm one must be refused.
    double u = 0.0;
    for (double du : {0.001, 0.003, 0.009, 0.003}) {
        const ElementStatus s = e->setTrial(at(u + du));
        if (du == 0.009) {
            QVERIFY(!s.ok);
            QVERIFY(s.limit);
            const QString msg = QString::fromStdString(s.message);
            QVERIFY2(msg.contains("Element 1") && msg.contains("increment") &&
                         msg.contains("0.002"),
                     qPrintable(msg));
            e->revert();
            continue;
        }
        QVERIFY2(s.ok, s.message.c_str());
        QVERIFY(e->commit().ok);
        u += du;
    }
    QCOMPARE(int(log.targets.size()), 3);
    double last = 0.0;
    for (double d : log.targets) {
        QVERIFY2(std::abs(d - last) <= limits.maxIncrement, qPrintable(QString::number(d)));
        last = d;
    }
}

void TestExperimentalElement::forceLimitFailsTheTrial() {
    SafetyLimits limits;
    limits.maxForce = 15.0; // [kN m]: reached at theta = 15 / 900 = 0.0167 rad
    Log log;
    auto e = makeElement(limits, log);
    QVERIFY(e->setTrial(at(0.045)).ok); // M = 13.5
    QVERIFY(e->commit().ok);
    const ElementStatus s = e->setTrial(at(0.054)); // M = 16.2
    QVERIFY(!s.ok);
    QVERIFY(s.limit);
    const QString msg = QString::fromStdString(s.message);
    QVERIFY2(msg.contains("Element 1") && msg.contains("force") && msg.contains("15"),
             qPrintable(msg));
}

void TestExperimentalElement::impossibleMeasuredDeformationFailsTheTrial() {
    // A controller reporting 5 rad (limit 0.15) for a 0.01 rad target: a limit, named.
    SafetyLimits limits;
    limits.maxDeformation = 0.15;
    Log log;
    RecordingControl* control = nullptr;
    auto e = makeElement(limits, log, &control);
    control->reportDeformation = 0.155; // inside the 5 % tolerance
    QVERIFY(e->setTrial(at(0.03)).ok);
    QVERIFY(e->commit().ok);
    control->reportDeformation = 5.0;
    ElementStatus s = e->setTrial(at(0.03));
    QVERIFY(!s.ok);
    QVERIFY(s.limit);
    QString msg = QString::fromStdString(s.message);
    QVERIFY2(msg.contains("Element 1") && msg.contains("measured deformation |d| = 5 ") &&
                 msg.contains("0.15"),
             qPrintable(msg));
    control->reportDeformation = 0.1576; // just past 0.15 * 1.05
    QVERIFY(e->setTrial(at(0.03)).limit);
    for (const double bad : {std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity()}) {
        control->reportDeformation = bad;
        s = e->setTrial(at(0.03));
        QVERIFY(s.limit);
        QVERIFY2(QString::fromStdString(s.message).contains("not a finite"), s.message.c_str());
    }
    QCOMPARE(log.commits, 1); // nothing past the first step was committed
}

void TestExperimentalElement::controlFaultIsReported() {
    Log log;
    RecordingControl* control = nullptr;
    auto e = makeElement({}, log, &control);
    control->failNext = true;
    const ElementStatus s = e->setTrial(at(0.01));
    QVERIFY(!s.ok);
    QVERIFY(!s.limit); // a fault, not a limit
    QVERIFY2(QString::fromStdString(s.message).contains("Element 1: actuator fault"),
             s.message.c_str());
}

void TestExperimentalElement::revertForgetsTheUnacceptedReading() {
    Log log;
    auto e = makeElement({}, log);
    QVERIFY(e->setTrial(at(0.03)).ok);
    QVERIFY(e->commit().ok);
    const double committedForce = e->force();
    QVERIFY(e->setTrial(at(0.06)).ok);
    QVERIFY(e->force() != committedForce);
    e->revert();
    QCOMPARE(e->force(), committedForce);
    QVERIFY(std::abs(e->commandedDeformation() - 0.01) < 1e-17);
}

void TestExperimentalElement::raisedLimitsTakeEffect() {
    SafetyLimits limits;
    limits.maxDeformation = 0.01;
    Log log;
    auto e = makeElement(limits, log);
    QVERIFY(!e->setTrial(at(0.045)).ok); // theta 0.015
    QVERIFY(log.targets.empty());
    limits.maxDeformation = 0.02;
    e->setLimits(limits);
    QCOMPARE(e->limits().maxDeformation, 0.02);
    QVERIFY(e->setTrial(at(0.045)).ok);
    QCOMPARE(int(log.targets.size()), 1);
}

QTEST_APPLESS_MAIN(TestExperimentalElement)
#include "TestExperimentalElement.moc"
