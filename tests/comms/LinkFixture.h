#pragma once
// Helpers shared by the link tests: configurations derived from the paper's preset, a
// bounded driver for a HybridTest that resumes after holds, and a step-by-step comparison.

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"

#include <QDir>
#include <QString>

#include <cmath>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace linkfixture {

struct Recorder final : hsmu::StepObserver {
    std::vector<hsmu::StepRecord> records;
    std::function<void(int)> onStepHook;
    void onStep(const hsmu::StepRecord& r) override {
        records.push_back(r);
        if (onStepHook)
            onStepHook(r.step);
    }
};

/// paper-condition-3 cut to `duration` seconds, with force noise (so the seed matters) and a
/// fracture event at 1.5 s, ideal actuator.
inline nlohmann::json condition3(double duration = 3.0) {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json");
    nlohmann::json j = nlohmann::json::parse(in);
    j["analysis"]["duration"] = duration;
    auto& specimen = j["structure"]["elements"][0]["specimen"];
    specimen["forceNoiseStd"] = 0.05;
    specimen["seed"] = 7;
    specimen["fracture"] = {{"atTime", 1.5}, {"strengthLoss", 0.2}};
    return j;
}

inline std::string writeConfig(const QString& dir, const QString& name, const nlohmann::json& j) {
    const std::string path = QDir(dir).filePath(name).toStdString();
    std::ofstream(path) << j.dump(2);
    return path;
}

struct Run {
    bool prepared = false;
    std::string error;
    hsmu::HybridTest::State state = hsmu::HybridTest::State::Created;
    std::vector<hsmu::StepRecord> records;
    std::vector<hsmu::Alarm> alarms;
    int holds = 0;
};

/// Build and run to the end. After a hold: onHold() (e.g. restart the controller), then
/// resume(); at most maxHolds holds. onStep(step) is called after each published step.
inline Run runTest(const hsmu::TestConfig& cfg, const hsmu::ControlFactory& controls,
                   std::function<void(int)> onStep = {}, std::function<void()> onHold = {},
                   int maxHolds = 0) {
    Run run;
    std::unique_ptr<hsmu::HybridTest> test;
    try {
        test = hsmu::buildHybridTest(cfg, controls);
    } catch (const std::exception& e) {
        run.error = e.what();
        return run;
    }
    Recorder rec;
    rec.onStepHook = std::move(onStep);
    test->addObserver(&rec);
    run.prepared = test->prepare();
    if (!run.prepared) {
        run.error = test->lastError();
        run.state = test->state();
        return run;
    }
    for (int guard = 0; guard < 1000000; ++guard) {
        const auto r = test->step();
        if (r == hsmu::HybridTest::StepResult::Finished)
            break;
        if (r == hsmu::HybridTest::StepResult::Held) {
            if (++run.holds > maxHolds)
                break;
            if (onHold)
                onHold();
            test->resume();
        } else if (r != hsmu::HybridTest::StepResult::Advanced) {
            break;
        }
    }
    run.state = test->state();
    run.alarms = test->alarms();
    run.records = rec.records;
    if (!test->alarms().empty())
        run.error = test->alarms().back().message;
    test->removeObserver(&rec);
    return run;
}

/// Largest difference over every recorded quantity of two runs (inf if they differ in
/// length or step numbering).
inline double maxDifference(const Run& a, const Run& b) {
    if (a.records.size() != b.records.size())
        return INFINITY;
    double worst = 0.0;
    auto upd = [&worst](double x, double y) {
        if (std::isnan(x) && std::isnan(y))
            return;
        worst = std::max(worst, std::abs(x - y));
    };
    for (std::size_t i = 0; i < a.records.size(); ++i) {
        const auto &p = a.records[i], &q = b.records[i];
        if (p.step != q.step || p.u.size() != q.u.size() || p.elements.size() != q.elements.size())
            return INFINITY;
        upd(p.time, q.time);
        for (Eigen::Index k = 0; k < p.u.size(); ++k) {
            upd(p.u[k], q.u[k]);
            upd(p.v[k], q.v[k]);
            upd(p.a[k], q.a[k]);
        }
        for (std::size_t e = 0; e < p.elements.size(); ++e) {
            upd(p.elements[e].deformation, q.elements[e].deformation);
            upd(p.elements[e].force, q.elements[e].force);
            upd(p.elements[e].commanded, q.elements[e].commanded);
        }
    }
    return worst;
}

/// True if the records are steps 0, 1, 2, ... each exactly once.
inline bool everyStepOnce(const Run& r) {
    for (std::size_t i = 0; i < r.records.size(); ++i)
        if (r.records[i].step != static_cast<int>(i))
            return false;
    return true;
}

} // namespace linkfixture
