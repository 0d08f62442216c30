// Offline re-identification (core/offline/OfflineIdentification.h):
// - a recorded run of the paper's condition 3 (UKF updating, 3 s) re-identified from its
//   record with the recorded settings gives the online parameter history, standard
//   deviations, auxiliary force and fit error to 1e-9 relative (in fact bit for bit: same
//   code, same inputs);
// - a recorded Nelder-Mead run (the paper's bilinear example, 6 s) likewise, with the final
//   fit switched off (the online run has none);
// - synthetic Bouc-Wen data with known parameters, written as CSV in ms, mm and N and read
//   back through the importer, identifies them: the force of the identified model replayed
//   over the whole history matches the data (NRMSE bounds below), and the well-identified
//   parameters k0 and alpha come close to the truth (beta and gamma trade off:
//   docs/method.md, Identifiability);
// - settings overrides: unknown keys and a method the model cannot use are clear errors.

#include "RecordFixture.h"

#include "core/hysteresis/HysteresisLaw.h"
#include "core/hysteresis/LawFactory.h"
#include "core/identification/HistoryFit.h"
#include "core/offline/MeasuredDataCsv.h"
#include "core/offline/OfflineIdentification.h"
#include "core/record/RecordReader.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <numbers>
#include <sstream>

using namespace hsmu;
using namespace hsmu::testsupport;

namespace {

TestConfig preset(const std::string& name, double duration) {
    const std::string path = std::string(HSMU_SOURCE_DIR) + "/resources/presets/" + name + ".json";
    std::ifstream in(path);
    nlohmann::json j = nlohmann::json::parse(in);
    j["analysis"]["duration"] = duration;
    return parseConfig(j, path);
}

/// Runs cfg to its end while recording it; returns the record read back.
RecordData recordRun(const TestConfig& cfg, const std::string& path) {
    auto test = buildHybridTest(cfg);
    {
        RecordWriter writer(path, RunLayout::of(*test), recordStart(cfg));
        writer.trackAlarms(&test->alarms());
        test->addObserver(&writer);
        if (!test->prepare())
            throw std::runtime_error(test->lastError());
        while (test->step() == HybridTest::StepResult::Advanced) {
        }
        if (test->state() != HybridTest::State::Finished || !writer.finish())
            throw std::runtime_error("the recorded run did not finish");
        test->removeObserver(&writer);
    }
    return RecordReader(path).data();
}

double relativeDifference(double a, double b) {
    return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-300});
}

/// Offline result rows k = record rows k + 1; the largest relative difference.
double largestDifference(const OfflineIdentificationResult& r, const RecordData& d) {
    double worst = 0.0;
    for (Eigen::Index k = 0; k < r.parameters.rows(); ++k) {
        for (Eigen::Index j = 0; j < r.parameters.cols(); ++j) {
            worst = std::max(worst, relativeDifference(r.parameters(k, j), d.parameters(k + 1, j)));
            worst = std::max(worst, relativeDifference(r.stddev(k, j), d.stddev(k + 1, j)) *
                                        (d.stddev(k + 1, j) != 0.0 || r.stddev(k, j) != 0.0));
        }
        worst = std::max(worst, relativeDifference(r.auxiliaryForce[k], d.auxiliaryForce[k + 1]));
        worst = std::max(worst, relativeDifference(r.fitError[k], d.fitError[k + 1]));
    }
    return worst;
}

// Synthetic specimen: a lateral Bouc-Wen spring (m, kN) with known parameters, under a
// sine of 1 s period whose amplitude grows linearly to 4 uRef over 10 s (dt 0.01 s).
const std::map<std::string, double> kTruth{{"k0", 1.0},     {"alpha", 0.03},   {"n", 2.0},
                                           {"beta", 2.5},   {"gamma", 0.5},    {"A0", 1.0},
                                           {"deltaA", 0.0}, {"deltaNu", 0.03}, {"deltaEta", 0.03},
                                           {"uRef", 0.02},  {"fRef", 20.0}};

/// The CSV text in ms, mm and N; also returns the history in s, m, kN.
std::string syntheticCsv(SpecimenHistory& truth) {
    auto law = makeLaw("boucWen", kTruth);
    std::ostringstream csv;
    csv.precision(17);
    csv << "# synthetic Bouc-Wen specimen\n";
    csv << "time [ms]; deformation [mm]; force [N]\n";
    const double dt = 0.01;
    for (int k = 1; k <= 1000; ++k) {
        const double t = k * dt;
        const double u = 4.0 * 0.02 * (t / 10.0) * std::sin(2.0 * std::numbers::pi * t);
        if (law->setTrialDeformation(u) != LawStatus::Ok)
            throw std::runtime_error("the synthetic law failed");
        law->commit();
        const double f = law->committedForce();
        truth.time.push_back(t);
        truth.deformation.push_back(u);
        truth.force.push_back(f);
        csv << t * 1e3 << "; " << u * 1e3 << "; " << f * 1e3 << "\n";
    }
    return csv.str();
}

