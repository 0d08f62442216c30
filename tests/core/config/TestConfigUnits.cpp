// The configuration's "units" block (core/config/ConfigUnits.h): every converted field of a
// file written in mm, kip, deg, ms and kg against the value computed here from the exact
// definitions; the console's own units leave a document untouched; unknown units are refused
// with the field and the accepted units named.

#include "core/config/ConfigLoader.h"
#include "core/config/ConfigUnits.h"
#include "core/config/JsonCursor.h"

#include <QtTest>

#include <cmath>

using namespace hsmu;

namespace {

constexpr double kKip = 0.45359237 * 9.80665; // kN
constexpr double kDeg = 3.14159265358979323846 / 180.0;

bool close(double a, double b) {
    return std::abs(a - b) <= 1e-14 * std::abs(b);
}

nlohmann::json labDocument() {
    return nlohmann::json::parse(R"({
      "name": "lab units",
      "units": {"length": "mm", "force": "kip", "rotation": "deg", "time": "ms", "mass": "kg"},
      "structure": {
        "dofs": [{"name": "roof", "mass": 2000}, {"name": "floor", "mass": 500}],
        "damping": {"a0": 0.5, "a1": 2.0},
        "elements": [
          {"name": "brace", "type": "lateralSpring", "dof": "floor",
           "material": {"law": "bilinear", "k0": 10, "fy": 3, "b": 0.1}},
          {"name": "column", "type": "rotationalBaseSpring", "dof": "roof", "height": 3000,
           "material": {"law": "boucWen", "uRef": 1.5, "k0": 1.2},
           "experimental": true,
           "specimen": {
             "material": {"law": "boucWenPinching", "fRef": 200, "zetaS": 0.5},
             "forceNoiseStd": 0.5, "deformationNoiseStd": 0.01,
             "actuator": {"type": "lag", "timeConstant": 5},
             "fracture": {"atTime": 4000, "strengthLoss": 0.3},
             "interlock": {"deformation": 3, "force": 900, "increment": 0.6}},
           "limits": {"deformation": 2, "force": 800, "increment": 0.5}},
          {"name": "elastic", "type": "truss", "dofs": ["floor", "roof"],
           "material": {"law": "elastic", "k": 4}},
          {"name": "damper", "type": "lateralSpring", "dof": "floor",
           "material": {"law": "mr-damper", "c0": 30, "c1": 400, "uRef": 2, "alpha": 5}}
        ]
      },
      "groundMotion": {"builtin": "synthetic", "dt": 20},
      "analysis": {"dt": 10, "duration": 5000}
    })");
}

} // namespace

class TestConfigUnits : public QObject {
    Q_OBJECT
private slots:
    void convertsEveryDimensionalField();
    void consoleUnitsLeaveTheDocument();
    void momentUnitAndErrors();
};

