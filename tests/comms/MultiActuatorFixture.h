#pragma once
// Shared by the two-actuator column frame's link tests (TestMultiActuatorLink: the native
// protocol; TestMultiActuatorOpenFresco: SimApp and GenericTCP): the preset, its all-numerical
// twin and the comparison of two runs.
#include "LinkFixture.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <string>

namespace multiactuator {

using linkfixture::Run;

inline nlohmann::json preset(double duration) {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) +
                     "/resources/presets/two-actuator-column-frame.json");
    nlohmann::json j = nlohmann::json::parse(in);
    j["analysis"]["duration"] = duration;
    return j;
}

// The left column numerical: held axial load, the lateral actuator's law on the shear DOF,
// a free rotation (no actuator on it), as test_config_link2d's twin.
inline nlohmann::json numericalTwin(nlohmann::json doc) {
    nlohmann::json& col = doc["structure"]["elements"][0];
    const nlohmann::json shear = col["actuators"][1]["material"];
    const double axial = col["actuators"][0]["force"];
    for (const char* k : {"experimental", "setup", "actuators"})
        col.erase(k);
    col["basic"] = nlohmann::json::array(
        {{{"heldForce", axial}}, {{"material", shear}}, nlohmann::json::object()});
    return doc;
}

/// Largest |difference| of the DOF displacements and of the left column's recorded force,
/// relative to their peaks in a (inf when the runs differ in length).
inline double relativeDifference(const Run& a, const Run& b) {
    if (a.records.size() != b.records.size() || a.records.empty())
        return INFINITY;
    double peakU = 0, peakF = 0, du = 0, dF = 0;
    for (std::size_t i = 0; i < a.records.size(); ++i) {
        peakU = std::max(peakU, a.records[i].u.cwiseAbs().maxCoeff());
        du = std::max(du, (a.records[i].u - b.records[i].u).cwiseAbs().maxCoeff());
        peakF = std::max(peakF, std::abs(a.records[i].elements[0].force));
        dF =
            std::max(dF, std::abs(a.records[i].elements[0].force - b.records[i].elements[0].force));
    }
    return std::max(du / peakU, dF / peakF);
}

} // namespace multiactuator
