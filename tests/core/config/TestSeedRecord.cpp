// updating.ukf.seedRecord (docs/configuration.md): a run of the sdof-bouc-wen preset is
// recorded, then the same test configured with that record as the robust UKF's seed starts
// with a seeded filter whose anchor fits the recorded specimen; a missing file, a record
// without the specimen and the paper formulation are refused with the file and the field.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/session/TestSession.h"
#include "core/updating/ModelUpdater.h"
#include "core/updating/RobustUkfIdentifier.h"

#include <QtTest>

#include <fstream>
#include <nlohmann/json.hpp>

using namespace hsmu;

namespace {

nlohmann::json preset() {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) + "/resources/presets/sdof-bouc-wen.json");
    return nlohmann::json::parse(in);
}

/// The preset with updating of its spring by the robust UKF, `ukf` as its ukf block.
nlohmann::json withUpdating(nlohmann::json ukf, const std::string& specimen = "Spring") {
    nlohmann::json d = preset();
    d["updating"] = {{"specimen", specimen}, {"method", "ukf"}, {"ukf", std::move(ukf)}};
    return d;
}

std::string configError(const nlohmann::json& d, const std::string& source) {
    try {
        buildHybridTest(parseConfig(d, source));
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

} // namespace

class TestSeedRecord : public QObject {
    Q_OBJECT
private slots:
    void seedsTheRobustUkfFromAPreviousRun() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string source = dir.filePath("test.json").toStdString();
        const std::string record = dir.filePath("previous/record.h5").toStdString();
        {
            const TestConfig cfg = parseConfig(preset(), source);
            SessionOptions o;
            o.recordPath = record;
            o.recordStart = RecordStart{cfg.raw.dump(), cfg.name, {}, cfg.analysis.dt};
            TestSession s(buildHybridTest(cfg), o);
            QVERIFY(s.prepare());
            QVERIFY(s.openRecord());
            QCOMPARE(s.runToEnd(), TestSession::Status::Finished);
        }
        // A relative path is taken from the configuration's folder.
        const TestConfig cfg =
            parseConfig(withUpdating({{"seedRecord", "previous/record.h5"}}), source);
        QCOMPARE(cfg.updating.seedRecord, record);
        auto test = buildHybridTest(cfg);
        QVERIFY(test->updater() != nullptr);
        const auto* id =
            dynamic_cast<const RobustUkfIdentifier*>(&test->updater()->identifier());
        QVERIFY(id != nullptr);
        QVERIFY(id->seeded());
        qInfo("seed anchor NRMSE over the previous run: %.4f", id->anchorNrmse());
        QVERIFY(id->anchorNrmse() < 0.05); // the recorded specimen is the preset's own law

        // Refused, naming the file and the field.
        const std::string missing = configError(withUpdating({{"seedRecord", "none.h5"}}), source);
        QVERIFY2(missing.find("ukf.seedRecord") != std::string::npos &&
                     missing.find("none.h5") != std::string::npos,
                 missing.c_str());
        const std::string paper = configError(
            withUpdating({{"formulation", "paper"}, {"seedRecord", "previous/record.h5"}}),
            source);
        QVERIFY2(paper.find("seedRecord") != std::string::npos, paper.c_str());
    }
};

QTEST_APPLESS_MAIN(TestSeedRecord)
#include "TestSeedRecord.moc"