void TestConfigUnits::convertsEveryDimensionalField() {
    const TestConfig cfg = parseConfig(labDocument(), "lab.json");
    QVERIFY(close(cfg.dofs[0].mass, 2.0) && close(cfg.dofs[1].mass, 0.5));
    QVERIFY(close(cfg.damping.a0, 500.0));  // 0.5 / ms
    QVERIFY(close(cfg.damping.a1, 0.002));  // 2 ms
    const ElementSpec& brace = cfg.elements[0];
    QVERIFY(close(brace.material.params.at("k0"), 10.0 * kKip / 0.001)); // kip/mm -> kN/m
    QVERIFY(close(brace.material.params.at("fy"), 3.0 * kKip));
    QCOMPARE(brace.material.params.at("b"), 0.1);
    const ElementSpec& column = cfg.elements[1];
    QVERIFY(close(column.height, 3.0));
    // Rotational: deformation in deg, force in the moment kip mm.
    QVERIFY(close(column.material.params.at("uRef"), 1.5 * kDeg));
    QVERIFY(close(column.material.params.at("fRef"), 1.0 * kKip * 0.001)); // default 1 written
    QCOMPARE(column.material.params.at("k0"), 1.2);                        // normalized
    const auto& truth = column.specimen.trueMaterial.params;
    QVERIFY(close(truth.at("fRef"), 200.0 * kKip * 0.001));
    QVERIFY(close(truth.at("uRef"), kDeg));
    QCOMPARE(truth.at("zetaS"), 0.5);
    const auto& o = column.specimen.options;
    QVERIFY(close(o.forceNoiseStd, 0.5 * kKip * 0.001));
    QVERIFY(close(o.deformationNoiseStd, 0.01 * kDeg));
    QVERIFY(close(o.actuator.timeConstant, 0.005));
    QVERIFY(close(o.fracture.atTime, 4.0));
    QCOMPARE(o.fracture.strengthLoss, 0.3);
    QVERIFY(close(o.interlock.maxDeformation, 3.0 * kDeg));
    QVERIFY(close(o.interlock.maxIncrement, 0.6 * kDeg));
    QVERIFY(close(o.interlock.maxForce, 900.0 * kKip * 0.001));
    QVERIFY(close(column.limits.maxDeformation, 2.0 * kDeg));
    QVERIFY(close(column.limits.maxIncrement, 0.5 * kDeg));
    QVERIFY(close(column.limits.maxForce, 800.0 * kKip * 0.001));
    QVERIFY(close(cfg.elements[2].material.params.at("k"), 4.0 * kKip / 0.001));
    // mrDamper: the scales as Bouc-Wen's, the dashpots (normalized force x time) from ms to s.
    const MaterialSpec& damper = cfg.elements[3].material;
    QCOMPARE(damper.law, std::string("mrDamper"));
    QVERIFY(close(damper.params.at("uRef"), 0.002));
    QVERIFY(close(damper.params.at("fRef"), kKip));
    QVERIFY(close(damper.params.at("c0"), 0.03));
    QVERIFY(close(damper.params.at("c1"), 0.4));
    QCOMPARE(damper.params.at("alpha"), 5.0);
    QVERIFY(close(cfg.groundMotion.dt, 0.02));
    QVERIFY(close(cfg.analysis.dt, 0.01));
    QVERIFY(close(cfg.analysis.duration, 5.0));
    // The record keeps the document as written.
    QCOMPARE(cfg.raw["analysis"]["dt"].get<double>(), 10.0);
}

void TestConfigUnits::consoleUnitsLeaveTheDocument() {
    nlohmann::json doc = labDocument();
    doc["units"] = {{"force", "kN"}, {"length", "m"}, {"time", "s"}, {"mass", "t"},
                    {"rotation", "rad"}, {"moment", "kN m"}};
    QVERIFY(toConsoleUnits(doc, "a.json") == doc);
    doc.erase("units");
    QVERIFY(toConsoleUnits(doc, "a.json") == doc);
}

void TestConfigUnits::momentUnitAndErrors() {
    nlohmann::json doc = labDocument();
    doc["units"]["moment"] = "kip in"; // the other units as before (time in ms, ...)
    doc["units"]["rotation"] = "rad";
    TestConfig cfg;
    try {
        cfg = parseConfig(doc, "m.json");
    } catch (const ConfigError& e) {
        QFAIL(e.what());
    }
    QVERIFY(close(cfg.elements[1].specimen.trueMaterial.params.at("fRef"), 200.0 * kKip * 0.0254));
    const auto message = [](const nlohmann::json& units) {
        nlohmann::json d = labDocument();
        d["units"] = units;
        try {
            parseConfig(d, "e.json");
        } catch (const ConfigError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    QCOMPARE(message({{"length", "yd"}}),
             std::string("e.json: units.length: unknown length unit 'yd' (expected m, cm, mm, "
                         "in, ft)"));
    QCOMPARE(message({{"force", "ton"}}),
             std::string("e.json: units.force: unknown force unit 'ton' (expected N, kN, MN, "
                         "lbf, kip, kgf, tonf)"));
    QVERIFY(message({{"speed", "m/s"}}).find("units") != std::string::npos);
    QVERIFY(message({{"mass", "lb"}}).find("expected t, kg") != std::string::npos);
}

QTEST_APPLESS_MAIN(TestConfigUnits)
#include "TestConfigUnits.moc"
