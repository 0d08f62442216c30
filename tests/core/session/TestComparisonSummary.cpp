// ComparisonSummary: compare.json's keys and values from a ComparisonResult (built by hand, so
// every number is known), null for non-finite numbers, the specimen's true parameters from
// the configuration, and the file written.

#include "tests/core/output/OutputFixture.h"

#include "core/session/ComparisonSummary.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>

using namespace hsmu;
using namespace hsmu::testsupport;

namespace {

ComparisonRun run(const std::string& name, int steps, const std::string& state) {
    ComparisonRun r;
    r.name = name;
    r.steps = steps;
    r.finalState = state;
    return r;
}

ComparisonResult sample() {
    ComparisonResult r;
    r.element = "Element 2";
    r.dof = "DOF 2";
    r.forceUnit = "kN m";
    r.deformationUnit = "rad";
    r.reference = run("reference", 100, "finished");
    r.initial = run("initial", 100, "finished");
    r.updated = run("updated", 100, "finished");
    r.updated.parameterNames = {"k0", "n"};
    r.updated.parameters = {{1.3, 1.2}, {1.05, 1.9}};
    r.updated.stddev = {{0.2, 0.5}, {0.01, 0.02}};
    r.updated.appliedUpdates = 42;
    r.updated.alarms = {"t = 1 s: something"};
    r.reference.sites = {"controller", "Lab B"};
    r.reference.linkSecurity = {{"controller", "builtin"}, {"Lab B", "builtin"}};
    r.updated.sites = {"controller"};
    r.updated.linkSecurity = {{"controller", "builtin"}};
    r.initialMetric = {0.4, 3.5, 0.3, 0.02};
    r.updatedMetric = {0.04, 0.5, NAN, 0.002};
    return r;
}

} // namespace

class TestComparisonSummary : public QObject {
    Q_OBJECT
private slots:
    void keysAndValues() {
        const TestConfig cfg = condition3(1.0);
        const nlohmann::json j = makeComparisonSummary(sample(), cfg);
        QCOMPARE(j.at("config").at("name").get<std::string>(), cfg.name);
        QCOMPARE(j.at("element").get<std::string>(), std::string("Element 2"));
        QCOMPARE(j.at("dof").get<std::string>(), std::string("DOF 2"));
        QCOMPARE(j.at("force_unit").get<std::string>(), std::string("kN m"));
        QCOMPARE(j.at("displacement_unit").get<std::string>(), std::string("m"));
        const auto& initial = j.at("runs").at("initial");
        QCOMPARE(initial.at("force_nrmse").get<double>(), 0.4);
        QCOMPARE(initial.at("force_peak_error").get<double>(), 3.5);
        QCOMPARE(initial.at("displacement_nrmse").get<double>(), 0.3);
        QCOMPARE(initial.at("displacement_peak_error").get<double>(), 0.02);
        QCOMPARE(initial.at("final_state").get<std::string>(), std::string("finished"));
        const auto& updated = j.at("runs").at("updated");
        QCOMPARE(updated.at("force_nrmse").get<double>(), 0.04);
        QVERIFY(updated.at("displacement_nrmse").is_null()); // NaN -> null
        QVERIFY(!j.at("runs").contains("reference"));
        QCOMPARE(j.at("reference").at("steps").get<int>(), 100);
        QCOMPARE(j.at("final_parameters").at("k0").get<double>(), 1.05);
        QCOMPARE(j.at("final_parameters").at("n").get<double>(), 1.9);
        QCOMPARE(j.at("final_standard_deviations").at("n").get<double>(), 0.02);
        QCOMPARE(j.at("applied_updates").get<int>(), 42);
        QCOMPARE(j.at("steps").get<int>(), 100);
        QCOMPARE(j.at("alarms").at("updated").size(), std::size_t(1));
        // The specimen's own law (the preset's "specimen" material of Element 1).
        QCOMPARE(j.at("true_parameters").at("k0").get<double>(), 1.0);
        QCOMPARE(j.at("true_parameters").at("n").get<double>(), 2.0);
        QCOMPARE(j.at("true_parameters").size(), std::size_t(2));
        // Each run's link_security: its own sites (the reference has more specimens); a run
        // with no sites has an empty object.
        QCOMPARE(j.at("reference").at("link_security"),
                 (nlohmann::json{{"controller", "builtin"}, {"Lab B", "builtin"}}));
        QCOMPARE(updated.at("link_security"), (nlohmann::json{{"controller", "builtin"}}));
        QVERIFY(initial.at("link_security").is_object() && initial.at("link_security").empty());
    }

    void trueParametersOnlyForTheUpdatingSpecimen() {
        TestConfig cfg = condition3(1.0);
        QCOMPARE(trueParameters(cfg, {"alpha", "nope"}).size(), std::size_t(1));
        cfg.updating.specimen = "Element 2"; // not experimental
        QVERIFY(trueParameters(cfg, {"alpha"}).empty());
        cfg.updating.specimen = "Element 1";
        cfg.elements[0].material.law = "bilinear"; // another law: nothing comparable
        QVERIFY(trueParameters(cfg, {"k0"}).empty());
    }

    void writesTheFile() {
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("compare.json")).toStdString();
        writeComparisonJson(path, sample(), condition3(1.0));
        std::ifstream in(path);
        const nlohmann::json j = nlohmann::json::parse(in);
        QCOMPARE(j.at("runs").size(), std::size_t(2));
        QVERIFY_THROWS_EXCEPTION(
            std::runtime_error,
            writeComparisonJson("/nonexistent-dir/x/compare.json", sample(), condition3(1.0)));
    }
};

QTEST_APPLESS_MAIN(TestComparisonSummary)
#include "TestComparisonSummary.moc"
