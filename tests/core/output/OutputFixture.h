#pragma once
// Shared by the core/output tests: a small frame built from an inline configuration (a Bouc-Wen
// specimen as a rotational base spring, a bilinear numerical base spring, an elastic truss),
// the paper's condition 3 with online model updating (the preset file), and an observer
// keeping every StepRecord.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"

#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace hsmu::testsupport {

inline nlohmann::json smallFrameJson(double duration = 2.0, double specimenLimit = 0.15) {
    return nlohmann::json::parse(R"({
      "name": "small frame",
      "structure": {
        "dofs": [{"name": "D1", "mass": 4.0}, {"name": "D2", "mass": 2.0}],
        "damping": {"ratio": 0.02, "modes": [1, 2]},
        "elements": [
          {"name": "E1", "type": "rotationalBaseSpring", "dof": "D1", "height": 3.0,
           "material": {"law": "boucWen", "k0": 1.0, "uRef": 0.02, "fRef": 20.0},
           "experimental": true,
           "specimen": {"material": {"law": "boucWen", "k0": 1.0, "uRef": 0.02, "fRef": 20.0}},
           "limits": {"deformation": 0.15}},
          {"name": "E2", "type": "rotationalBaseSpring", "dof": "D2", "height": 3.0,
           "material": {"law": "bilinear", "k0": 1000.0, "fy": 5.0, "b": 0.05}},
          {"name": "E3", "type": "truss", "dofs": ["D1", "D2"],
           "material": {"law": "elastic", "k": 40.0}}
        ]
      },
      "groundMotion": {"builtin": "synthetic", "scale": 3.0},
      "analysis": {"dt": 0.01}
    })")
        .patch(nlohmann::json::parse(
            R"([{"op": "add", "path": "/analysis/duration", "value": )" + std::to_string(duration) +
            R"(}, {"op": "replace", "path": "/structure/elements/0/limits/deformation", "value": )" +
            std::to_string(specimenLimit) + "}]"));
}

inline std::unique_ptr<HybridTest> smallFrame(double duration = 2.0, double specimenLimit = 0.15) {
    return buildHybridTest(parseConfig(smallFrameJson(duration, specimenLimit), "inline.json"));
}

/// The preset paper-condition-3 (UKF updating of Element 1, reported to Element 2), cut to
/// `duration` seconds.
inline TestConfig condition3(double duration) {
    const std::string path =
        std::string(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json";
    std::ifstream in(path);
    nlohmann::json j = nlohmann::json::parse(in);
    j["analysis"]["duration"] = duration;
    return parseConfig(j, path);
}

class Collector final : public StepObserver {
public:
    void onStep(const StepRecord& r) override { records.push_back(r); }
    std::vector<StepRecord> records;
};

} // namespace hsmu::testsupport
