// Identification and updating on one basic DOF of a multi-DOF specimen (docs/setups.md,
// "Identification and updating on a basic DOF"; docs/configuration.md, updating.basicDof):
// the shipped preset two-actuator-column-frame (a one-bay frame whose left column is a link2d
// specimen behind expSetup NoTransformation: a vertical actuator holding -500 kN on the axial
// DOF, a lateral actuator on the shear DOF whose Bouc-Wen material is the shear law, known) with
// the right column a link2d twin.
//  - The shear DOF's history as the setup recovers it (basic deformation and force, S3-S4)
//    equals the lateral actuator's stroke and force (the setup's closed form here), and the
//    axial DOF's force is the held -500 kN: a wrong DOF would be seen at once.
//  - The robust UKF (online) and the calibration (offline, on that history) identify the
//    shear law's parameters from it, starting from a wrong model.
//  - A run whose twin's shear DOF takes one approved update while the frame is at rest equals
//    (1e-9 of the peak) a run whose twin starts with those parameters; the twin's other DOFs
//    are untouched, and the update is in the record with the identified DOF.
//  - Errors: a basic DOF out of range (specimen, target, one-DOF specimen), a twin DOF with a
//    held force or a free DOF, a link2d specimen without a model, a model for a one-DOF
//    specimen; the same through the API (Reporter::bind, ModelUpdater::attach).
// Units: kN, m, s, t; Bouc-Wen parameters normalized by uRef / fRef.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/experimental/ExperimentalLink2d.h"
#include "core/identification/CalibrationDefaults.h"
#include "core/offline/SpecimenHistory.h"
#include "core/record/RecordReader.h"
#include "core/session/TestSession.h"
#include "core/structure/Link2dElement.h"
#include "core/structure/Structure.h"
#include "core/updating/ModelUpdater.h"
#include "core/updating/RobustUkfIdentifier.h"

#include <QtTest>

#include <cmath>
#include <fstream>

#include "../config/Link2dFrameFixture.h"

using namespace hsmu;

