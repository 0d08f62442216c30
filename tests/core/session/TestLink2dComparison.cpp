// `hsmu compare` with a link2d specimen (core/session/ComparisonProtocol.h, ChannelComparison.h;
// docs/cli.md "Per basic DOF and per actuator"), on the preset two-actuator-column-frame with
// the shear DOF of Column L identified and Column R's shear DOF updated (updating.basicDof), the
// twin's rotation free as the specimen's (so that the twin with the true law IS the specimen):
//  - without a perturbation (the twin starts with the specimen's true law) the initial run
//    equals the reference (Column R a copy of the link2d specimen) in every basic DOF but one:
//    shear and rotation deformations and forces, the axial force, to 1e-9 of the peak; the
//    axial deformation differs by the vertical actuator's elastic shortening P / k =
//    500 / 2e5 = 0.0025 m exactly where the numerical twin's is 0 (NRMSE 1); each actuator of
//    the specimen tracks its command exactly (J2 = J3 = 0; the lab is ideal) and its force
//    equals the reference's; the units are the DOF's (m | rad, kN | kN m) and the actuator's
//    (m for the displacement-controlled lateral one, kN for the force-controlled vertical one);
//  - with the perturbation (a wrong initial law) the twin's shear force error is large in the
//    initial run and smaller in the updated one, and the lateral actuator's force error equals
//    the specimen's shear force error (NoTransformation: f = q), to 1e-12 relative;
//  - with the lateral actuator delayed 30 ms (three steps) its tracking J1 is 30 ms (within
//    1 ms: the correlation's parabola) and its J2 the hand-computed RMS error of stroke against
//    command (1e-9 relative).
// compare.json carries both lists with their units, and the specimen's true shear law (the
// lateral actuator's material). Units: kN, m, rad, s.

#include "core/config/ConfigLoader.h"
#include "core/session/ComparisonProtocol.h"
#include "core/session/ComparisonSummary.h"

#include <QtTest>

#include <cmath>
#include <fstream>

#include "../config/Link2dFrameFixture.h"

using namespace hsmu;

namespace {

const std::string kPreset = HSMU_SOURCE_DIR "/resources/presets/two-actuator-column-frame.json";

const nlohmann::json& kTrueLaw = link2dframe::kLateralLaw;
nlohmann::json wrongLaw() { return link2dframe::wrongLateralLaw(); }

TestConfig frame(const nlohmann::json& twinShear, const nlohmann::json& lateralModel = nullptr)
{
    std::ifstream in(kPreset);
    nlohmann::json doc = nlohmann::json::parse(in);
    nlohmann::json& els = doc["structure"]["elements"];
    els[1]["basic"][1]["material"] = twinShear;
    els[1]["basic"][2] = nlohmann::json::object(); // a free rotation, as the specimen's
    if (!lateralModel.is_null())
        els[0]["actuators"][1]["actuator"] = lateralModel;
    doc["updating"] = {{"specimen", "Column L"},
                       {"basicDof", "shear"},
                       {"model", wrongLaw()},
                       {"reporter", {{"targets", {{{"element", "Column R"}}}}}}};
    TestConfig cfg = parseConfig(doc, "frame.json");
    cfg.analysis.duration = 4.0;
    return cfg;
}

const BasicDofComparison& dof(const ComparisonRun& run, const std::string& element,
                              const std::string& name)
{
    for (const BasicDofComparison& b : run.basicDofs)
        if (b.element == element && b.dof == name)
            return b;
    qFatal("no basic DOF %s of %s", name.c_str(), element.c_str());
    return run.basicDofs.front();
}

const ActuatorComparison& actuator(const ComparisonRun& run, const std::string& element,
                                   const std::string& name)
{
    for (const ActuatorComparison& a : run.actuators)
        if (a.element == element && a.actuator == name)
            return a;
    qFatal("no actuator %s of %s", name.c_str(), element.c_str());
    return run.actuators.front();
}

double peakOf(const std::vector<double>& x)
{
    double p = 0.0;
    for (double v : x)
        p = std::max(p, std::abs(v));
    return p;
}

} // namespace

