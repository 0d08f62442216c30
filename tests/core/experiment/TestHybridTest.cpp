// Tests of HybridTest (core/experiment/HybridTest.h), the step loop, on an SDOF frame whose
// spring is either numerical or a VirtualSpecimen behind a recording ExperimentalControl
// (a test double for the seam that forwards to the specimen and keeps every target).
// Units: kN, m, s, t. SDOF: m = 2 t, k = 800 kN/m (omega = 20 rad/s), 5 % damping.

#include "core/experimental/ExperimentalElement.h"
#include "core/experimental/VirtualSpecimen.h"
#include "core/hysteresis/LinearElastic.h"
#include "core/integration/AlphaOS.h"
#include "core/integration/ExplicitNewmark.h"
#include "core/structure/SpringElement.h"
#include "core/structure/Structure.h"
#include "core/experiment/HybridTest.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

using namespace hsmu;

namespace {

constexpr double kMass = 2.0, kStiff = 800.0;

class RecordingControl final : public ExperimentalControl {
public:
    RecordingControl(std::unique_ptr<VirtualSpecimen> inner, std::vector<double>& targets)
        : m_inner(std::move(inner)), m_targets(targets) {}
    std::string description() const override { return "recording " + m_inner->description(); }
    ControlResult prepare(double dt) override { return m_inner->prepare(dt); }
    ControlResult setTarget(double d) override {
        m_targets.push_back(d);
        return m_inner->setTarget(d);
    }
    ControlResult measure(ControlMeasurement& out) override {
        const ControlResult r = m_inner->measure(out);
        if (m_targets.size() > lieAfterTargets)
            out.deformation *= 30.0; // a controller reporting impossible deformations
        return r;
    }
    ControlResult commit() override { return m_inner->commit(); }
    void hold(const std::string& reason) override { m_inner->hold(reason); }
    void resume() override { m_inner->resume(); }
    std::size_t lieAfterTargets = ~std::size_t(0);

private:
    std::unique_ptr<VirtualSpecimen> m_inner;
    std::vector<double>& m_targets;
};

struct Recorder final : StepObserver {
    std::vector<StepRecord> records;
    void onStep(const StepRecord& r) override { records.push_back(r); }
};

// 4 s of a 2 Hz sine, 2 m/s^2, at 0.01 s.
GroundMotion sineRecord() {
    GroundMotion gm;
    gm.name = "sine";
    gm.dt = 0.01;
    for (int i = 0; i <= 400; ++i)
        gm.acceleration.push_back(2.0 * std::sin(2.0 * std::numbers::pi * 2.0 * i * gm.dt));
    return gm;
}

// SDOF with a numerical spring, or a specimen (elastic true law, ideal, no noise) whose
// targets are appended to *targets.
std::unique_ptr<Structure> sdof(std::vector<double>* targets, const SafetyLimits& limits = {},
                                const VirtualSpecimenOptions& options = {}) {
    auto s = std::make_unique<Structure>();
    s->addDof("DOF 1", kMass);
    if (targets) {
        auto specimen =
            std::make_unique<VirtualSpecimen>(std::make_unique<LinearElastic>(kStiff), options);
        s->addElement(std::make_unique<ExperimentalElement>(
            "Spring", "lateralSpring", std::vector<DofTerm>{{0, 1.0}},
            std::make_unique<RecordingControl>(std::move(specimen), *targets), limits, kStiff));
    } else {
        s->addElement(SpringElement::lateral("Spring", 0, std::make_unique<LinearElastic>(kStiff)));
    }
    s->setModalDamping(0.05, 1, 1);
    return s;
}

std::unique_ptr<HybridTest> makeTest(std::unique_ptr<Structure> s, double dt = 0.01,
                                     bool allowUnstable = false) {
    HybridTestOptions o;
    o.dt = dt;
    o.allowUnstable = allowUnstable;
    return std::make_unique<HybridTest>(std::move(s), std::make_unique<ExplicitNewmark>(),
                                        sineRecord(), o);
}

// Steps until the test stops advancing; returns the last result.
HybridTest::StepResult runToStop(HybridTest& t) {
    HybridTest::StepResult r;
    while ((r = t.step()) == HybridTest::StepResult::Advanced) {
    }
    return r;
}

// Bitwise equality of two histories (same arithmetic in the same order).
bool sameHistory(const std::vector<StepRecord>& a, const std::vector<StepRecord>& b, QString& why) {
    if (a.size() != b.size()) {
        why = QString("lengths %1 and %2").arg(a.size()).arg(b.size());
        return false;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].step != b[i].step || a[i].u != b[i].u || a[i].v != b[i].v || a[i].a != b[i].a ||
            a[i].elements[0].deformation != b[i].elements[0].deformation ||
            a[i].elements[0].force != b[i].elements[0].force) {
            why = QString("records differ at step %1: u %2 vs %3")
                      .arg(i)
                      .arg(a[i].u[0])
                      .arg(b[i].u[0]);
            return false;
        }
    }
    return true;
}

