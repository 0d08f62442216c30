// Tests of the configuration loader and factory (core/config): a valid document parses into
// the expected TestConfig, every broken one fails with a ConfigError naming the file and the
// field path, and a relative ground-motion path is resolved from the configuration's folder.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/groundmotion/GroundMotion.h"
#include "core/integration/Integrator.h"
#include "core/structure/Structure.h"
#include "core/experiment/HybridTest.h"

#include <QtTest>

#include <cmath>
#include <fstream>
#include <functional>
#include <string>

using namespace hsmu;
using json = nlohmann::json;

namespace {

// An SDOF specimen test with every section present.
json baseDocument() {
    return json::parse(R"({
      "name": "loader test",
      "structure": {
        "dofs": [{"name": "top", "mass": 10.0}, {"name": "other", "mass": 5.0}],
        "equalDofs": [{"master": "top", "slave": "other"}],
        "damping": {"ratio": 0.05, "modes": [1, 1]},
        "elements": [{
          "name": "Spring", "type": "lateralSpring", "dof": "top",
          "material": {"law": "boucWen", "k0": 1.0, "uRef": 0.05, "fRef": 20.0},
          "experimental": true,
          "specimen": {
            "material": {"law": "boucWen", "k0": 1.1, "uRef": 0.05, "fRef": 20.0},
            "forceNoiseStd": 0.1, "seed": 5,
            "actuator": {"type": "lag", "timeConstant": 0.02}
          },
          "limits": {"deformation": 0.5, "force": 200.0, "increment": 0.05}
        }]
      },
      "groundMotion": {"builtin": "synthetic", "scale": 0.5},
      "analysis": {"integrator": "alphaOS", "alpha": -0.1, "dt": 0.01, "duration": 2.0}
    })");
}

void writeFile(const QString& path, const std::string& text) {
    std::ofstream out(path.toStdString());
    out << text;
}

// Loads and builds; returns the ConfigError message, or a marker if something else happened.
QString errorOf(const QString& path) {
    try {
        const TestConfig cfg = loadConfigFile(path.toStdString());
        buildHybridTest(cfg);
    } catch (const ConfigError& e) {
        return QString::fromStdString(e.what());
    } catch (const std::exception& e) {
        return "NOT A ConfigError: " + QString::fromStdString(e.what());
    }
    return "NO ERROR";
}

struct BrokenCase {
    const char* tag;
    std::function<void(json&)> mutate;
    QStringList expected; // substrings besides the file name
};

