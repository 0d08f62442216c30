// The by-position parameter paths of core/updating (names resolved once, one setParameters per
// law per step) against the by-name paths they replace, bit for bit:
//  - HysteresisLaw::setParameterValues (BoucWen's override, and the base's for Bilinear)
//    equals successive setParameter calls, refusals and all-or-nothing restores included;
//  - Reporter::offerValues equals Reporter::offer on twin structures, for every policy;
//  - a whole updated run of the condition-3 frame whose identifier only has the by-name
//    interface (the base class's map-based estimateValues etc.) records exactly what the
//    UkfIdentifier's own by-position overrides give.
#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/config/UpdatingConfig.h"
#include "core/hysteresis/Bilinear.h"
#include "core/hysteresis/BoucWen.h"
#include "core/structure/Structure.h"
#include "core/experiment/HybridTest.h"
#include "core/updating/ModelUpdater.h"
#include "core/updating/Reporter.h"
#include "core/updating/UkfIdentifier.h"

#include <QtTest>

#include <cmath>
#include <cstring>
#include <memory>

using namespace hsmu;

namespace {

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

/// A degrading Bouc-Wen law in normalized units (k0, alpha, n, beta, gamma, A0, deltaA, deltaNu,
/// deltaEta, uRef, fRef).
BoucWenParameters specimen() {
    return {1.0, 0.03, 2.0, 2.5, 0.5, 1.0, 0.0, 0.03, 0.03, 0.02, 20.0};
}

/// Same parameters, committed deformation, force and trial force, bit for bit.
bool sameLaw(const HysteresisLaw& a, const HysteresisLaw& b) {
    for (const auto& n : a.parameterNames())
        if (!sameBits(*a.parameter(n), *b.parameter(n)))
            return false;
    return sameBits(a.committedForce(), b.committedForce()) &&
           sameBits(a.committedDeformation(), b.committedDeformation()) &&
           sameBits(a.trialForce(), b.trialForce());
}

/// The by-name reference of setParameterValues (the contract in HysteresisLaw.h).
int byName(HysteresisLaw& law, const std::vector<std::string>& names,
           const std::vector<double>& values, bool allOrNothing) {
    std::map<std::string, double> old;
    for (const auto& n : names)
        if (auto v = law.parameter(n))
            old[n] = *v;
    int first = -1;
    for (std::size_t k = 0; k < names.size(); ++k) {
        if (law.setParameter(names[k], values[k]))
            continue;
        if (first < 0)
            first = int(k);
        if (allOrNothing) {
            for (const auto& [n, o] : old)
                law.setParameter(n, o);
            return first;
        }
    }
    return first;
}

/// Records everything a step publishes.
struct Recorder final : StepObserver {
    std::vector<StepRecord> steps;
    void onStep(const StepRecord& r) override { steps.push_back(r); }
};

/// A real UKF behind the by-name interface only: the base class's map-based by-position
/// defaults run instead of UkfIdentifier's overrides.
class ByNameOnly final : public Identifier {
public:
    explicit ByNameOnly(std::unique_ptr<Identifier> inner) : m(std::move(inner)) {}
    std::string methodName() const override { return m->methodName(); }
    std::vector<std::string> parameterNames() const override { return m->parameterNames(); }
    IdentificationStatus observe(double d, double f, bool u) override {
        return m->observe(d, f, u);
    }
    ParameterValues estimate() const override { return m->estimate(); }
    ParameterValues standardDeviation() const override { return m->standardDeviation(); }
    double predictedForce() const override { return m->predictedForce(); }
    const ParameterBoundsMap& bounds() const override { return m->bounds(); }
    bool setBounds(const std::string& n, const ParameterBounds& b) override {
        return m->setBounds(n, b);
    }

private:
    std::unique_ptr<Identifier> m;
};

TestConfig condition3(ReporterPolicy policy) {
    TestConfig cfg =
        loadConfigFile(std::string(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json");
    cfg.analysis.duration = 8.0; // the synthetic record: yielding, updates, zero crossings
    cfg.updating.policy = policy;
    cfg.updating.everyN = 7;
    return cfg;
}

std::unique_ptr<HybridTest> build(const TestConfig& cfg, bool byNameOnly, Recorder& rec) {
    auto test = buildHybridTest(cfg);
    if (byNameOnly) {
        const UpdatingSpec& u = cfg.updating;
        auto aux = buildLaw(cfg.elements[0].material, "test");
        auto ukf = buildIdentifier(u, *aux, cfg.analysis.dt, "test");
        test->setUpdater(std::make_unique<ModelUpdater>(
            u.specimen, std::move(aux), std::make_unique<ByNameOnly>(std::move(ukf)), u.inspector,
            std::make_unique<Reporter>(u.targets, u.policy, u.everyN)));
    }
    test->addObserver(&rec);
    return test;
}

} // namespace

class TestParameterVectors : public QObject {
    Q_OBJECT
private slots:
    void boucWenSetParameterValuesEqualsSuccessiveSetParameter() {
        // Admissible values; a beta refused with the old gamma (beta + gamma <= 0) that the
        // new gamma would have made admissible; a NaN; alpha > 1; an unknown name.
        const std::vector<std::string> names{"alpha", "beta", "gamma", "k0", "n"};
        const std::vector<std::string> withUnknown{"alpha", "beta", "nonsense", "k0"};
        struct Case {
            const std::vector<std::string>* names;
            std::vector<double> values;
            int refused; // the first refused position
        };
        const std::vector<Case> cases{{&names, {0.02, 3.1, 0.7, 1.2, 1.5}, -1},
                                      {&names, {0.02, -0.8, 1.0, 1.2, 1.5}, 1},
                                      {&names, {0.02, 3.1, NAN, 1.2, 1.5}, 2},
                                      {&names, {1.5, 3.1, 0.7, 1.2, 1.5}, 0},
                                      {&withUnknown, {0.02, 3.1, 7.0, 1.2}, 2}};
        for (bool allOrNothing : {false, true}) {
            for (const Case& c : cases) {
                BoucWen a(specimen()), b(specimen());
                std::vector<int> indices;
                for (const auto& n : *c.names)
                    indices.push_back(a.parameterIndex(n));
                for (BoucWen* law : {&a, &b}) {
                    law->setTrialDeformation(0.03);
                    law->commit();
                    law->setTrialDeformation(0.025); // a pending trial
                }
                const double before = a.committedForce();
                if (allOrNothing && c.refused == 1) {
                    // judged as one set (BoucWen.h): beta -0.8 with the new gamma 1.0 is
                    // admissible although beta -0.8 with the old gamma is not
                    QCOMPARE(a.setParameterValues(indices, c.values, allOrNothing), -1);
                    QCOMPARE(*a.parameter("beta"), -0.8);
                    QCOMPARE(*a.parameter("gamma"), 1.0);
                    continue;
                }
                QCOMPARE(a.setParameterValues(indices, c.values, allOrNothing), c.refused);
                QCOMPARE(byName(b, *c.names, c.values, allOrNothing), c.refused);
                QVERIFY(sameLaw(a, b));
                if (c.refused < 0) // applied: the force follows the new parameters
                    QVERIFY(a.committedForce() != before);
            }
        }
    }

    void baseSetParameterValuesEqualsSuccessiveSetParameter() {
        const std::vector<std::string> names{"b", "fy", "k0"};
        for (bool allOrNothing : {false, true}) {
            for (const std::vector<double>& values :
                 {std::vector<double>{0.2, 1.5, 3.0}, std::vector<double>{0.2, -1.0, 3.0}}) {
                Bilinear a(BilinearParameters{2.0, 1.0, 0.1}), b(BilinearParameters{2.0, 1.0, 0.1});
                std::vector<int> indices;
                for (const auto& n : names)
                    indices.push_back(a.parameterIndex(n));
                for (Bilinear* law : {&a, &b}) {
                    law->setTrialDeformation(0.9);
                    law->commit();
                }
                const int expected = values[1] < 0 ? 1 : -1;
                QCOMPARE(a.setParameterValues(indices, values, allOrNothing), expected);
                QCOMPARE(byName(b, names, values, allOrNothing), expected);
                QVERIFY(sameLaw(a, b));
            }
        }
    }

    void wholeRunByPositionEqualsByName_data() {
        QTest::addColumn<int>("policy");
        QTest::newRow("everyStep") << int(ReporterPolicy::EveryStep);
        QTest::newRow("zeroCrossing") << int(ReporterPolicy::ZeroCrossing);
        QTest::newRow("everyNSteps") << int(ReporterPolicy::EveryNSteps);
    }

    void wholeRunByPositionEqualsByName() {
        QFETCH(int, policy);
        const TestConfig cfg = condition3(static_cast<ReporterPolicy>(policy));
        Recorder fast, slow;
        auto a = build(cfg, false, fast);
        auto b = build(cfg, true, slow);
        QCOMPARE(b->updater()->identifier().methodName(), std::string("UKF"));
        QVERIFY(a->prepare());
        QVERIFY(b->prepare());
        while (a->step() == HybridTest::StepResult::Advanced) {
        }
        while (b->step() == HybridTest::StepResult::Advanced) {
        }
        QVERIFY(fast.steps.size() > 500);
        QCOMPARE(fast.steps.size(), slow.steps.size());
        int applied = 0;
        for (std::size_t k = 0; k < fast.steps.size(); ++k) {
            const StepRecord &x = fast.steps[k], &y = slow.steps[k];
            for (Eigen::Index i = 0; i < x.u.size(); ++i)
                QVERIFY(sameBits(x.u[i], y.u[i]) && sameBits(x.a[i], y.a[i]));
            for (std::size_t e = 0; e < x.elements.size(); ++e)
                QVERIFY(sameBits(x.elements[e].force, y.elements[e].force));
            QCOMPARE(x.updating.parameters.size(), std::size_t(7));
            QCOMPARE(x.updating.parameters.size(), y.updating.parameters.size());
            for (std::size_t i = 0; i < x.updating.parameters.size(); ++i)
                QVERIFY(sameBits(x.updating.parameters[i], y.updating.parameters[i]) &&
                        sameBits(x.updating.stddev[i], y.updating.stddev[i]));
            QVERIFY(sameBits(x.updating.auxiliaryForce, y.updating.auxiliaryForce));
            QVERIFY(sameBits(x.updating.fitError, y.updating.fitError));
            QCOMPARE(x.updating.appliedUpdates, y.updating.appliedUpdates);
            applied = x.updating.appliedUpdates;
        }
        QVERIFY(applied > 10); // the targets were updated
        QCOMPARE(a->alarms().size(), b->alarms().size());
    }
};

QTEST_APPLESS_MAIN(TestParameterVectors)
#include "TestParameterVectors.moc"
