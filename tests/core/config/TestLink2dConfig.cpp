// Tests of the "link2d" element of a configuration (core/config/Link2dConfig.h,
// docs/configuration.md "link2d"): the shipped preset two-actuator-column-frame.json (a one-bay
// frame whose left column is a two-actuator specimen with a constant axial load on the
// in-process virtual lab) equals the same frame with that column numerical (the same laws, the
// axial load held) to 1e-9 of the peak; and each configuration error names the field, the
// setup and its parameter. Units: kN, m, s, t.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/experimental/ExperimentalLink2d.h"
#include "core/structure/Structure.h"

#include <QtTest>

#include <cmath>
#include <fstream>

#include "Link2dFrameFixture.h"

using namespace hsmu;
using namespace link2dframe;

namespace {

// The left column as the numerical twin: held axial load, the lateral actuator's law on the
// shear DOF, a free rotation (no actuator on it).
nlohmann::json numericalTwin(nlohmann::json doc)
{
    nlohmann::json& col = doc["structure"]["elements"][0];
    const nlohmann::json shear = col["actuators"][1]["material"];
    const double axial = col["actuators"][0]["force"];
    for (const char* k : {"experimental", "setup", "actuators"})
        col.erase(k);
    col["basic"] = nlohmann::json::array({{{"heldForce", axial}}, {{"material", shear}},
                                          nlohmann::json::object()});
    return doc;
}

} // namespace

class TestLink2dConfig : public QObject {
    Q_OBJECT

private slots:
    void presetEqualsNumericalTwin()
    {
        std::unique_ptr<HybridTest> hybrid;
        const auto b = run(presetJson(), 10.0, &hybrid);
        const auto a = run(numericalTwin(presetJson()), 10.0);
        QCOMPARE(a.size(), b.size());
        const auto [peak, du, peakF, dF] = compareRuns(a, b);
        QVERIFY(peak > 0.01); // twice the column's yield displacement (about 0.005 m: z_max fRef / k0)
        QVERIFY(du <= 1e-9 * peak);
        QVERIFY(dF <= 1e-9 * peakF);
        const auto* x = dynamic_cast<const ExperimentalLink2d*>(
            hybrid->structure().element("Column L"));
        QVERIFY(x);
        QCOMPARE(x->setup().typeName(), std::string("NoTransformation"));
        QCOMPARE(x->channels()[0].mode, ActuatorMode::Force);
        QVERIFY(std::abs(x->basicForces()[0] + 500.0) <= 1e-9);
    }

    // "geometry": "corotational" on every link2d (eq. L3-L5): the preset still equals its
    // numerical twin to 1e-9, and K0 carries the held axial loads' geometric stiffness: each
    // column's -500 kN takes 500 / 3 kN/m off the sway DOF's diagonal (P / L).
    void corotationalPresetEqualsNumericalTwin()
    {
        auto doc = presetJson();
        for (auto& e : doc["structure"]["elements"])
            e["geometry"] = "corotational";
        std::unique_ptr<HybridTest> hybrid, linear;
        const auto b = run(doc, 10.0, &hybrid);
        const auto a = run(numericalTwin(doc), 10.0);
        const auto c = run(presetJson(), 10.0, &linear);
        QCOMPARE(a.size(), b.size());
        const auto [peak, du, peakF, dF] = compareRuns(a, b);
        QVERIFY(peak > 0.01);
        QVERIFY(du <= 1e-9 * peak);
        QVERIFY(dF <= 1e-9 * peakF);
        const auto diff = compareRuns(b, c); // corotational against linear: they differ
        QVERIFY(diff.du > 1e-6 * peak);
        const auto& k = hybrid->structure().initialStiffness();
        const auto& k0 = linear->structure().initialStiffness();
        qInfo("K0(x3, x3): linear %.12g, corotational %.12g kN/m", k0.coeff(0, 0), k.coeff(0, 0));
        QVERIFY(std::abs(k.coeff(0, 0) - (k0.coeff(0, 0) - 500.0 / 3.0)) <= 1e-9 * k0.coeff(0, 0));
        QVERIFY(std::abs(k.coeff(1, 1) - (k0.coeff(1, 1) - 500.0 / 3.0)) <= 1e-9 * k0.coeff(1, 1));
    }

    void errorsNameTheSetupAndParameter()
    {
        auto doc = presetJson();
        doc["structure"]["elements"][0]["setup"]["script"] =
            "expSetup NoTransformation 1 -dir 1 2 -sizeTrialOut 2 2";
        QString e = errorOf(doc);
        QVERIFY2(e.contains("setup.script") && e.contains("NoTransformation serves 2 basic DOFs"),
                 qPrintable(e));

        doc = presetJson();
        doc["structure"]["elements"][0]["setup"]["script"] =
            "expSetup TwoActuators2d 1 1.5 1.2 0.0 -phiLocX 90";
        e = errorOf(doc);
        QVERIFY2(e.contains("setup.script") && e.contains("TwoActuators2d: L"), qPrintable(e));

        doc = presetJson();
        doc["structure"]["elements"][0]["actuators"].erase(1);
        e = errorOf(doc);
        QVERIFY2(e.contains("actuators") && e.contains("NoTransformation has 2 actuators, 1 given"),
                 qPrintable(e));

        doc = presetJson();
        doc["structure"]["elements"][0]["actuators"][0]["control"] = "velocity";
        e = errorOf(doc);
        QVERIFY2(e.contains("control") && e.contains("'displacement' or 'force'"), qPrintable(e));

        doc = presetJson();
        doc["structure"]["elements"][0]["dofs"] = nlohmann::json::array({nullptr, "x3"});
        e = errorOf(doc);
        QVERIFY2(e.contains("dofs") && e.contains("six DOFs"), qPrintable(e));

        doc = presetJson();
        doc["structure"]["elements"][0]["geometry"] = "Corotational";
        e = errorOf(doc);
        QVERIFY2(e.contains("geometry") && e.contains("'linear'") && e.contains("'corotational'") &&
                     e.contains("'Corotational'"),
                 qPrintable(e));

        doc = presetJson(); // a zero-length element has no chord to turn
        doc["structure"]["elements"][2]["length"] = 0.0;
        doc["structure"]["elements"][2]["geometry"] = "corotational";
        e = errorOf(doc);
        QVERIFY2(e.contains("length") && e.contains("> 0"), qPrintable(e));

        doc = presetJson(); // the primary basic DOF of a numerical link needs a law
        doc["structure"]["elements"][1]["basic"][1] = {{"heldForce", 3.0}};
        e = errorOf(doc);
        QVERIFY2(e.contains("primary"), qPrintable(e));
    }
};

QTEST_GUILESS_MAIN(TestLink2dConfig)
#include "TestLink2dConfig.moc"