class TestLink2dComparison : public QObject {
    Q_OBJECT

private slots:
    void withoutPerturbationTheInitialRunIsTheReference()
    {
        const ComparisonResult r = runComparison(frame(kTrueLaw));
        QCOMPARE(r.reference.finalState, std::string("finished"));
        QCOMPARE(r.initial.finalState, std::string("finished"));
        QCOMPARE(r.forceUnit, std::string("kN"));
        const ComparisonRun& i = r.initial;
        QCOMPARE(int(i.basicDofs.size()), 9); // Column L, Column R and the beam, 3 each
        for (const char* element : {"Column L", "Column R"})
            for (const char* name : {"shear", "rotation"}) {
                const BasicDofComparison& b = dof(i, element, name);
                const double peakD = peakOf(channelSeries(r.reference.channels, element,
                                                          std::string(name) + " deformation"));
                const double peakF = std::max(1.0, peakOf(channelSeries(
                                                       r.reference.channels, element,
                                                       std::string(name) + " force")));
                qInfo("%s %s: deformation error %.3g of %.4g, force error %.3g of %.4g", element,
                      name, b.deformationPeakError, peakD, b.forcePeakError, peakF);
                QVERIFY(peakD > 0.0 || std::string(name) == "rotation");
                QVERIFY(b.deformationPeakError <= 1e-9 * std::max(peakD, 1e-3));
                QVERIFY(b.forcePeakError <= 1e-9 * peakF);
            }
        QCOMPARE(dof(i, "Column R", "shear").deformationUnit, std::string("m"));
        QCOMPARE(dof(i, "Column R", "shear").forceUnit, std::string("kN"));
        QCOMPARE(dof(i, "Column R", "rotation").deformationUnit, std::string("rad"));
        QCOMPARE(dof(i, "Column R", "rotation").forceUnit, std::string("kN m"));
        const BasicDofComparison& axial = dof(i, "Column R", "axial");
        QVERIFY(axial.forcePeakError <= 1e-9 * 500.0);
        QVERIFY(std::abs(axial.deformationPeakError - 500.0 / 2e5) <= 1e-12);
        QVERIFY(std::abs(axial.deformationNrmse - 1.0) <= 1e-12);

        QCOMPARE(int(r.reference.actuators.size()), 4); // both columns are specimens there
        QCOMPARE(int(i.actuators.size()), 2);
        const ActuatorComparison& v = actuator(i, "Column L", "vertical");
        const ActuatorComparison& l = actuator(i, "Column L", "lateral");
        QCOMPARE(v.control, std::string("force"));
        QCOMPARE(v.commandUnit, std::string("kN"));
        QCOMPARE(l.control, std::string("displacement"));
        QCOMPARE(l.commandUnit, std::string("m"));
        QCOMPARE(l.forceUnit, std::string("kN"));
        QVERIFY(v.compared && l.compared);
        QVERIFY(v.tracking.j2 <= 1e-9 && l.tracking.j2 == 0.0 && l.tracking.j3 == 0.0);
        QVERIFY(v.forcePeakError <= 1e-9 * 500.0);
        QVERIFY(l.forcePeakError <= 1e-9 * peakOf(channelSeries(i.channels, "Column L",
                                                                "lateral force")));
    }

    void withPerturbationTheErrorsShowAndShrink()
    {
        const TestConfig cfg = frame(wrongLaw());
        const ComparisonResult r = runComparison(cfg);
        QCOMPARE(r.updated.finalState, std::string("finished"));
        const double initial = dof(r.initial, "Column R", "shear").forceNrmse;
        const double updated = dof(r.updated, "Column R", "shear").forceNrmse;
        qInfo("Column R shear force NRMSE: initial %.4g, updated %.4g", initial, updated);
        QVERIFY(initial > 0.05);
        QVERIFY(updated < initial);
        for (const ComparisonRun* run : {&r.initial, &r.updated}) {
            const ActuatorComparison& l = actuator(*run, "Column L", "lateral");
            const BasicDofComparison& s = dof(*run, "Column L", "shear");
            QVERIFY(s.forceNrmse > 0.0);
            QVERIFY(std::abs(l.forceNrmse - s.forceNrmse) <= 1e-12 * s.forceNrmse);
            QVERIFY(std::abs(l.forcePeakError - s.forcePeakError) <= 1e-12 * s.forcePeakError);
        }
        const nlohmann::json j = makeComparisonSummary(r, cfg);
        const nlohmann::json& dofs = j["runs"]["initial"]["basic_dofs"];
        QCOMPARE(int(dofs.size()), 9);
        bool found = false;
        for (const auto& d : dofs)
            if (d["element"] == "Column R" && d["dof"] == "rotation") {
                found = true;
                QCOMPARE(d["deformation_unit"].get<std::string>(), std::string("rad"));
                QCOMPARE(d["force_unit"].get<std::string>(), std::string("kN m"));
            }
        QVERIFY(found);
        QCOMPARE(int(j["reference"]["actuators"].size()), 4);
        const nlohmann::json& a = j["runs"]["updated"]["actuators"][1];
        QCOMPARE(a["actuator"].get<std::string>(), std::string("lateral"));
        QCOMPARE(a["command_unit"].get<std::string>(), std::string("m"));
        QVERIFY(a.contains("force_nrmse") && a["tracking"].contains("J2_percent"));
        QVERIFY(!j["reference"].contains("basic_dofs"));
        // The true law: the lateral actuator's material (NoTransformation -dir 1 2: actuator 2
        // drives the shear DOF alone); the updated estimate close to it.
        const nlohmann::json& truth = j["true_parameters"];
        QCOMPARE(truth["alpha"].get<double>(), 0.05);
        QCOMPARE(truth["beta"].get<double>(), 3.0);
        QCOMPARE(truth["n"].get<double>(), 2.0);
        QVERIFY(std::abs(j["final_parameters"]["alpha"].get<double>() - 0.05) <= 0.01);
    }

    void delayedActuatorTracking()
    {
        const ComparisonResult r =
            runComparison(frame(wrongLaw(), {{"type", "delay"}, {"delay", 0.03}}));
        const ActuatorComparison& l = actuator(r.initial, "Column L", "lateral");
        const std::vector<double> c = channelSeries(r.initial.channels, "Column L",
                                                    "lateral command");
        const std::vector<double> s = channelSeries(r.initial.channels, "Column L",
                                                    "lateral stroke");
        double se = 0.0, sc = 0.0;
        for (std::size_t k = 0; k < c.size(); ++k) {
            se += (s[k] - c[k]) * (s[k] - c[k]);
            sc += c[k] * c[k];
        }
        const double j2 = 100.0 * std::sqrt(se / sc);
        qInfo("lateral J1 %.4g ms, J2 %.4g %% (by hand %.4g %%)", l.tracking.j1, l.tracking.j2,
              j2);
        QVERIFY(std::abs(l.tracking.j1 - 30.0) <= 1.0);
        QVERIFY(j2 > 0.0);
        QVERIFY(std::abs(l.tracking.j2 - j2) <= 1e-9 * j2);
        QVERIFY(s.size() > 10 && s[4] == c[1]); // three steps late
    }
};

QTEST_APPLESS_MAIN(TestLink2dComparison)
#include "TestLink2dComparison.moc"