namespace {

const std::string kPreset = HSMU_SOURCE_DIR "/resources/presets/two-actuator-column-frame.json";

// The specimen's true shear law (the lateral actuator's material) and a wrong initial model.
const nlohmann::json& kTrueLaw = link2dframe::kLateralLaw;
nlohmann::json wrongModel() { return link2dframe::wrongLateralLaw(); }

nlohmann::json presetJson()
{
    std::ifstream in(kPreset);
    return nlohmann::json::parse(in);
}

// The preset: the specimen reports its axial DOF (primary 0), the twin its rotation (primary
// 2), so that the identified and updated shear DOF is neither's reported one; the twin's shear
// law starts as `twinShear`.
nlohmann::json frame(const nlohmann::json& twinShear)
{
    nlohmann::json doc = presetJson();
    nlohmann::json& els = doc["structure"]["elements"];
    els[0]["primary"] = 0;
    els[0]["actuators"][1]["material"] = kTrueLaw;
    els[1]["primary"] = 2;
    els[1]["basic"][1]["material"] = twinShear;
    return doc;
}

nlohmann::json updating(const nlohmann::json& extra = nlohmann::json::object())
{
    nlohmann::json u = {{"specimen", "Column L"},
                        {"basicDof", "shear"},
                        {"model", wrongModel()},
                        {"reporter", {{"targets", {{{"element", "Column R"}}}}}}};
    u.merge_patch(extra);
    return u;
}

struct Recorder final : StepObserver {
    std::vector<StepRecord> records;
    void onStep(const StepRecord& r) override { records.push_back(r); }
};

// A ground motion file (time [s], acceleration [m/s^2]): `rest` s of zeros, then a 1.5 Hz sine
// of amplitude a for `shaking` s.
std::string restThenSine(const QTemporaryDir& dir, double rest, double shaking, double a)
{
    const std::string path = dir.filePath("motion.txt").toStdString();
    std::ofstream out(path);
    out.precision(17);
    const double dt = 0.01;
    for (int k = 0; k * dt <= rest + shaking + 1e-9; ++k) {
        const double t = k * dt;
        out << t << ' ' << (t <= rest ? 0.0 : a * std::sin(2.0 * M_PI * 1.5 * (t - rest)))
            << '\n';
    }
    return path;
}

QString errorOf(const nlohmann::json& doc)
{
    try {
        buildHybridTest(parseConfig(doc, "frame.json"));
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

Link2dElement& twin(HybridTest& t)
{
    return *dynamic_cast<Link2dElement*>(t.structure().element("Column R"));
}

double parameter(HysteresisLaw* law, const std::string& name)
{
    return law->parameterValue(law->parameterIndex(name));
}

} // namespace

class TestBasicDofUpdating : public QObject {
    Q_OBJECT
private slots:
    // The recovered shear history is the lateral actuator's, and the UKF online and the
    // calibration offline identify the shear law from it.
    void identifiesTheShearLawFromTheRecoveredBasicHistory()
    {
        nlohmann::json doc = frame(wrongModel());
        doc["updating"] = updating();
        TestConfig cfg = parseConfig(doc, "frame.json");
        cfg.analysis.duration = 20.0;
        QCOMPARE(cfg.updating.basicDof, 1);
        auto test = buildHybridTest(cfg);
        QVERIFY(test->updater() && test->updater()->basicDof() == 1);
        QVERIFY2(test->prepare(), test->lastError().c_str());
        auto* specimen = dynamic_cast<ExperimentalLink2d*>(test->structure().element("Column L"));
        QVERIFY(specimen);
        std::vector<double> d, f;
        double worstStroke = 0.0, worstForce = 0.0, worstAxial = 0.0, peak = 0.0;
        while (test->step() == HybridTest::StepResult::Advanced) {
            const ControlMeasurement m = specimen->basicMeasurement(1);
            d.push_back(m.deformation);
            f.push_back(m.force);
            // NoTransformation -dir 1 2: actuator 2 (lateral) is the shear DOF (S1, S3).
            worstStroke = std::max(worstStroke, std::abs(m.deformation - specimen->strokes()[1]));
            worstForce = std::max(worstForce, std::abs(m.force - specimen->actuatorForces()[1]));
            worstAxial = std::max(worstAxial, std::abs(specimen->basicMeasurement(0).force + 500.0));
            peak = std::max(peak, std::abs(m.deformation));
        }
        QCOMPARE(int(test->state()), int(HybridTest::State::Finished));
        QCOMPARE(worstStroke, 0.0);
        QCOMPARE(worstForce, 0.0);
        QVERIFY2(worstAxial < 1e-9, qPrintable(QString::number(worstAxial)));
        qInfo("shear history: %zu samples, peak %.4f m (uRef 0.01: yielding)", d.size(), peak);
        QVERIFY(peak > 2.0 * 0.01);

        // Online: the robust UKF's estimate and the twin's shear law after the updates.
        const ModelUpdater& up = *test->updater();
        const ParameterLayout& layout = up.layout();
        const auto est = up.identifier().estimate();
        HysteresisLaw* twinShear = twin(*test).basicLaw(1);
        for (const char* name : {"k0", "alpha", "beta", "gamma", "n"}) {
            const double truth = kTrueLaw[name];
            const double online = est[*layout.find(name)];
            qInfo("%-5s true %.4f  UKF %.4f (error %.2e)  twin %.4f", name, truth, online,
                  std::abs(online - truth), parameter(twinShear, name));
            QVERIFY(std::abs(parameter(twinShear, name) - online) <= 1e-12 * std::abs(online));
        }
        QVERIFY(up.reporter().appliedCount() > 0);
        // The history is the true law's, noise-free (the built-in lab): every parameter to
        // 1e-6 of its value (measured: 1.3e-15 at worst).
        for (const char* name : {"k0", "alpha", "beta", "gamma", "n"})
            QVERIFY2(std::abs(est[*layout.find(name)] - double(kTrueLaw[name])) <=
                         1e-6 * double(kTrueLaw[name]),
                     name);
        QVERIFY(std::abs(twin(*test).basicLaw(2)->initialTangent() - 5000.0) == 0.0);
        QCOMPARE(twin(*test).basicLaw(0), nullptr); // the held axial force stays one
        // The auxiliary model (the identified shear law) reproduces the measured shear force.
        qInfo("auxiliary model fit error at the end: %.2e", up.inspector().fitError());
        QVERIFY(up.inspector().fitError() < 1e-9);

        // Offline: the calibration of the same recovered history.
        CalibrationRequest request;
        request.uRef = 0.01;
        request.fRef = 100.0;
        const CalibrationResult c = calibrateHistory(d, f, request);
        QVERIFY2(c.ok, c.reason.c_str());
        double worstCal = 0.0;
        for (const char* name : {"k0", "alpha", "beta", "gamma", "n"})
            worstCal = std::max(worstCal, std::abs(c.parameters.at(name) - double(kTrueLaw[name])) /
                                              double(kTrueLaw[name]));
        qInfo("calibration: NRMSE %.2e, worst relative parameter error %.2e", c.nrmse, worstCal);
        QVERIFY(c.nrmse < 1e-9);
        QVERIFY(worstCal <= 1e-6); // every parameter to 1e-6 of its value
    }

    // Nelder-Mead (through the calibration's refit) on the shear DOF, and the record: the
    // identified DOF in /updating, offline identification reading its channels.
    void nelderMeadAndTheRecordTakeTheBasicDof()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        nlohmann::json doc = frame(wrongModel());
        doc["updating"] = updating({{"method", "nelderMead"}, {"nelderMead", {{"cooldown", 2.0}}}});
        const std::string source = dir.filePath("frame.json").toStdString();
        TestConfig cfg = parseConfig(doc, source);
        cfg.analysis.duration = 12.0;
        const std::string record = dir.filePath("record.h5").toStdString();
        {
            SessionOptions o;
            o.recordPath = record;
            o.recordStart = RecordStart{cfg.raw.dump(), cfg.name, {}, cfg.analysis.dt};
            auto test = buildHybridTest(cfg);
            HybridTest* t = test.get();
            TestSession s(std::move(test), o);
            QVERIFY(s.prepare());
            QVERIFY(s.openRecord());
            QCOMPARE(s.runToEnd(), TestSession::Status::Finished);
            const ModelUpdater& up = *t->updater();
            QVERIFY(up.reporter().appliedCount() > 0);
            const auto est = up.identifier().estimate();
            const double k0 = est[*up.layout().find("k0")];
            const double alpha = est[*up.layout().find("alpha")];
            qInfo("Nelder-Mead (calibration refits): k0 %.4f alpha %.4f, fit error %.2e", k0,
                  alpha, up.inspector().fitError());
            QVERIFY(std::abs(k0 - 1.0) <= 1e-6);
            QVERIFY(std::abs(alpha - 0.05) <= 1e-6 * 0.05);
            QCOMPARE(parameter(twin(*t).basicLaw(1), "alpha"), alpha);
        }
        // The robust UKF seeded from that record: the shear DOF's channels are calibrated.
        nlohmann::json seeded = frame(wrongModel());
        seeded["updating"] = updating({{"ukf", {{"seedRecord", record}}}});
        auto t = buildHybridTest(parseConfig(seeded, source));
        const auto* id = dynamic_cast<const RobustUkfIdentifier*>(&t->updater()->identifier());
        QVERIFY(id && id->seeded());
        qInfo("seed anchor NRMSE over the recorded shear DOF: %.2e", id->anchorNrmse());
        QVERIFY(id->anchorNrmse() < 1e-3);
        const RecordReader reader(record);
        const RecordData& r = reader.data();
        QVERIFY(r.layout.updating.has_value());
        QCOMPARE(r.layout.updating->basicDof, std::string("shear"));
        QCOMPARE(r.layout.updating->units.deformation, std::string("m"));
        QVERIFY(!r.updateEvents.empty());
        // Offline identification reads the identified DOF's channels, not the primary column
        // (the axial DOF: its force is the held -500 kN): the lateral actuator's stroke and
        // force (NoTransformation), recorded as channels of their own.
        const SpecimenHistory h = historyFromRecord(r, "Column L", "record");
        QCOMPARE(h.size(), r.rows() - 1);
        int stroke = -1, force = -1;
        for (std::size_t c = 0; c < r.layout.channels.size(); ++c) {
            if (r.layout.channels[c].element != "Column L")
                continue;
            stroke = r.layout.channels[c].name == "lateral stroke" ? int(c) : stroke;
            force = r.layout.channels[c].name == "lateral force" ? int(c) : force;
        }
        QVERIFY(stroke >= 0 && force >= 0);
        double worst = 0.0, peak = 0.0;
        for (int k = 0; k < h.size(); ++k) {
            worst = std::max(worst, std::abs(h.deformation[std::size_t(k)] - r.channels(k + 1, stroke)));
            worst = std::max(worst, std::abs(h.force[std::size_t(k)] - r.channels(k + 1, force)));
            peak = std::max(peak, std::abs(h.force[std::size_t(k)]));
        }
        QCOMPARE(worst, 0.0);
        QVERIFY(peak > 50.0);
        QVERIFY(std::abs(r.force(1, 0) + 500.0) < 1e-9); // the record's column: the axial DOF
    }

    // One approved update of the twin's shear DOF while the frame is at rest, then the run
    // equals a run whose twin starts with the approved parameters.
    void approvedUpdateEqualsARunStartedWithIt()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string motion = restThenSine(dir, 0.5, 5.0, 2.5);
        auto withMotion = [&](nlohmann::json doc) {
            doc["groundMotion"] = {{"file", motion}, {"format", "time-acc"}, {"units", "m/s^2"}};
            return doc;
        };
        // The paper's UKF offers its estimate from the first step; at rest (no force, no
        // deformation) it is its starting model, here the specimen's true shear law, while
        // the twin's shear DOF starts from the wrong one.
        const std::string source = dir.filePath("frame.json").toStdString();
        const std::vector<std::string> sent = {"alpha", "beta", "gamma", "n"}; // K0 unchanged
        nlohmann::json a = withMotion(frame(wrongModel()));
        a["updating"] = updating(
            {{"model", kTrueLaw},
             {"ukf", {{"formulation", "paper"}}},
             {"bounds", {{"alpha", {0.0, 0.5}}, {"beta", {0.0, 5.0}}, {"gamma", {-2.0, 5.0}},
                         {"n", {1.0, 3.0}}}},
             {"reporter",
              {{"policy", "onApproval"},
               {"targets", {{{"element", "Column R"}, {"parameters", sent}}}}}}});
        auto testA = buildHybridTest(parseConfig(a, source));
        Recorder recA;
        testA->addObserver(&recA);
        QVERIFY2(testA->prepare(), testA->lastError().c_str());
        for (int k = 0; k < 5; ++k)
            QCOMPARE(int(testA->step()), int(HybridTest::StepResult::Advanced));
        for (const StepRecord& r : recA.records)
            for (int i = 0; i < r.u.size(); ++i)
                QCOMPARE(r.u[i], 0.0); // at rest: no state for the new parameters to meet
        const auto& pending = testA->updater()->reporter().pending();
        QVERIFY(!pending.empty());
        QCOMPARE(pending.front().basicDof, 1);
        QVERIFY(testA->approveUpdate(pending.front().id));
        HysteresisLaw* shearA = twin(*testA).basicLaw(1);
        nlohmann::json b = withMotion(frame(wrongModel()));
        nlohmann::json& bShear = b["structure"]["elements"][1]["basic"][1]["material"];
        double changed = 0.0;
        for (const std::string& name : sent) {
            bShear[name] = parameter(shearA, name);
            changed = std::max(changed, std::abs(parameter(shearA, name) - double(wrongModel()[name])));
            qInfo("approved %-5s %.6f (initial %.6f)", name.c_str(), parameter(shearA, name),
                  double(wrongModel()[name]));
        }
        QVERIFY(changed > 0.05); // the approved values are not the twin's initial ones
        QCOMPARE(twin(*testA).basicLaw(2)->initialTangent(), 5000.0);
        while (testA->step() == HybridTest::StepResult::Advanced) {
        }
        QCOMPARE(int(testA->state()), int(HybridTest::State::Finished));
        QCOMPARE(testA->updater()->reporter().appliedCount(), 1);

        auto runOf = [&](const nlohmann::json& doc) {
            auto t = buildHybridTest(parseConfig(doc, source));
            Recorder rec;
            t->addObserver(&rec);
            if (!t->prepare())
                qFatal("%s", t->lastError().c_str());
            while (t->step() == HybridTest::StepResult::Advanced) {
            }
            t->removeObserver(&rec);
            return rec.records;
        };
        const auto recB = runOf(b);
        const auto recC = runOf(withMotion(frame(wrongModel()))); // never updated
        QCOMPARE(recB.size(), recA.records.size());
        double peak = 0.0, diffB = 0.0, diffC = 0.0;
        for (std::size_t s = 0; s < recB.size(); ++s)
            for (int i = 0; i < recB[s].u.size(); ++i) {
                peak = std::max(peak, std::abs(recB[s].u[i]));
                diffB = std::max(diffB, std::abs(recA.records[s].u[i] - recB[s].u[i]));
                diffC = std::max(diffC, std::abs(recA.records[s].u[i] - recC[s].u[i]));
            }
        testA->removeObserver(&recA);
        qInfo("peak %.4f m; updated run - run started updated: %.3g m; - never updated: %.3g m",
              peak, diffB, diffC);
        QVERIFY(diffB <= 1e-9 * peak);
        QVERIFY(diffC > 1e-3 * peak); // the update mattered
    }