const Alarm* findAlarm(const HybridTest& t, AlarmKind kind) {
    for (const Alarm& a : t.alarms())
        if (a.kind == kind)
            return &a;
    return nullptr;
}

double referencePeak(const std::vector<StepRecord>& records) {
    double peak = 0.0;
    for (const auto& r : records)
        peak = std::max(peak, std::abs(r.u[0]));
    return peak;
}

} // namespace

class TestHybridTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void specimenRunEqualsNumericalRun();
    void observersGetEveryStep();
    void deformationLimitHoldsAndResumes();
    void operatorHoldAndResume();
    void forceLimitHolds();
    void impossibleMeasurementHoldsCritically();
    void specimenInterlockIsAControlFault();
    void refusesUnstableExplicitRun();
    void allowUnstableStartsWithWarning();
    void prepareFailures();

private:
    std::vector<StepRecord> m_reference; // all-numerical run
};

void TestHybridTest::initTestCase() {
    auto t = makeTest(sdof(nullptr));
    Recorder rec;
    t->addObserver(&rec);
    QVERIFY(t->prepare());
    QVERIFY(runToStop(*t) == HybridTest::StepResult::Finished);
    m_reference = rec.records;
    QCOMPARE(int(m_reference.size()), 401);
    double peak = 0.0;
    for (const auto& r : m_reference)
        peak = std::max(peak, std::abs(r.u[0]));
    QVERIFY2(peak > 0.005, qPrintable(QString::number(peak))); // a real response, ~1 cm
}

void TestHybridTest::specimenRunEqualsNumericalRun() {
    std::vector<double> targets;
    auto t = makeTest(sdof(&targets));
    Recorder rec;
    t->addObserver(&rec);
    QVERIFY2(t->prepare(), t->lastError().c_str());
    QVERIFY(runToStop(*t) == HybridTest::StepResult::Finished);
    QVERIFY(t->state() == HybridTest::State::Finished);
    QVERIFY(t->alarms().empty());
    // Same law, same arithmetic: identical step by step, bit for bit.
    QString why;
    QVERIFY2(sameHistory(rec.records, m_reference, why), qPrintable(why));
    QCOMPARE(int(targets.size()), 400); // one target per step
    for (std::size_t n = 1; n < rec.records.size(); ++n) {
        QCOMPARE(rec.records[n].elements[0].commanded, targets[n - 1]);
        QCOMPARE(rec.records[n].elements[0].commanded, rec.records[n].u[0]);
    }
}

void TestHybridTest::observersGetEveryStep() {
    std::vector<double> targets;
    auto t = makeTest(sdof(&targets));
    Recorder a, b;
    t->addObserver(&a);
    t->addObserver(&b);
    QVERIFY(t->prepare());
    QCOMPARE(t->totalSteps(), 400);
    for (int i = 0; i < 100; ++i)
        QVERIFY(t->step() == HybridTest::StepResult::Advanced);
    t->removeObserver(&b);
    QVERIFY(runToStop(*t) == HybridTest::StepResult::Finished);
    QVERIFY(t->step() == HybridTest::StepResult::Finished); // stays finished
    QCOMPARE(t->currentStep(), 400);
    QCOMPARE(int(a.records.size()), 401);
    QCOMPARE(int(b.records.size()), 101);
    const GroundMotion gm = sineRecord();
    for (int n = 0; n <= 400; ++n) {
        const StepRecord& r = a.records[n];
        QCOMPARE(r.step, n);
        QVERIFY(std::abs(r.time - n * 0.01) < 1e-12);
        QCOMPARE(r.groundAcceleration, gm.acceleration[n]);
        QCOMPARE(int(r.elements.size()), 1);
    }
    QCOMPARE(a.records[0].u[0], 0.0);
    QCOMPARE(a.records[0].elements[0].commanded, 0.0);
    // A numerical element has no commanded deformation.
    QVERIFY(std::isnan(m_reference[10].elements[0].commanded));
}

