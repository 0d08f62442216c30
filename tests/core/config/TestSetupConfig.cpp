// Tests of a link2d specimen's setup given as type + OpenFresco's parameters in JSON
// (core/config/SetupConfig.h, docs/configuration.md "link2d"): for every setup type, the JSON
// block and the expSetup line with the same numbers build identical setups (the same strokes,
// Jacobian, measured basic displacements and basic forces, bit for bit, at rest and at a
// large displacement with rotations of 0.2 rad); the block's line is the one expected; each
// error names the field (the setup's parameter) and the setup type; and the preset
// two-actuator-column-frame with its setup as a JSON block runs identically to the one with
// the script (every DOF, every step, bit for bit). Units: m, rad, kN.

#include "core/config/ConfigLoader.h"
#include "core/config/SetupConfig.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/experimental/setup/SetupScript.h"

#include <QtTest>

#include <fstream>

using namespace hsmu;
using nlohmann::json;

namespace {

const std::string kPreset = HSMU_SOURCE_DIR "/resources/presets/two-actuator-column-frame.json";

std::unique_ptr<ExperimentalSetup> fromScript(const std::string& script) {
    SetupsByTag setups;
    std::string error;
    if (!parseSetupScript(script, setups, error))
        qFatal("%s", error.c_str());
    return std::move(setups.rbegin()->second); // the last line's (the Aggregator's) tag
}

std::unique_ptr<ExperimentalSetup> fromJson(const json& block) {
    return fromScript(setupScriptOf(JsonCursor(block, "frame.json", "setup")));
}

QString errorOf(const json& block) {
    try {
        setupScriptOf(JsonCursor(block, "frame.json", "setup"));
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

// Everything a setup computes, at d, compared bit for bit.
bool same(const ExperimentalSetup& a, const ExperimentalSetup& b, const Eigen::VectorXd& d) {
    Eigen::VectorXd sa, sb, da, db, qa, qb;
    Eigen::MatrixXd ja, jb;
    if (a.typeName() != b.typeName() || a.basicSize() != b.basicSize() ||
        a.actuatorCount() != b.actuatorCount())
        return false;
    const Eigen::VectorXd f = Eigen::VectorXd::LinSpaced(a.actuatorCount(), -300.0, 200.0);
    const bool ok = a.strokes(d, sa).ok && b.strokes(d, sb).ok && a.jacobian(d, ja).ok &&
                    b.jacobian(d, jb).ok && a.basicDisplacements(sa, d, da).ok &&
                    b.basicDisplacements(sb, d, db).ok && a.basicForces(d, f, qa).ok &&
                    b.basicForces(d, f, qb).ok;
    return ok && sa == sb && ja == jb && da == db && qa == qb;
}

struct Case {
    const char* name;
    json block;
    std::string script;
};

std::vector<Case> cases() {
    return {
        {"TwoActuators2d nlGeom right",
         {{"type", "TwoActuators2d"},
          {"La1", 1.5},
          {"La2", 1.2},
          {"L", 0.6},
          {"nlGeom", true},
          {"posAct", "right"},
          {"phiLocX", 90}},
         "expSetup TwoActuators2d 1 1.5 1.2 0.6 -nlGeom -posAct right -phiLocX 90"},
        {"TwoActuators2d linear",
         {{"type", "TwoActuators2d"}, {"La1", 1.5}, {"La2", 1.2}, {"L", 0.6}},
         "expSetup TwoActuators2d 1 1.5 1.2 0.6"},
        {"ThreeActuators2d",
         {{"type", "ThreeActuators2d"},
          {"La1", 1.6},
          {"La2", 1.1},
          {"La3", 1.3},
          {"L1", 0.7},
          {"L2", 0.5},
          {"nlGeom", true},
          {"phiLocX", -20.0}},
         "expSetup ThreeActuators2d 1 1.6 1.1 1.3 0.7 0.5 -nlGeom -phiLocX -20"},
        {"ThreeActuatorsJntOff2d",
         {{"type", "ThreeActuatorsJntOff2d"},
          {"La1", 1.6},
          {"La2", 1.1},
          {"La3", 1.3},
          {"L1", 0.2},
          {"L2", 0.7},
          {"L3", 0.5},
          {"L4", 0.1},
          {"L5", 0.15},
          {"L6", 0.25},
          {"nlGeom", true},
          {"posAct1", "right"}},
         "expSetup ThreeActuatorsJntOff2d 1 1.6 1.1 1.3 0.2 0.7 0.5 0.1 0.15 0.25 -nlGeom "
         "-posAct1 right"},
        {"InvertedVBrace2d",
         {{"type", "InvertedVBrace2d"},
          {"La1", 1.6},
          {"La2", 1.1},
          {"La3", 1.3},
          {"L1", 0.7},
          {"L2", 0.5},
          {"nlGeom", true}},
         "expSetup InvertedVBrace2d 1 1.6 1.1 1.3 0.7 0.5 -nlGeom"},
        {"ChevronBrace2d",
         {{"type", "ChevronBrace2d"},
          {"La1", 1.6},
          {"La2", 1.1},
          {"La3", 1.3},
          {"L1", 0.7},
          {"L2", 0.5}},
         "expSetup ChevronBrace2d 1 1.6 1.1 1.3 0.7 0.5"},
        {"InvertedVBraceJntOff2d",
         {{"type", "InvertedVBraceJntOff2d"},
          {"La1", 1.6},
          {"La2", 1.1},
          {"La3", 1.3},
          {"L1", 0.2},
          {"L2", 0.7},
          {"L3", 0.5},
          {"L4", 0.1},
          {"L5", 0.15},
          {"L6", 0.25}},
         "expSetup InvertedVBraceJntOff2d 1 1.6 1.1 1.3 0.2 0.7 0.5 0.1 0.15 0.25"},
        {"FourActuators3d",
         {{"type", "FourActuators3d"},
          {"L1", 1.5},
          {"L2", 1.5},
          {"L3", 1.4},
          {"L4", 1.4},
          {"a1", 0.1},
          {"a2", 0.1},
          {"a3", 0.12},
          {"a4", 0.12},
          {"h", 0.8},
          {"h1", 0.3},
          {"h2", 0.3},
          {"arlN", 0.2},
          {"arlS", 0.2},
          {"LrodN", 1.0},
          {"LrodS", 1.0},
          {"Hbeam", 0.4},
          {"nlGeom", true}},
         "expSetup FourActuators3d 1 1.5 1.5 1.4 1.4 0.1 0.1 0.12 0.12 0.8 0.3 0.3 0.2 0.2 1 1 "
         "0.4 -nlGeom"},
        {"OneActuator",
         {{"type", "OneActuator"}, {"dir", 2}, {"sizeTrial", 3}},
         "expSetup OneActuator 1 2 -sizeTrialOut 3 3"},
        {"NoTransformation",
         {{"type", "NoTransformation"}, {"dir", {1, 2}}, {"sizeTrial", 3}},
         "expSetup NoTransformation 1 -dir 1 2 -sizeTrialOut 3 3"},
        {"Aggregator",
         {{"type", "Aggregator"},
          {"setups",
           {{{"type", "OneActuator"}, {"dir", 1}, {"sizeTrial", 1}},
            {{"type", "ThreeActuators2d"},
             {"La1", 1.6},
             {"La2", 1.1},
             {"La3", 1.3},
             {"L1", 0.7},
             {"L2", 0.5},
             {"nlGeom", true}}}}},
         "expSetup OneActuator 1 1 -sizeTrialOut 1 1\n"
         "expSetup ThreeActuators2d 2 1.6 1.1 1.3 0.7 0.5 -nlGeom\n"
         "expSetup Aggregator 3 -setup 1 2 -sizeTrialOut 4 4"},
    };
}

struct Recorder final : StepObserver {
    std::vector<StepRecord> records;
    void onStep(const StepRecord& r) override { records.push_back(r); }
};

std::vector<StepRecord> run(const json& doc) {
    TestConfig cfg = parseConfig(doc, "frame.json");
    cfg.analysis.duration = 2.0;
    auto test = buildHybridTest(cfg);
    Recorder rec;
    test->addObserver(&rec);
    if (!test->prepare())
        qFatal("%s", test->lastError().c_str());
    while (test->step() == HybridTest::StepResult::Advanced) {
    }
    test->removeObserver(&rec);
    return rec.records;
}

} // namespace

class TestSetupConfig : public QObject {
    Q_OBJECT

private slots:
    void jsonAndScriptBuildIdenticalSetups() {
        for (const Case& c : cases()) {
            const std::string line = setupScriptOf(JsonCursor(c.block, "frame.json", "setup"));
            QCOMPARE(QString::fromStdString(line).trimmed(), QString::fromStdString(c.script));
            const auto a = fromJson(c.block);
            const auto b = fromScript(c.script);
            const int n = a->basicSize();
            // At rest and at a large displacement (translations 0.05 m, rotations 0.2 rad; the
            // FourActuators3d's six basic DOFs likewise).
            Eigen::VectorXd big = Eigen::VectorXd::Constant(n, 0.05);
            for (int k = 2; k < n; k += 3)
                big[k] = 0.2;
            QVERIFY2(same(*a, *b, Eigen::VectorXd::Zero(n)), c.name);
            QVERIFY2(same(*a, *b, big), c.name);
        }
    }

    void numbersReadBackExactly() {
        // 0.1 + 0.2 has no short decimal: the line must still read back the same double.
        const json block{{"type", "TwoActuators2d"},
                         {"La1", 0.1 + 0.2},
                         {"La2", 1.0 / 3.0},
                         {"L", 0.6},
                         {"nlGeom", true}};
        std::ostringstream line;
        line.precision(17);
        line << "expSetup TwoActuators2d 1 " << 0.1 + 0.2 << " " << 1.0 / 3.0 << " 0.6 -nlGeom";
        const Eigen::Vector3d d(0.03, 0.01, 0.2);
        QVERIFY(same(*fromJson(block), *fromScript(line.str()), d));
    }

    void errorsNameTheTypeAndParameter() {
        json b{{"type", "TwoActuators2d"}, {"La1", 1.5}, {"L", 0.6}};
        QString e = errorOf(b);
        QVERIFY2(e.contains("setup.La2: TwoActuators2d: La2 missing"), qPrintable(e));

        b = {{"type", "TwoActuators2d"}, {"La1", 1.5}, {"La2", 1.2}, {"L", 0.0}};
        e = errorOf(b);
        QVERIFY2(e.contains("setup.L: TwoActuators2d: L = 0"), qPrintable(e));

        b = {{"type", "ThreeActuators2d"},
             {"La1", 1.6},
             {"La2", 1.1},
             {"La3", 1.3},
             {"L1", 0.7},
             {"L2", 0.5},
             {"nlgeom", true}};
        e = errorOf(b);
        QVERIFY2(e.contains("setup.nlgeom: ThreeActuators2d: unknown parameter") &&
                     e.contains("nlGeom"),
                 qPrintable(e));

        b = {{"type", "TwoActuators2d"}, {"La1", 1.5}, {"La2", 1.2}, {"L", 0.6}, {"posAct", "up"}};
        e = errorOf(b);
        QVERIFY2(e.contains("setup.posAct: TwoActuators2d: -posAct wants left, right"),
                 qPrintable(e));

        b = {{"type", "TwoActuators2d"}, {"La1", "1.5"}, {"La2", 1.2}, {"L", 0.6}};
        e = errorOf(b);
        QVERIFY2(e.contains("setup.La1") && e.contains("number"), qPrintable(e));

        b = {{"type", "FiveActuators2d"}};
        e = errorOf(b);
        QVERIFY2(e.contains("setup.type: unknown experimental setup type 'FiveActuators2d'"),
                 qPrintable(e));

        b = {{"type", "NoTransformation"}, {"dir", {1, 4}}, {"sizeTrial", 3}};
        e = errorOf(b);
        QVERIFY2(e.contains("setup.dir") && e.contains("out of range [1, 3]"), qPrintable(e));

        b = {{"type", "NoTransformation"}, {"dir", {1, 1}}, {"sizeTrial", 3}};
        e = errorOf(b);
        QVERIFY2(e.contains("setup.") && e.contains("NoTransformation") && e.contains("twice"),
                 qPrintable(e));

        b = {{"type", "Aggregator"},
             {"setups", {{{"type", "TwoActuators2d"}, {"La1", 1.5}, {"La2", 1.2}, {"L", 0}}}}};
        e = errorOf(b);
        QVERIFY2(e.contains("setup.setups[0].L: TwoActuators2d: L = 0"), qPrintable(e));

        // FourActuators3d's axial-load rods: a rod of zero length, named
        json four;
        for (const Case& c : cases())
            if (std::string(c.name) == "FourActuators3d")
                four = c.block; // the rods 1 m long
        QVERIFY(!four.is_null());
        b = four;
        b["LrodN"] = 0.0;
        e = errorOf(b);
        QVERIFY2(e.contains("setup.LrodN: FourActuators3d: LrodN = 0 must be a positive finite "
                            "length (an axial-load rod's pin-to-pin length)"),
                 qPrintable(e));
        b = four;
        b["h1"] = "high";
        e = errorOf(b);
        QVERIFY2(e.contains("setup.h1") && e.contains("number"), qPrintable(e));

        // In a configuration: the link2d element's setup field, with the 3-DOF check.
        std::ifstream in(kPreset);
        const json preset = json::parse(in);
        auto configError = [&](const json& setup) {
            json doc = preset;
            doc["structure"]["elements"][0]["setup"] = setup;
            try {
                parseConfig(doc, "frame.json");
            } catch (const std::exception& x) {
                return QString(x.what());
            }
            return QString("accepted");
        };
        e = configError({{"type", "NoTransformation"}, {"dir", {1, 2}}, {"sizeTrial", 2}});
        QVERIFY2(e.contains("setup.type") && e.contains("NoTransformation serves 2 basic DOFs"),
                 qPrintable(e));
        e = configError(four); // six basic DOFs on a 3-DOF link2d
        QVERIFY2(e.contains("setup.type") && e.contains("FourActuators3d serves 6 basic DOFs"),
                 qPrintable(e));
    }

    void presetWithJsonSetupRunsIdentically() {
        std::ifstream in(kPreset);
        const json script = json::parse(in);
        json block = script;
        block["structure"]["elements"][0]["setup"] = {
            {"type", "NoTransformation"}, {"dir", {1, 2}}, {"sizeTrial", 3}};
        const auto a = run(script);
        const auto b = run(block);
        QCOMPARE(a.size(), std::size_t(201));
        QCOMPARE(b.size(), a.size());
        for (std::size_t i = 0; i < a.size(); ++i) {
            QVERIFY(a[i].u == b[i].u);
            QVERIFY(a[i].channels == b[i].channels);
        }
    }
};

QTEST_GUILESS_MAIN(TestSetupConfig)
#include "TestSetupConfig.moc"