/// The specimen's deliberately wrong initial model (the presets' Element 1 model).
nlohmann::json wrongModel() {
    return {{"law", "boucWen"}, {"k0", 1.3},    {"alpha", 0.01},    {"n", 1.2},
            {"beta", 4.5},      {"gamma", 2.0}, {"deltaNu", 0.005}, {"deltaEta", 0.005},
            {"uRef", 0.02},     {"fRef", 20.0}};
}

/// RMS(F_model - F) / RMS(F) of `model` replayed over the history.
double nrmse(const SpecimenHistory& h, const MaterialSpec& model) {
    double f2 = 0.0;
    for (double f : h.force)
        f2 += f * f;
    return HistoryFit::rmsError(model.law, model.params, h.deformation, h.force, 0) /
           std::sqrt(f2 / h.size());
}

} // namespace

class TestOfflineIdentification : public QObject {
    Q_OBJECT
private slots:
    void ukfOfflineEqualsOnline();
    void nelderMeadOfflineEqualsOnline();
    void importedSyntheticDataIdentifiesKnownParameters_data();
    void importedSyntheticDataIdentifiesKnownParameters();
    void badSettingsAreClearErrors();
};

void TestOfflineIdentification::ukfOfflineEqualsOnline() {
    QTemporaryDir dir;
    const TestConfig cfg = condition3(3.0);
    const RecordData d = recordRun(cfg, dir.filePath("record.h5").toStdString());
    QCOMPARE(d.rows(), 301);
    const TestConfig recorded = parseConfig(nlohmann::json::parse(d.meta.configuration), "rec");
    const IdentificationSettings s = identificationSettingsFrom(recorded);
    QCOMPARE(s.specimen, std::string("Element 1"));
    QCOMPARE(s.updating.method, std::string("ukf"));
    const SpecimenHistory h = historyFromRecord(d, s.specimen, "rec");
    QCOMPARE(h.size(), 300);
    QCOMPARE(h.deformationUnits, std::string("rad"));
    QCOMPARE(h.forceUnits, std::string("kN m"));

    const OfflineIdentificationResult r = identifyOffline(h, s);
    QCOMPARE(r.method, std::string("UKF"));
    QCOMPARE(r.parameterNames, d.layout.updating->parameters);
    QCOMPARE(r.parameters.rows(), Eigen::Index(300));
    for (std::size_t j = 0; j < r.parameterNames.size(); ++j)
        QCOMPARE(r.initial.at(r.parameterNames[j]), d.parameters(0, Eigen::Index(j)));
    const double worst = largestDifference(r, d);
    QVERIFY2(worst <= 1e-9, QByteArray::number(worst));
    // The estimate moved during the run (so the equality is not that of two constants).
    QVERIFY((d.parameters.row(300) - d.parameters.row(0)).norm() > 1e-3);
    QVERIFY(r.finalNrmse > 0.0 && r.finalNrmse < 1.0);
}

void TestOfflineIdentification::nelderMeadOfflineEqualsOnline() {
    QTemporaryDir dir;
    const TestConfig cfg = preset("paper-bilinear-nelder-mead", 6.0);
    const RecordData d = recordRun(cfg, dir.filePath("record.h5").toStdString());
    const TestConfig recorded = parseConfig(nlohmann::json::parse(d.meta.configuration), "rec");
    IdentificationSettings s = identificationSettingsFrom(recorded);
    s.finalFit = false;
    const OfflineIdentificationResult r =
        identifyOffline(historyFromRecord(d, s.specimen, "rec"), s);
    QCOMPARE(r.method, std::string("Nelder-Mead"));
    const double worst = largestDifference(r, d);
    QVERIFY2(worst <= 1e-9, QByteArray::number(worst));
    QVERIFY2(r.refits > 0, "the run never refitted: the comparison would be trivial");
}

void TestOfflineIdentification::importedSyntheticDataIdentifiesKnownParameters_data() {
    QTest::addColumn<QString>("method");
    QTest::addColumn<double>("nrmseBound");       // force of the final model over the history
    QTest::addColumn<double>("k0AlphaTolerance"); // relative, k0 and alpha
    QTest::addColumn<double>("allTolerance");     // relative, every identified parameter
    // Measured on this data set (noise free, 1000 samples): UKF final NRMSE 2.6 %, k0 +2.3 %,
    // alpha -3.6 %, the others within 21 % (deltaNu; beta and gamma trade off:
    // docs/method.md, Identifiability);
    // Nelder-Mead (whole-history fit of the generating law) recovers them to < 1e-9. The
    // bounds leave about a factor two (UKF) and orders of magnitude (Nelder-Mead) of margin.
    QTest::newRow("ukf") << QStringLiteral("ukf") << 0.05 << 0.06 << 0.35;
    QTest::newRow("nelder-mead") << QStringLiteral("nelder-mead") << 1e-6 << 1e-4 << 1e-3;
}