void TestHybridTest::deformationLimitHoldsAndResumes() {
    SafetyLimits limits;
    limits.maxDeformation = 0.3 * referencePeak(m_reference); // reached early in the run
    std::vector<double> targets;
    auto t = makeTest(sdof(&targets, limits));
    Recorder rec;
    t->addObserver(&rec);
    QVERIFY(t->prepare());
    QVERIFY(runToStop(*t) == HybridTest::StepResult::Held);
    QVERIFY(t->state() == HybridTest::State::Holding);
    const int heldAt = t->currentStep();
    QVERIFY(heldAt > 0 && heldAt < 400);

    const Alarm* alarm = findAlarm(*t, AlarmKind::LimitExceeded);
    QVERIFY(alarm != nullptr);
    QVERIFY(alarm->severity == AlarmSeverity::Critical);
    QCOMPARE(alarm->step, heldAt);
    const QString msg = QString::fromStdString(alarm->message);
    QVERIFY2(msg.contains("Spring") && msg.contains(QString::number(limits.maxDeformation, 'g', 6)),
             qPrintable(msg));
    // Nothing past the limit ever reached the control.
    for (double d : targets)
        QVERIFY2(std::abs(d) <= limits.maxDeformation, qPrintable(QString::number(d)));
    QCOMPARE(int(targets.size()), heldAt);
    // Held: no more steps, and every committed step was published.
    for (int i = 0; i < 3; ++i)
        QVERIFY(t->step() == HybridTest::StepResult::Held);
    QCOMPARE(t->currentStep(), heldAt);
    QCOMPARE(int(rec.records.size()), heldAt + 1);
    QCOMPARE(rec.records.back().step, heldAt);

    // The operator raises the limit and resumes: the run completes as if never held.
    auto* element = dynamic_cast<ExperimentalElement*>(t->structure().element("Spring"));
    QVERIFY(element != nullptr);
    element->setLimits(SafetyLimits{});
    t->resume();
    QVERIFY(t->state() == HybridTest::State::Running);
    QVERIFY(runToStop(*t) == HybridTest::StepResult::Finished);
    QString why;
    QVERIFY2(sameHistory(rec.records, m_reference, why), qPrintable(why));
}

void TestHybridTest::forceLimitHolds() {
    SafetyLimits limits;
    limits.maxForce = 0.3 * kStiff * referencePeak(m_reference); // [kN]
    std::vector<double> targets;
    auto t = makeTest(sdof(&targets, limits));
    Recorder rec;
    t->addObserver(&rec);
    QVERIFY(t->prepare());
    QVERIFY(runToStop(*t) == HybridTest::StepResult::Held);
    const Alarm* alarm = findAlarm(*t, AlarmKind::LimitExceeded);
    QVERIFY(alarm != nullptr);
    const QString msg = QString::fromStdString(alarm->message);
    QVERIFY2(msg.contains("Spring") && msg.contains("force") &&
                 msg.contains(QString::number(limits.maxForce, 'g', 6)),
             qPrintable(msg));
    QCOMPARE(int(rec.records.size()), t->currentStep() + 1);
    for (const auto& r : rec.records) // no committed step carries a force past the limit
        QVERIFY(std::abs(r.elements[0].force) <= limits.maxForce);
}

void TestHybridTest::impossibleMeasurementHoldsCritically() {
    // From the 101st target on the control reports 30 times the true deformation (far past
    // the limit): the test holds with a critical alarm naming the element and the value, and
    // nothing from such a sample is committed or published.
    SafetyLimits limits;
    limits.maxDeformation = 2.0 * referencePeak(m_reference);
    std::vector<double> targets;
    auto s = sdof(&targets, limits);
    auto* x = static_cast<ExperimentalElement*>(s->elements()[0].get());
    static_cast<RecordingControl&>(x->control()).lieAfterTargets = 100;
    auto t = makeTest(std::move(s));
    Recorder rec;
    t->addObserver(&rec);
    QVERIFY(t->prepare());
    for (int i = 0; i < 400 && t->step() == HybridTest::StepResult::Advanced; ++i) {
    }
    QVERIFY(t->state() == HybridTest::State::Holding);
    QCOMPARE(t->currentStep(), 100);
    const Alarm* alarm = findAlarm(*t, AlarmKind::LimitExceeded);
    QVERIFY(alarm != nullptr);
    QCOMPARE(alarm->severity, AlarmSeverity::Critical);
    const QString msg = QString::fromStdString(alarm->message);
    QVERIFY2(msg.contains("Spring") && msg.contains("measured deformation |d| ="), qPrintable(msg));
    QCOMPARE(int(rec.records.size()), 101);
    for (const auto& r : rec.records)
        QVERIFY(std::abs(r.elements[0].deformation) <= limits.maxDeformation);
}