    void errorsNameTheFieldAndTheDof()
    {
        auto with = [](const nlohmann::json& u) {
            nlohmann::json doc = frame(wrongModel());
            doc["updating"] = u;
            return doc;
        };
        const QString range = errorOf(with(updating({{"basicDof", 3}})));
        QVERIFY2(range.contains("basicDof") && range.contains("out of range") &&
                     range.contains("0 .. 2"),
                 qPrintable(range));
        const QString name = errorOf(with(updating({{"basicDof", "moment"}})));
        QVERIFY2(name.contains("basicDof") && name.contains("axial, shear, rotation"),
                 qPrintable(name));
        nlohmann::json noModel = updating();
        noModel.erase("model");
        const QString model = errorOf(with(noModel));
        QVERIFY2(model.contains("model") && model.contains("shear"), qPrintable(model));
        // The twin's axial DOF holds a force: nothing to update there.
        const QString held = errorOf(with(updating(
            {{"reporter", {{"targets", {{{"element", "Column R"}, {"basicDof", "axial"}}}}}}})));
        QVERIFY2(held.contains("basic DOF 0 (axial)") && held.contains("no hysteretic law") &&
                     held.contains("held force"),
                 qPrintable(held));
        const QString targetRange = errorOf(with(
            updating({{"reporter", {{"targets", {{{"element", "Column R"}, {"basicDof", 5}}}}}}})));
        QVERIFY2(targetRange.contains("out of range"), qPrintable(targetRange));
        // The twin's rotation DOF is elastic: not the specimen model's law.
        const QString elastic = errorOf(with(
            updating({{"reporter", {{"targets", {{{"element", "Column R"}, {"basicDof", 2}}}}}}})));
        QVERIFY2(elastic.contains("'elastic' differs"), qPrintable(elastic));
        // A free twin DOF (no material, no held force).
        nlohmann::json free = with(updating());
        free["structure"]["elements"][1]["basic"][1] = nlohmann::json::object();
        free["structure"]["elements"][1]["primary"] = 2;
        const QString freeDof = errorOf(free);
        QVERIFY2(freeDof.contains("basic DOF 1 (shear)") && freeDof.contains("free DOF"),
                 qPrintable(freeDof));

        // A one-DOF specimen: basicDof 0 only, and no model of its own.
        std::ifstream in(HSMU_SOURCE_DIR "/resources/presets/sdof-bouc-wen.json");
        nlohmann::json sdof = nlohmann::json::parse(in);
        sdof["updating"] = {{"specimen", "Spring"}, {"basicDof", 1}};
        const QString one = errorOf(sdof);
        QVERIFY2(one.contains("basicDof") && one.contains("has 1 (0 .. 0)"), qPrintable(one));
        sdof["updating"] = {{"specimen", "Spring"}, {"basicDof", 0}};
        QCOMPARE(errorOf(sdof), QString());
        QCOMPARE(parseConfig(sdof, "sdof.json").updating.basicDof, -1); // today's path
        sdof["updating"] = {{"specimen", "Spring"}, {"model", kTrueLaw}};
        const QString ownModel = errorOf(sdof);
        QVERIFY2(ownModel.contains("model") && ownModel.contains("only for a link2d"),
                 qPrintable(ownModel));

        // The same checks where the configuration is bypassed (the API).
        TestConfig cfg = parseConfig(with(updating()), "frame.json");
        {
            auto t = buildHybridTest(cfg);
            Reporter r({{"Column R", {"alpha"}, {}, 0}}, ReporterPolicy::EveryStep);
            std::string error;
            QVERIFY(!r.bind(t->structure(), ParameterLayout({"alpha"}), &error));
            QVERIFY2(error.find("basic DOF 0 (axial) carries no hysteretic law") !=
                         std::string::npos,
                     error.c_str());
            Reporter far({{"Column R", {"alpha"}, {}, 3}}, ReporterPolicy::EveryStep);
            QVERIFY(!far.bind(t->structure(), ParameterLayout({"alpha"}), &error));
            QVERIFY2(error.find("basic DOF 3 is out of range: a link2d has 3") != std::string::npos,
                     error.c_str());
        }
        {
            auto t = buildHybridTest(cfg);
            t->updater()->setBasicDof(3);
            QVERIFY(!t->prepare());
            QVERIFY2(t->lastError().find("basic DOF 3 of 'Column L' is out of range") !=
                         std::string::npos,
                     t->lastError().c_str());
        }
    }
};

QTEST_APPLESS_MAIN(TestBasicDofUpdating)
#include "TestBasicDofUpdating.moc"