void TestOfflineIdentification::importedSyntheticDataIdentifiesKnownParameters() {
    QFETCH(QString, method);
    QFETCH(double, nrmseBound);
    QFETCH(double, k0AlphaTolerance);
    QFETCH(double, allTolerance);
    SpecimenHistory truth;
    std::istringstream csv(syntheticCsv(truth));
    const SpecimenHistory h = readMeasuredDataCsv(csv, "synthetic.csv");
    QCOMPARE(h.size(), truth.size());
    QCOMPARE(h.deformationUnits, std::string("m"));
    QCOMPARE(h.forceUnits, std::string("kN"));
    for (int k = 0; k < h.size(); ++k) { // unit conversion to 1e-12 relative
        const auto i = std::size_t(k);
        QVERIFY(relativeDifference(h.time[i], truth.time[i]) < 1e-12);
        QVERIFY(std::abs(h.deformation[i] - truth.deformation[i]) <= 1e-12 * 0.08);
        QVERIFY(std::abs(h.force[i] - truth.force[i]) <= 1e-12 * 20.0);
    }
    IdentificationSettings s = defaultIdentificationSettings();
    s.dt = h.meanStep();
    QVERIFY(std::abs(s.dt - 0.01) < 1e-12);
    const nlohmann::json updating = {{"nelderMead", {{"maxEvaluations", 1500}}},
                                     {"ukf", {{"parameterNoise", 1e-3}}}};
    s = withOverride(s, {{"model", wrongModel()}, {"updating", updating}}, "override.json");
    QCOMPARE(s.updating.parameterNoise, 1e-3);
    s = withMethod(s, method.toStdString());
    const OfflineIdentificationResult r = identifyOffline(h, s);

    // The wrong initial model misses the data by far; the identified one does not.
    const double before = nrmse(h, s.model);
    QVERIFY2(before > 0.2, QByteArray::number(before));
    QVERIFY2(r.finalNrmse < nrmseBound, QByteArray::number(r.finalNrmse));
    for (const auto& [name, value] : r.finalEstimate) {
        const bool strict = name == "k0" || name == "alpha";
        const double error = relativeDifference(value, kTruth.at(name));
        QVERIFY2(
            error < (strict ? k0AlphaTolerance : allTolerance),
            qPrintable(QStringLiteral("%1 = %2").arg(QString::fromStdString(name)).arg(value)));
    }
    // The running fit (inspector window) ends well inside the 10 % update threshold.
    QVERIFY(r.fitError[r.fitError.size() - 1] < 0.01);
}

void TestOfflineIdentification::badSettingsAreClearErrors() {
    const IdentificationSettings s = defaultIdentificationSettings();
    const auto message = [&](const nlohmann::json& o) -> std::string {
        try {
            withOverride(s, o, "o.json");
        } catch (const ConfigError& e) {
            return e.what();
        }
        return "no error";
    };
    QCOMPARE(message({{"modell", {}}}),
             std::string("o.json: modell: unknown field (expected one of: model, updating)"));
    const std::string bilinearUkf =
        message({{"model", {{"law", "bilinear"}}}, {"updating", {{"method", "ukf"}}}});
    QVERIFY2(bilinearUkf.find("UKF identifies a boucWen model") != std::string::npos,
             bilinearUkf.c_str());
    // A specimen model with offsets (OffsetLaw.h): the online identifiers fit none and say so
    // (docs/method.md, "Offsets"), for the UKF and for Nelder-Mead.
    SpecimenHistory h;
    h.source = "offset.csv";
    for (int k = 0; k < 20; ++k) {
        h.time.push_back(0.01 * k);
        h.deformation.push_back(0.01 * std::sin(0.5 * k));
        h.force.push_back(std::sin(0.5 * k));
    }
    for (const char* method : {"ukf", "nelderMead"}) {
        std::string why = "no error";
        try {
            identifyOffline(h, withOverride(s,
                                            {{"model", {{"law", "boucWen"}, {"forceOffset", 0.1}}},
                                             {"updating", {{"method", method}}}},
                                            "o.json"));
        } catch (const ConfigError& e) {
            why = e.what();
        }
        QVERIFY2(why.find("the specimen model has offsets (deformationOffset, forceOffset); the "
                          "online identifiers fit none") != std::string::npos,
                 why.c_str());
    }
    try {
        withMethod(s, "simplex");
        QFAIL("no error");
    } catch (const ConfigError& e) {
        QCOMPARE(std::string(e.what()),
                 std::string("--method: expected ukf, nelder-mead, calibration or all, found 'simplex'"));
    }
}

QTEST_APPLESS_MAIN(TestOfflineIdentification)
#include "TestOfflineIdentification.moc"
