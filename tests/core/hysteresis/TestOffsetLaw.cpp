// Tests of OffsetLaw (core/hysteresis/OffsetLaw.h) and of the offsets LawFactory gives every
// law: F(u) = F_law(u - u0) + F0 with the law's own tangent, against the same law driven
// along the shifted history (an independent evaluation of the definition), the two trailing
// parameters, their admissibility and what a refused set leaves.

#include "core/hysteresis/OffsetLaw.h"

#include "core/hysteresis/LawFactory.h"
#include "tests/core/hysteresis/LawTestSupport.h"
#include "tests/support/LawByName.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace hsmu;

class TestOffsetLaw : public QObject {
    Q_OBJECT

private slots:
    /// Every law: the offset law's force along u is the law's along u - u0 plus F0, bit for
    /// bit, and its tangents are the law's.
    void shiftsEveryLawByItsOffsets() {
        const double u0 = 0.013, f0 = -0.21;
        const std::vector<double> u = testsupport::sineHistory(0.6, 3, 80);
        for (const std::string& name : knownLaws()) {
            const auto plain = makeLaw(name, {});
            const auto shifted =
                makeLaw(name, {{"deformationOffset", u0}, {"forceOffset", f0}});
            QCOMPARE(shifted->lawName(), name);
            plain->setTimeIncrement(0.01);
            shifted->setTimeIncrement(0.01);
            QCOMPARE(shifted->isRateDependent(), plain->isRateDependent());
            for (const double x : u) {
                QCOMPARE(plain->setTrialDeformation(x - u0), LawStatus::Ok);
                QCOMPARE(shifted->setTrialDeformation(x), LawStatus::Ok);
                QCOMPARE(shifted->trialForce(), plain->trialForce() + f0);
                QCOMPARE(shifted->trialTangent(), plain->trialTangent());
                QCOMPARE(shifted->algorithmicTangent(), plain->algorithmicTangent());
                QCOMPARE(shifted->trialDeformation(), (x - u0) + u0);
                plain->commit();
                shifted->commit();
                QCOMPARE(shifted->committedForce(), plain->committedForce() + f0);
            }
            QCOMPARE(shifted->initialTangent(), plain->initialTangent());
            // back to the virgin state: the inner law at its own zero, the force F0
            shifted->revertToStart();
            QCOMPARE(shifted->committedForce(), f0);
            QCOMPARE(shifted->committedDeformation(), u0);
        }
    }

    /// The layout: the law's names, then the offsets; read and set by position.
    void addsTwoTrailingParameters() {
        const auto law = makeLaw("bilinear", {{"forceOffset", 2.5}});
        QCOMPARE(law->parameterNames(),
                 (std::vector<std::string>{"k0", "fy", "b", "deformationOffset", "forceOffset"}));
        QCOMPARE(*test::parameterNamed(*law, "deformationOffset"), 0.0);
        QCOMPARE(*test::parameterNamed(*law, "forceOffset"), 2.5);
        QVERIFY(test::setParameterNamed(*law, "deformationOffset", -0.4));
        QVERIFY(test::setParameterNamed(*law, "fy", 3.0));
        QCOMPARE(*test::parameterNamed(*law, "deformationOffset"), -0.4);
        QCOMPARE(*test::parameterNamed(*law, "fy"), 3.0);
        // the clone keeps the values and the state
        QCOMPARE(law->setTrialDeformation(0.1), LawStatus::Ok);
        law->commit();
        const auto copy = law->clone();
        QCOMPARE(copy->parameterNames(), law->parameterNames());
        QCOMPARE(copy->committedForce(), law->committedForce());
        QCOMPARE(copy->committedForce(), 1.0 * (0.1 + 0.4) + 2.5); // elastic: k0 (u - u0) + F0
        // no offsets given: the law itself, with its own layout
        QCOMPARE(makeLaw("bilinear", {})->parameterNames().size(), std::size_t(3));
    }

    /// A non-finite offset or an inadmissible law value in the same set: nothing changes with
    /// allOrNothing, the position of the first refused value is returned.
    void refusesInadmissibleSets() {
        const auto law = makeLaw("bilinear", {{"deformationOffset", 0.0}});
        const int b = law->parameterIndex("b"), u0 = law->parameterIndex("deformationOffset"),
                  f0 = law->parameterIndex("forceOffset");
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const std::vector<int> idx{f0, b, u0};
        QCOMPARE(law->setParameterValues(idx, std::vector<double>{1.0, 1.5, 0.2}, true), 1);
        QCOMPARE(law->setParameterValues(idx, std::vector<double>{1.0, 0.2, nan}, true), 2);
        QCOMPARE(*test::parameterNamed(*law, "forceOffset"), 0.0);
        QCOMPARE(*test::parameterNamed(*law, "b"), 0.1);
        // one by one: the admissible ones are set, the first refused reported
        QCOMPARE(law->setParameterValues(idx, std::vector<double>{1.0, 1.5, 0.2}, false), 1);
        QCOMPARE(*test::parameterNamed(*law, "forceOffset"), 1.0);
        QCOMPARE(*test::parameterNamed(*law, "deformationOffset"), 0.2);
        QCOMPARE(*test::parameterNamed(*law, "b"), 0.1);
        QCOMPARE(law->setParameterValues(std::vector<int>{99}, std::vector<double>{1.0}, true), 0);
        QCOMPARE(law->setTrialDeformation(nan), LawStatus::InvalidInput);
    }

    /// The factory: non-finite offsets and unknown names are refused with the law's name.
    void factoryRejectsBadOffsets() {
        try {
            makeLaw("boucWen", {{"forceOffset", std::numeric_limits<double>::infinity()}});
            QFAIL("accepted an infinite offset");
        } catch (const std::invalid_argument& e) {
            QVERIFY(std::string(e.what()).find("boucWen: parameter 'forceOffset'") !=
                    std::string::npos);
        }
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 makeLaw("boucWen", {{"forceOffset", 1.0}, {"k00", 1.0}}));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 OffsetLaw(nullptr, 0.0, 0.0));
    }
};

QTEST_APPLESS_MAIN(TestOffsetLaw)
#include "TestOffsetLaw.moc"