void TestHybridTest::specimenInterlockIsAControlFault() {
    // The element's limits let the target through; the lab controller's interlock refuses it.
    VirtualSpecimenOptions options;
    options.interlock.maxDeformation = 0.3 * referencePeak(m_reference);
    std::vector<double> targets;
    auto t = makeTest(sdof(&targets, {}, options));
    QVERIFY(t->prepare());
    QVERIFY(runToStop(*t) == HybridTest::StepResult::Held);
    QVERIFY(t->state() == HybridTest::State::Holding);
    const Alarm* alarm = findAlarm(*t, AlarmKind::ControlFault);
    QVERIFY(alarm != nullptr);
    QVERIFY(findAlarm(*t, AlarmKind::LimitExceeded) == nullptr);
    QVERIFY2(QString::fromStdString(alarm->message).contains("interlock"), alarm->message.c_str());
    QCOMPARE(int(targets.size()), t->currentStep() + 1); // the refused one reached the control
}

void TestHybridTest::operatorHoldAndResume() {
    std::vector<double> targets;
    auto t = makeTest(sdof(&targets));
    Recorder rec;
    t->addObserver(&rec);
    QVERIFY(t->prepare());
    for (int i = 0; i < 150; ++i)
        t->step();
    t->hold("operator checks the specimen");
    QVERIFY(t->state() == HybridTest::State::Holding);
    QVERIFY(t->step() == HybridTest::StepResult::Held);
    QCOMPARE(t->currentStep(), 150);
    QCOMPARE(int(targets.size()), 150);
    const Alarm* alarm = findAlarm(*t, AlarmKind::OperatorHold);
    QVERIFY(alarm != nullptr);
    QVERIFY2(QString::fromStdString(alarm->message).contains("operator checks the specimen"),
             alarm->message.c_str());
    t->resume();
    QVERIFY(runToStop(*t) == HybridTest::StepResult::Finished);
    QString why;
    QVERIFY2(sameHistory(rec.records, m_reference, why), qPrintable(why));
}

void TestHybridTest::refusesUnstableExplicitRun() {
    // omega dt = 20 * 0.105 = 2.1 > 2; the largest stable dt is 0.1 s.
    auto t = makeTest(sdof(nullptr), 0.105);
    QVERIFY(!t->prepare());
    QVERIFY(t->state() == HybridTest::State::Failed);
    const QString msg = QString::fromStdString(t->lastError());
    QVERIFY2(msg.contains("unstable") && msg.contains("0.1 s"), qPrintable(msg));
    QVERIFY(!t->stability().stable);
    QVERIFY(t->step() == HybridTest::StepResult::NotReady);

    // alpha-OS is unconditionally stable: the same model and dt start without an alarm.
    HybridTestOptions o;
    o.dt = 0.105;
    HybridTest alpha(sdof(nullptr), std::make_unique<AlphaOS>(-0.05), sineRecord(), o);
    QVERIFY2(alpha.prepare(), alpha.lastError().c_str());
    QVERIFY(alpha.alarms().empty());
}

void TestHybridTest::allowUnstableStartsWithWarning() {
    auto t = makeTest(sdof(nullptr), 0.105, /*allowUnstable=*/true);
    QVERIFY2(t->prepare(), t->lastError().c_str());
    QVERIFY(t->state() == HybridTest::State::Ready);
    QCOMPARE(int(t->alarms().size()), 1);
    const Alarm& a = t->alarms().front();
    QVERIFY(a.kind == AlarmKind::Stability);
    QVERIFY(a.severity == AlarmSeverity::Warning);
    QVERIFY2(QString::fromStdString(a.message).contains("unstable"), a.message.c_str());
    QVERIFY(t->step() == HybridTest::StepResult::Advanced);
}

void TestHybridTest::prepareFailures() {
    for (double dt : {0.0, -0.01, std::numeric_limits<double>::quiet_NaN()}) {
        auto t = makeTest(sdof(nullptr), dt);
        QVERIFY(!t->prepare());
        QVERIFY(t->state() == HybridTest::State::Failed);
        QVERIFY2(QString::fromStdString(t->lastError()).contains("dt"), t->lastError().c_str());
        QVERIFY(t->step() == HybridTest::StepResult::NotReady);
    }
    GroundMotion tooShort;
    tooShort.dt = 0.01;
    tooShort.acceleration = {0.0};
    HybridTest shortRecord(sdof(nullptr), std::make_unique<ExplicitNewmark>(), tooShort, {});
    QVERIFY(!shortRecord.prepare());
    QVERIFY(!shortRecord.lastError().empty());

    auto s = sdof(nullptr);
    s->addEqualDof(0, 3); // bad DOF index: finalize() throws, prepare() reports
    auto bad = makeTest(std::move(s));
    QVERIFY(!bad->prepare());
    QVERIFY2(QString::fromStdString(bad->lastError()).contains("DOF index 3"),
             bad->lastError().c_str());

    auto twice = makeTest(sdof(nullptr));
    QVERIFY(twice->prepare());
    QVERIFY(!twice->prepare());
}

QTEST_APPLESS_MAIN(TestHybridTest)
#include "TestHybridTest.moc"
