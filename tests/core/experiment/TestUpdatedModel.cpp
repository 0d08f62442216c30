// The updated model (core/experiment/HybridTest.h, docs/method.md "The updated model"): when a
// numerical element's parameters change during a test, K0, the damping matrix and the start's
// stability report are kept; the stability of the updated model is rechecked and a crossing of
// the explicit scheme's limit is a Warning alarm, not a hold.
// SDOF, m = 2 t, numerical linear spring k = 800 kN/m (omega = 20 rad/s), 5 % Rayleigh
// damping at mode 1, explicit Newmark (limit omega dt <= 2), dt = 0.05 s: omega dt = 1.
// Raising k five-fold gives omega = 20 sqrt(5) = 44.72 rad/s, omega dt = 2.236 > 2.

#include "core/experiment/HybridTest.h"
#include "tests/support/LawByName.h"
#include "core/hysteresis/LinearElastic.h"
#include "core/integration/ExplicitNewmark.h"
#include "core/structure/SpringElement.h"
#include "core/structure/Structure.h"

#include <QtTest>

#include <cmath>
#include <memory>

using namespace hsmu;

namespace {

std::unique_ptr<HybridTest> sdof() {
    auto s = std::make_unique<Structure>();
    s->addDof("DOF 1", 2.0);
    s->addElement(SpringElement::lateral("Spring", 0, std::make_unique<LinearElastic>(800.0)));
    s->setModalDamping(0.05, 1, 1);
    GroundMotion gm;
    gm.name = "pulse";
    gm.dt = 0.05;
    for (int i = 0; i <= 40; ++i)
        gm.acceleration.push_back(i < 5 ? 1.0 : 0.0);
    HybridTestOptions o;
    o.dt = 0.05;
    return std::make_unique<HybridTest>(std::move(s), std::make_unique<ExplicitNewmark>(), gm, o);
}

std::size_t stabilityAlarms(const HybridTest& t, AlarmSeverity severity) {
    std::size_t n = 0;
    for (const Alarm& a : t.alarms())
        n += a.kind == AlarmKind::Stability && a.severity == severity;
    return n;
}

} // namespace

class TestUpdatedModel : public QObject {
    Q_OBJECT
private slots:
    void keepsK0AndDampingAndWarnsOnACrossing() {
        auto t = sdof();
        QVERIFY(t->prepare());
        const double c0 = t->structure().damping().coeff(0, 0);
        QCOMPARE(t->stability().omegaMax, 20.0);
        QVERIFY(t->stability().stable);
        for (int i = 0; i < 5; ++i)
            QCOMPARE(t->step(), HybridTest::StepResult::Advanced);

        // An unchanged model: nothing to report.
        t->revisitUpdatedModel();
        QCOMPARE(t->alarms().size(), std::size_t(0));
        QCOMPARE(t->updatedStability().omegaMax, 20.0);

        // k x 5 (as an applied update would set it).
        HysteresisLaw* law = t->structure().elements()[0]->law();
        QVERIFY(test::setParameterNamed(*law, "k", 4000.0));
        t->revisitUpdatedModel();
        QVERIFY(std::abs(t->updatedStability().omegaMax - 20.0 * std::sqrt(5.0)) <
                1e-9 * 44.72);
        QVERIFY(!t->updatedStability().stable);
        QCOMPARE(stabilityAlarms(*t, AlarmSeverity::Warning), std::size_t(1));
        // Kept: K0, C, the start's report.
        QCOMPARE(t->structure().initialStiffness().coeff(0, 0), 800.0);
        QCOMPARE(t->structure().damping().coeff(0, 0), c0);
        QCOMPARE(t->stability().omegaMax, 20.0);
        QVERIFY(t->stability().stable);
        // Once per crossing; the test is not held.
        t->revisitUpdatedModel();
        QCOMPARE(stabilityAlarms(*t, AlarmSeverity::Warning), std::size_t(1));
        QCOMPARE(t->step(), HybridTest::StepResult::Advanced);
        QCOMPARE(t->state(), HybridTest::State::Running);

        // Back within the limit: an Info alarm.
        QVERIFY(test::setParameterNamed(*law, "k", 1000.0));
        t->revisitUpdatedModel();
        QVERIFY(t->updatedStability().stable);
        QCOMPARE(stabilityAlarms(*t, AlarmSeverity::Info), std::size_t(1));
        QVERIFY(std::abs(t->updatedStability().omegaMax - std::sqrt(500.0)) < 1e-9 * 22.4);
    }
};

QTEST_APPLESS_MAIN(TestUpdatedModel)
#include "TestUpdatedModel.moc"
