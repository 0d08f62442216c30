// Tests of a link2d specimen simulated as a whole by the virtual lab, configured in JSON
// ("specimen": {"type": "cantileverColumn", ...} and an "actuator" model per actuator;
// core/config/Link2dConfig.h, docs/setups.md "The specimen as a whole"): the two-actuator
// column frame (resources/presets/two-actuator-column-frame.json) with the whole-specimen lab,
// against a closed form and end to end with a Bouc-Wen hinge and a lagging lateral actuator;
// each configuration error names its field. Units: kN, m, s, t, rad.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/experimental/ExperimentalLink2d.h"
#include "core/structure/Structure.h"

#include <QtTest>

#include <cmath>

#include "Link2dFrameFixture.h"

using namespace hsmu;
using namespace link2dframe;

namespace {

constexpr double kL = 3.0, kEI = 2e5, kHinge = 1.6e5, kP = 500.0;

// The preset's left column simulated as a whole: the hinge law given, elastic axial 2e5 kN/m,
// EI 2e5 kN m^2; the actuators without materials.
nlohmann::json wholeColumn(nlohmann::json hinge) {
    nlohmann::json doc = presetJson();
    nlohmann::json& col = doc["structure"]["elements"][0];
    col["specimen"] = {{"type", "cantileverColumn"},
                       {"hinge", hinge},
                       {"axial", {{"law", "elastic"}, {"k", 2e5}}},
                       {"ei", kEI}};
    for (auto& a : col["actuators"])
        a.erase("material");
    return doc;
}

double freeTopStiffness() {
    return 1.0 / (kL * kL / kHinge + kL * kL * kL / (3.0 * kEI));
}

} // namespace

class TestWholeSpecimenConfig : public QObject {
    Q_OBJECT

private slots:
    // With an elastic hinge the column is linear: lateral stiffness k - P / L under the held
    // 500 kN (P-Delta), a free top. So the frame equals the frame whose left column is
    // numerical with that shear stiffness, the axial load held and a free rotation (K0 the
    // same: the lateral actuator's initialStiffness set to k - P / L).
    void elasticHingeFrameEqualsClosedFormTwin() {
        auto whole = wholeColumn({{"law", "elastic"}, {"k", kHinge}});
        whole["structure"]["elements"][0]["actuators"][1]["initialStiffness"] =
            freeTopStiffness() - kP / kL;
        nlohmann::json twin = presetJson();
        nlohmann::json& col = twin["structure"]["elements"][0];
        for (const char* k : {"experimental", "setup", "actuators"})
            col.erase(k);
        col["basic"] = nlohmann::json::array(
            {{{"heldForce", -kP}},
             {{"material", {{"law", "elastic"}, {"k", freeTopStiffness() - kP / kL}}}},
             nlohmann::json::object()});
        std::unique_ptr<HybridTest> hybrid;
        const auto b = run(whole, 4.0, &hybrid);
        const auto a = run(twin, 4.0);
        QCOMPARE(a.size(), b.size());
        const auto [peak, du, peakF, dF] = compareRuns(a, b);
        QVERIFY(peak > 0.005);
        QVERIFY(du <= 1e-9 * peak);
        QVERIFY(dF <= 1e-9 * peakF);
        const auto* x =
            dynamic_cast<const ExperimentalLink2d*>(hybrid->structure().element("Column L"));
        QVERIFY(x);
        QVERIFY(std::abs(x->basicForces()[0] + kP) <= 1e-9);
        QVERIFY(std::abs(x->basicForces()[2]) <= 1e-9); // a free top
    }

    // A Bouc-Wen moment-rotation hinge (yield near 150 kN m) and a lagging lateral actuator
    // (tau 5 ms): the run finishes, the column yields, the axial load is held, the measured
    // lateral stroke trails the command, and the lab's default K0 is the column's k.
    void boucWenHingeWithLagRuns() {
        auto doc = wholeColumn({{"law", "boucWen"},
                                {"k0", 1.0},
                                {"alpha", 0.05},
                                {"n", 2.0},
                                {"beta", 3.0},
                                {"gamma", 1.0},
                                {"A0", 1.0},
                                {"uRef", 0.001875},
                                {"fRef", 300.0}});
        doc["structure"]["elements"][0]["actuators"][1]["actuator"] = {{"type", "lag"},
                                                                       {"timeConstant", 0.005}};
        const TestConfig cfg = parseConfig(doc, "frame.json");
        QVERIFY(std::abs(cfg.elements[0].link2d->actuators[1].channel.initialStiffness -
                         freeTopStiffness()) <= 1e-9 * freeTopStiffness());
        std::unique_ptr<HybridTest> hybrid;
        const auto r = run(doc, 4.0, &hybrid);
        QCOMPARE(int(r.size()), 401);
        double peakF = 0;
        for (const auto& s : r)
            peakF = std::max(peakF, std::abs(s.elements[0].force));
        qInfo("peak shear %.6g kN", peakF);
        QVERIFY(peakF > 40.0 && peakF < 80.0); // yielded: M_y / L = 50 kN, 5 % hardening
        const auto* x =
            dynamic_cast<const ExperimentalLink2d*>(hybrid->structure().element("Column L"));
        QVERIFY(std::abs(x->actuatorForces()[0] + kP) <= 1e-9);
        QVERIFY(std::abs(x->strokes()[1] - x->commands()[1]) > 0.0); // the lag trails
    }

    void errorsNameTheField() {
        const nlohmann::json hinge = {{"law", "elastic"}, {"k", kHinge}};
        auto doc = wholeColumn(hinge);
        doc["structure"]["elements"][0]["specimen"]["type"] = "column";
        QString e = errorOf(doc);
        QVERIFY2(e.contains("specimen.type") && e.contains("cantileverColumn"), qPrintable(e));

        doc = wholeColumn(hinge);
        doc["structure"]["elements"][0]["specimen"]["ei"] = -1.0;
        e = errorOf(doc);
        QVERIFY2(e.contains("specimen.ei"), qPrintable(e));

        doc = wholeColumn(hinge);
        doc["structure"]["elements"][0]["specimen"].erase("hinge");
        e = errorOf(doc);
        QVERIFY2(e.contains("hinge"), qPrintable(e));

        doc = wholeColumn(hinge);
        doc["structure"]["elements"][0]["actuators"][1]["material"] = hinge;
        e = errorOf(doc);
        QVERIFY2(e.contains("actuators[1].material") && e.contains("whole specimen"),
                 qPrintable(e));

        doc = wholeColumn(hinge);
        doc["structure"]["elements"][0]["actuators"][0]["actuator"] = {{"type", "servoHydraulic"}};
        e = errorOf(doc);
        QVERIFY2(e.contains("actuators[0].actuator.type") && e.contains("force-controlled"),
                 qPrintable(e));

        doc = wholeColumn(hinge);
        doc["structure"]["elements"][0]["actuators"][1]["actuator"] = {{"type", "lag"},
                                                                       {"timeConstant", -1.0}};
        e = errorOf(doc);
        QVERIFY2(e.contains("actuators[1].actuator.timeConstant"), qPrintable(e));

        doc = presetJson();
        doc["structure"]["elements"][2]["specimen"] = {{"type", "cantileverColumn"}};
        e = errorOf(doc);
        QVERIFY2(e.contains("specimen") && e.contains("experimental"), qPrintable(e));
    }
};

QTEST_APPLESS_MAIN(TestWholeSpecimenConfig)
#include "TestWholeSpecimenConfig.moc"