const std::vector<BrokenCase>& brokenCases() {
    static const std::vector<BrokenCase> cases = {
        {"missing structure", [](json& d) { d.erase("structure"); }, {"structure", "missing"}},
        {"missing mass",
         [](json& d) { d["structure"]["dofs"][0].erase("mass"); },
         {"structure.dofs[0].mass", "missing"}},
        {"mass is a string",
         [](json& d) { d["structure"]["dofs"][0]["mass"] = "heavy"; },
         {"structure.dofs[0].mass", "expected a number", "string"}},
        {"elements is an object",
         [](json& d) { d["structure"]["elements"] = json::object(); },
         {"structure.elements", "expected an array"}},
        {"seed is a number with decimals",
         [](json& d) { d["structure"]["elements"][0]["specimen"]["seed"] = 1.5; },
         {"structure.elements[0].specimen.seed", "integer"}},
        {"typo in an element field",
         [](json& d) { d["structure"]["elements"][0]["hieght"] = 3; },
         {"structure.elements[0].hieght", "unknown field"}},
        {"typo at top level",
         [](json& d) { d["analysys"] = json::object(); },
         {"analysys", "unknown field"}},
        {"typo in limits",
         [](json& d) { d["structure"]["elements"][0]["limits"]["forse"] = 1; },
         {"structure.elements[0].limits.forse", "unknown field"}},
        {"bad integrator",
         [](json& d) { d["analysis"]["integrator"] = "rk4"; },
         {"analysis.integrator", "explicitNewmark"}},
        {"bad element type",
         [](json& d) { d["structure"]["elements"][0]["type"] = "spring"; },
         {"structure.elements[0].type", "spring"}},
        {"bad actuator type",
         [](json& d) { d["structure"]["elements"][0]["specimen"]["actuator"]["type"] = "laggy"; },
         {"structure.elements[0].specimen.actuator.type", "laggy"}},
        {"bad DOF name",
         [](json& d) { d["structure"]["elements"][0]["dof"] = "DOF 9"; },
         {"structure.elements[0].dof", "DOF 9"}},
        {"duplicate element name, not next to its twin",
         [](json& d) {
             json& e = d["structure"]["elements"];
             json other = e[0];
             other["name"] = "Spring 2";
             e.push_back(other);
             e.push_back(e[0]);
         },
         {"structure.elements[2].name", "duplicate element name 'Spring'"}},
        {"DOF index out of range",
         [](json& d) { d["structure"]["elements"][0]["dof"] = 7; },
         {"structure.elements[0].dof", "7"}},
        {"bad equalDof slave",
         [](json& d) { d["structure"]["equalDofs"][0]["slave"] = "x"; },
         {"structure.equalDofs[0].slave", "'x'"}},
        {"zero mass",
         [](json& d) { d["structure"]["dofs"][1]["mass"] = 0.0; },
         {"structure.dofs[1].mass", "> 0"}},
        {"negative mass",
         [](json& d) { d["structure"]["dofs"][0]["mass"] = -2.0; },
         {"structure.dofs[0].mass", "> 0"}},
        {"ei on a specimen",
         [](json& d) {
             auto& e = d["structure"]["elements"][0];
             e["type"] = "rotationalBaseSpring";
             e["height"] = 3.0;
             e["ei"] = 5000.0;
         },
         {"structure.elements[0].ei", "specimen"}},
        {"specimen on a numerical element",
         [](json& d) { d["structure"]["elements"][0]["experimental"] = false; },
         {"structure.elements[0].specimen", "experimental"}},
        {"one damping mode",
         [](json& d) { d["structure"]["damping"]["modes"] = {1}; },
         {"structure.damping.modes", "two mode numbers"}},
        {"negative dt",
         [](json& d) { d["analysis"]["dt"] = -0.01; },
         {"analysis.dt", "[1e-06, 10] s"}},
        {"unknown law parameter",
         [](json& d) { d["structure"]["elements"][0]["material"]["k00"] = 1.0; },
         {"structure.elements[0].material", "k00"}},
        {"unknown specimen law parameter",
         [](json& d) { d["structure"]["elements"][0]["specimen"]["material"]["k00"] = 1.0; },
         {"structure.elements[0].specimen.material", "k00"}},
        {"unknown law name",
         [](json& d) { d["structure"]["elements"][0]["material"]["law"] = "boucwenn"; },
         {"structure.elements[0].material", "boucwenn"}},
        {"numericalSite on a specimen",
         [](json& d) { d["structure"]["elements"][0]["numericalSite"] = "opensees://127.0.0.1:7790"; },
         {"structure.elements[0].numericalSite", "numerical elements"}},
        {"numericalSite not an opensees address",
         [](json& d) {
             auto& e = d["structure"]["elements"][0];
             e.erase("specimen");
             e.erase("limits");
             e["experimental"] = false;
             e["numericalSite"] = "tcp://127.0.0.1:7790";
         },
         {"structure.elements[0].numericalSite", "opensees://HOST:PORT"}},
        {"numericalSite without a port",
         [](json& d) {
             auto& e = d["structure"]["elements"][0];
             e.erase("specimen");
             e.erase("limits");
             e["experimental"] = false;
             e["numericalSite"] = "opensees://127.0.0.1:0";
         },
         {"structure.elements[0].numericalSite", "port"}},
        {"numericalSite where nothing provides sites (core alone)",
         [](json& d) {
             auto& e = d["structure"]["elements"][0];
             e.erase("specimen");
             e.erase("limits");
             e["experimental"] = false;
             e["numericalSite"] = "opensees://127.0.0.1:7790";
         },
         {"element 'Spring'", "numericalSite", "not supported here"}},
        {"inadmissible law parameter",
         [](json& d) { d["structure"]["elements"][0]["material"]["alpha"] = 2.0; },
         {"structure.elements[0].material", "alpha"}},
    };
    return cases;
}

} // namespace

class TestConfigLoader : public QObject {
    Q_OBJECT
private slots:
    void parsesValidDocument();
    void unreadableFile();
    void jsonSyntaxError();
    void brokenDocument_data();
    void brokenDocument();
    void relativeGroundMotionFromConfigFolder_data();
    void relativeGroundMotionFromConfigFolder();

private:
    QTemporaryDir m_dir;
};

void TestConfigLoader::parsesValidDocument() {
    QVERIFY(m_dir.isValid());
    const QString path = m_dir.filePath("valid.json");
    writeFile(path, "// comments are allowed\n" + baseDocument().dump(2));
    const TestConfig cfg = loadConfigFile(path.toStdString());
    QCOMPARE(QString::fromStdString(cfg.name), QString("loader test"));
    QCOMPARE(QString::fromStdString(cfg.sourcePath), path);
    QCOMPARE(int(cfg.dofs.size()), 2);
    QCOMPARE(cfg.dofs[1].mass, 5.0);
    QCOMPARE(int(cfg.equalDofs.size()), 1);
    QVERIFY(cfg.equalDofs[0] == std::make_pair(0, 1)); // names resolved to indices
    QVERIFY(cfg.damping.kind == DampingSpec::Kind::ModalRatio);
    QCOMPARE(cfg.damping.modeJ, 1);
    const ElementSpec& e = cfg.elements.at(0);
    QVERIFY(e.experimental);
    QVERIFY(e.dofs == std::vector<int>{0});
    QCOMPARE(e.material.params.at("uRef"), 0.05);
    QCOMPARE(e.specimen.trueMaterial.params.at("k0"), 1.1);
    QVERIFY(e.specimen.options.actuator.type == ActuatorModel::Type::Lag);
    QCOMPARE(e.specimen.options.actuator.timeConstant, 0.02);
    QCOMPARE(e.specimen.options.forceNoiseStd, 0.1);
    QCOMPARE(e.specimen.options.seed, std::uint64_t(5));
    QCOMPARE(e.limits.maxIncrement, 0.05);
    QCOMPARE(cfg.groundMotion.scale, 0.5);
    QCOMPARE(QString::fromStdString(cfg.analysis.integrator), QString("alphaOS"));
    QCOMPARE(cfg.analysis.alpha, -0.1);

    auto test = buildHybridTest(cfg);
    QVERIFY2(test->prepare(), test->lastError().c_str());
    QCOMPARE(test->structure().freeDofCount(), 1);
    QCOMPARE(test->totalSteps(), 200);
    QCOMPARE(QString::fromStdString(test->integrator().name()), QString("alphaOS"));
}

