#pragma once
// Shared by the tests of the link2d element's configuration (TestLink2dConfig,
// TestWholeSpecimenConfig, TestCantileverColumnLabPreset; the updating and comparison tests
// take its laws): the preset two-actuator-column-frame.json, its lateral law, a run of a configuration
// to its end (every step recorded) and the error a configuration is refused with.
#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace link2dframe {

using namespace hsmu;

inline const std::string kPreset = HSMU_SOURCE_DIR "/resources/presets/two-actuator-column-frame.json";

struct Recorder final : StepObserver {
    std::vector<StepRecord> records;
    void onStep(const StepRecord& r) override { records.push_back(r); }
};

/// The preset's lateral actuator's Bouc-Wen law (the specimen's true shear law) and a wrong
/// initial model of it (alpha, beta, gamma, n off), as the updating tests use them.
inline const nlohmann::json kLateralLaw = {{"law", "boucWen"}, {"k0", 1.0},   {"alpha", 0.05},
                                           {"n", 2.0},         {"beta", 3.0}, {"gamma", 1.0},
                                           {"A0", 1.0},        {"uRef", 0.01}, {"fRef", 100.0}};
inline nlohmann::json wrongLateralLaw()
{
    nlohmann::json m = kLateralLaw;
    m["alpha"] = 0.15;
    m["beta"] = 1.5;
    m["gamma"] = 2.0;
    m["n"] = 1.5;
    return m;
}

inline nlohmann::json presetJson()
{
    std::ifstream in(kPreset);
    return nlohmann::json::parse(in);
}

inline std::vector<StepRecord> run(const nlohmann::json& doc, double duration,
                            std::unique_ptr<HybridTest>* keep = nullptr)
{
    TestConfig cfg = parseConfig(doc, "frame.json");
    cfg.analysis.duration = duration;
    auto test = buildHybridTest(cfg);
    Recorder rec;
    test->addObserver(&rec);
    if (!test->prepare())
        qFatal("%s", test->lastError().c_str());
    while (test->step() == HybridTest::StepResult::Advanced) {
    }
    if (test->state() != HybridTest::State::Finished)
        qFatal("not finished: %s", test->alarms().empty() ? "" : test->alarms().back().message.c_str());
    test->removeObserver(&rec);
    if (keep)
        *keep = std::move(test);
    return rec.records;
}

/// Two runs of the frame side by side: the peak |x3| [m] and largest |difference| of any DOF
/// displacement, the peak primary force of the left column [kN] and its largest |difference|.
struct RunDifference {
    double peak = 0, du = 0, peakF = 0, dF = 0;
};

inline RunDifference compareRuns(const std::vector<StepRecord>& a, const std::vector<StepRecord>& b)
{
    RunDifference r;
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
        r.peak = std::max(r.peak, std::abs(a[i].u[0]));
        r.du = std::max(r.du, (a[i].u - b[i].u).cwiseAbs().maxCoeff());
        r.peakF = std::max(r.peakF, std::abs(a[i].elements[0].force));
        r.dF = std::max(r.dF, std::abs(a[i].elements[0].force - b[i].elements[0].force));
    }
    qInfo("peak |x3| %.6g m, max |du| %.3g m; peak shear %.6g kN, max |dF| %.3g kN", r.peak, r.du,
          r.peakF, r.dF);
    return r;
}

inline QString errorOf(const nlohmann::json& doc)
{
    try {
        parseConfig(doc, "frame.json");
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

} // namespace link2dframe
