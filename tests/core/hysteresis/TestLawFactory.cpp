// Tests of makeLaw / knownLaws (core/hysteresis/LawFactory.h): each law is built with its
// defaults and given values, and every kind of mistake is rejected with a message that names
// the law, the parameter and what was expected.

#include "core/hysteresis/LawFactory.h"
#include "tests/support/LawByName.h"

#include "core/hysteresis/HysteresisLaw.h"

#include <QtTest>

#include <limits>
#include <stdexcept>

using namespace hsmu;

namespace {

// The message of the std::invalid_argument thrown by makeLaw, or "" if nothing was thrown.
std::string rejection(const std::string& law, const std::map<std::string, double>& params) {
    try {
        makeLaw(law, params);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return {};
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

class TestLawFactory : public QObject {
    Q_OBJECT

private slots:
    void makesEachLawWithDefaults();
    void appliesGivenParameters();
    void acceptsEveryParameterNameOfTheLaw();
    void rejectsUnknownLaw();
    void rejectsUnknownParameter();
    void rejectsInadmissibleValues();
};

void TestLawFactory::makesEachLawWithDefaults() {
    QVERIFY(knownLaws() ==
            (std::vector<std::string>{"boucWen", "boucWenPinching", "mrDamper", "bilinear",
                                      "elastic"}));
    for (const std::string& name : knownLaws()) {
        const auto law = makeLaw(name, {});
        QVERIFY(law != nullptr);
        QCOMPARE(law->lawName(), name);
        QVERIFY(law->initialTangent() > 0.0);
    }
    QCOMPARE(makeLaw("bouc-wen", {})->lawName(), std::string("boucWen"));
    QCOMPARE(makeLaw("BoucWen", {})->lawName(), std::string("boucWen"));
    const auto bw = makeLaw("boucWen", {});
    QCOMPARE(*test::parameterNamed(*bw, "beta"), 3.0);
    QCOMPARE(*test::parameterNamed(*bw, "uRef"), 1.0);
    const auto bl = makeLaw("bilinear", {});
    QCOMPARE(*test::parameterNamed(*bl, "k0"), 1.0);
    QCOMPARE(*test::parameterNamed(*bl, "fy"), 1.0);
    QCOMPARE(*test::parameterNamed(*bl, "b"), 0.1);
}

void TestLawFactory::appliesGivenParameters() {
    const auto bw = makeLaw("boucWen", {{"k0", 1.2}, {"n", 1.5}, {"deltaNu", 0.05}});
    QCOMPARE(*test::parameterNamed(*bw, "k0"), 1.2);
    QCOMPARE(*test::parameterNamed(*bw, "n"), 1.5);
    QCOMPARE(*test::parameterNamed(*bw, "deltaNu"), 0.05);
    QCOMPARE(*test::parameterNamed(*bw, "alpha"), 0.02); // default kept
    // beta + gamma > 0 is checked on the final set, whatever the order of the names.
    const auto sum = makeLaw("boucWen", {{"beta", -1.0}, {"gamma", 1.5}});
    QCOMPARE(*test::parameterNamed(*sum, "beta"), -1.0);

    const auto bl = makeLaw("bilinear", {{"k0", 1.015}, {"fy", 2.8}, {"b", 0.1}});
    QVERIFY(bl->setTrialDeformation(1.0) == LawStatus::Ok);
    QCOMPARE(bl->trialForce(), 1.015);

    const auto el = makeLaw("elastic", {{"k", 3.0}});
    QVERIFY(el->setTrialDeformation(2.0) == LawStatus::Ok);
    QCOMPARE(el->trialForce(), 6.0);
    QCOMPARE(el->trialTangent(), 3.0);
}

void TestLawFactory::acceptsEveryParameterNameOfTheLaw() {
    // The factory's tables and the laws' parameterNames() agree: feeding a law's own
    // parameters back reproduces it.
    for (const std::string& name : knownLaws()) {
        const auto law = makeLaw(name, {});
        std::map<std::string, double> params;
        for (const std::string& p : law->parameterNames()) {
            params[p] = *test::parameterNamed(*law, p);
        }
        const auto again = makeLaw(name, params);
        for (const std::string& p : law->parameterNames()) {
            QCOMPARE(*test::parameterNamed(*again, p), params[p]);
        }
    }
}

void TestLawFactory::rejectsUnknownLaw() {
    const std::string message = rejection("takeda", {});
    QVERIFY(contains(message, "'takeda'"));
    QVERIFY(contains(message, "boucWen") && contains(message, "bilinear") &&
            contains(message, "elastic") && contains(message, "mrDamper"));
}

void TestLawFactory::rejectsUnknownParameter() {
    QCOMPARE(rejection("bilinear", {{"fyy", 1.0}}),
             std::string("bilinear: unknown parameter 'fyy' (expected one of k0, fy, b)"));
    const std::string bw = rejection("boucWen", {{"delta", 0.1}});
    QVERIFY(contains(bw, "boucWen: unknown parameter 'delta'"));
    QVERIFY(contains(bw, "deltaNu") && contains(bw, "fRef"));
    QCOMPARE(rejection("elastic", {{"k0", 1.0}}),
             std::string("elastic: unknown parameter 'k0' (expected one of k)"));
}

void TestLawFactory::rejectsInadmissibleValues() {
    const std::string b = rejection("bilinear", {{"b", 1.0}});
    QVERIFY(contains(b, "bilinear") && contains(b, "'b'") && contains(b, "0 <= b < 1"));
    const std::string fy = rejection("bilinear", {{"fy", -2.8}});
    QVERIFY(contains(fy, "'fy' = -2.8") && contains(fy, "> 0"));
    const std::string alpha = rejection("boucWen", {{"alpha", 2.0}});
    QVERIFY(contains(alpha, "boucWen") && contains(alpha, "'alpha'") && contains(alpha, "[0, 1]"));
    const std::string shape = rejection("boucWen", {{"beta", -3.0}});
    QVERIFY(contains(shape, "boucWen") && contains(shape, "beta + gamma > 0"));
    const std::string nan = rejection("boucWen", {{"n", std::numeric_limits<double>::quiet_NaN()}});
    QVERIFY(contains(nan, "'n' = nan") && contains(nan, "finite"));
    const std::string k = rejection("elastic", {{"k", 0.0}});
    QVERIFY(contains(k, "elastic") && contains(k, "'k'"));
    for (const char* name : {"deltaNu", "deltaEta", "deltaA"}) {
        QVERIFY(contains(rejection("boucWen", {{name, -0.01}}), std::string("'") + name + "'"));
    }
    QVERIFY(contains(rejection("boucWen", {{"uRef", 0.0}}), "'uRef'"));
}

QTEST_APPLESS_MAIN(TestLawFactory)
#include "TestLawFactory.moc"