void TestConfigLoader::unreadableFile() {
    const QString path = m_dir.filePath("does-not-exist.json");
    const QString msg = errorOf(path);
    QVERIFY2(msg.contains(path) && msg.contains("cannot open"), qPrintable(msg));
}

void TestConfigLoader::jsonSyntaxError() {
    const QString path = m_dir.filePath("syntax.json");
    writeFile(path, "{\n  \"name\": \"x\",\n  \"structure\": { , }\n}\n");
    const QString msg = errorOf(path);
    QVERIFY2(msg.contains("syntax.json") && msg.contains("not valid JSON") &&
                 msg.contains("line 3"),
             qPrintable(msg));
}

void TestConfigLoader::brokenDocument_data() {
    QTest::addColumn<int>("index");
    for (std::size_t i = 0; i < brokenCases().size(); ++i)
        QTest::newRow(brokenCases()[i].tag) << int(i);
}

void TestConfigLoader::brokenDocument() {
    QFETCH(int, index);
    const BrokenCase& c = brokenCases()[std::size_t(index)];
    json doc = baseDocument();
    c.mutate(doc);
    const QString path = m_dir.filePath(QString("broken-%1.json").arg(index));
    writeFile(path, doc.dump(2));
    const QString msg = errorOf(path);
    QVERIFY2(msg.contains(QString("broken-%1.json").arg(index)),
             qPrintable("no file name: " + msg));
    for (const QString& s : c.expected)
        QVERIFY2(msg.contains(s), qPrintable("no '" + s + "' in: " + msg));
}

void TestConfigLoader::relativeGroundMotionFromConfigFolder_data() {
    QTest::addColumn<bool>("decoy");
    QTest::newRow("empty working directory") << false;
    QTest::newRow("same relative path in the working directory") << true;
}

void TestConfigLoader::relativeGroundMotionFromConfigFolder() {
    // <row>/config/test.json names "records/motion.txt"; the working directory is <row>/cwd,
    // which may hold a decoy at the same relative path that must not be picked up.
    QFETCH(bool, decoy);
    const QString root = m_dir.filePath(decoy ? "decoy" : "plain");
    QVERIFY(QDir().mkpath(root + "/config/records"));
    QVERIFY(QDir().mkpath(root + "/cwd/records"));
    writeFile(root + "/config/records/motion.txt",
              "# time [s]  acceleration [g]\n0.00 0.0\n0.02 0.1\n0.04 -0.2\n0.06 0.05\n");
    if (decoy)
        writeFile(root + "/cwd/records/motion.txt", "0.0 0.9\n0.5 0.9\n1.0 0.9\n");
    json doc = baseDocument();
    doc["groundMotion"] = {{"file", "records/motion.txt"}, {"format", "time-acc"}, {"units", "g"}};
    const QString path = root + "/config/test.json";
    writeFile(path, doc.dump(2));

    const TestConfig cfg = loadConfigFile(path.toStdString());
    const QString previous = QDir::currentPath();
    QVERIFY(QDir::setCurrent(root + "/cwd"));
    GroundMotion gm;
    QString error;
    try {
        gm = buildGroundMotion(cfg.groundMotion, cfg.sourcePath);
    } catch (const std::exception& e) {
        error = QString::fromStdString(e.what());
    }
    QDir::setCurrent(previous);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY2(gm.dt == 0.02, qPrintable(QString("read the working directory's records/motion.txt "
                                               "(dt %1 s) instead of the configuration folder's")
                                           .arg(gm.dt)));
    QCOMPARE(int(gm.acceleration.size()), 4);
    // Unit conversion by g = 9.80665 m/s^2: one multiplication, 1e-12 relative.
    const double expected[] = {0.0, 0.1, -0.2, 0.05};
    for (int i = 0; i < 4; ++i)
        QVERIFY2(std::abs(gm.acceleration[i] - expected[i] * kStandardGravity) < 1e-12,
                 qPrintable(QString("sample %1: %2").arg(i).arg(gm.acceleration[i])));
}

QTEST_APPLESS_MAIN(TestConfigLoader)
#include "TestConfigLoader.moc"
