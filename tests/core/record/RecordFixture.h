#pragma once
// Shared by the core/record tests: the preset paper-condition-3 (UKF updating of Element 1,
// reported to Element 2) cut to `duration` seconds, an observer keeping every StepRecord, and
// a helper running a test to its end while a RecordWriter records it.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/output/RunLayout.h"
#include "core/record/RecordWriter.h"
#include "core/experiment/HybridTest.h"

#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace hsmu::testsupport {

inline TestConfig condition3(double duration) {
    const std::string path =
        std::string(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json";
    std::ifstream in(path);
    nlohmann::json j = nlohmann::json::parse(in);
    j["analysis"]["duration"] = duration;
    return parseConfig(j, path);
}

inline RecordStart recordStart(const TestConfig& cfg, const std::string& notes = {}) {
    RecordStart s;
    s.configuration = cfg.raw.dump();
    s.configName = cfg.name;
    s.operatorNotes = notes;
    s.dt = cfg.analysis.dt;
    return s;
}

class Collector final : public StepObserver {
public:
    void onStep(const StepRecord& r) override { records.push_back(r); }
    std::vector<StepRecord> records;
};

} // namespace hsmu::testsupport
