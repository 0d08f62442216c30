// Core compute benchmarks (issue targets on the 2-core dev machine):
//   Bouc-Wen trial + commit per step      <= 0.3 us
//   pinching Bouc-Wen trial + commit       <= 0.4 us (issue 12)
//   one HybridTest step, condition-3 frame <= 2 us
//   the whole 31 s El Centro run, frame     <= 20 ms (compute only: no output observers)
//   one step of the frame with online updating <= 8 us (issue 3)
//   the two-actuator column frame's whole step on the in-process virtual lab, within 1.3x of
//   the same frame with one actuator (issue 24; docs/benchmarks.md, "Multi-actuator
//   specimens"): bmTwoActuatorFrameStep / bmOneActuatorFrameStep
// Run: build/bin/hsmu_bench [--benchmark_repetitions=5]

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/BoucWenPinching.h"
#include "core/experiment/HybridTest.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

namespace {

using namespace hsmu;

const std::string kPreset = std::string(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json";
const std::string kElCentro =
    std::string(HSMU_SHARED_DATA_DIR) + "/elcentro/elCentro_Peknold_NS_0.02s.AT2";

void bmBoucWenStep(benchmark::State& state)
{
    BoucWenParameters p;
    p.k0 = 1.0; p.alpha = 0.03; p.n = 2.0; p.beta = 2.5; p.gamma = 0.5;
    p.deltaNu = 0.03; p.deltaEta = 0.03; p.uRef = 0.02; p.fRef = 20.0;
    BoucWen law(p);
    // A cyclic history of amplitude 0.04 rad in 400 steps per cycle (increments ~4e-4 rad,
    // the size of a 0.01 s step of the frame).
    long i = 0;
    for (auto _ : state) {
        const double u = 0.04 * std::sin(2.0 * M_PI * double(i++) / 400.0);
        benchmark::DoNotOptimize(law.setTrialDeformation(u));
        law.commit();
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(bmBoucWenStep);

void bmBoucWenPinchingStep(benchmark::State& state)
{
    // bmBoucWenStep's law and history with pinching (Foliente's wood-joint order of values);
    // pinching is active from the first dissipated energy on (every step but the first).
    BoucWenPinchingParameters p;
    BoucWenParameters& b = p.boucWen;
    b.k0 = 1.0; b.alpha = 0.03; b.n = 2.0; b.beta = 2.5; b.gamma = 0.5;
    b.deltaNu = 0.03; b.deltaEta = 0.03; b.uRef = 0.02; b.fRef = 20.0;
    p.pinching = {0.8, 1.0, 0.1, 0.2, 0.01, 0.5}; // zetaS, p, q, psi, deltaPsi, lambda
    BoucWenPinching law(p);
    long i = 0;
    for (auto _ : state) {
        const double u = 0.04 * std::sin(2.0 * M_PI * double(i++) / 400.0);
        benchmark::DoNotOptimize(law.setTrialDeformation(u));
        law.commit();
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(bmBoucWenPinchingStep);

/// The condition-3 frame; `updating` false: the issue-2 frame alone (no identification).
TestConfig frameConfig(bool elCentro, bool updating = false)
{
    TestConfig cfg = loadConfigFile(kPreset);
    if (elCentro)
        cfg.groundMotion.file = kElCentro;
    cfg.updating.enabled = updating;
    return cfg;
}

void frameSteps(benchmark::State& state, const TestConfig& cfg)
{
    auto test = buildHybridTest(cfg);
    test->prepare();
    for (auto _ : state) {
        if (test->step() != HybridTest::StepResult::Advanced) {
            state.PauseTiming();
            test = buildHybridTest(cfg);
            test->prepare();
            state.ResumeTiming();
        }
    }
    state.SetItemsProcessed(state.iterations());
}

void bmFrameStep(benchmark::State& state) { frameSteps(state, frameConfig(false)); }
BENCHMARK(bmFrameStep);

// One step of the frame with online updating: UKF, auxiliary model, inspector, reporter
// (target <= 8 us).
void bmUpdatedFrameStep(benchmark::State& state) { frameSteps(state, frameConfig(false, true)); }
BENCHMARK(bmUpdatedFrameStep);

// The preset two-actuator-column-frame (a link2d column behind NoTransformation, a vertical
// actuator holding -500 kN in force control, a lateral one in displacement control, each a
// uniaxial material of the virtual lab); actuators 1: the same frame with the lateral
// actuator alone (OneActuator on the shear DOF), today's one-actuator specimen step.
TestConfig actuatorFrame(int actuators)
{
    TestConfig cfg = loadConfigFile(std::string(HSMU_SOURCE_DIR) +
                                    "/resources/presets/two-actuator-column-frame.json");
    if (actuators == 1) {
        Link2dSpec& s = *cfg.elements[0].link2d;
        s.setupScript = "expSetup OneActuator 1 2 -sizeTrialOut 3 3";
        s.actuators.erase(s.actuators.begin()); // the vertical one
    }
    return cfg;
}

void bmTwoActuatorFrameStep(benchmark::State& state) { frameSteps(state, actuatorFrame(2)); }
BENCHMARK(bmTwoActuatorFrameStep);

void bmOneActuatorFrameStep(benchmark::State& state) { frameSteps(state, actuatorFrame(1)); }
BENCHMARK(bmOneActuatorFrameStep);

// The preset cantilever-column-lab: the same frame whose left column the virtual lab simulates
// as a whole (cantileverColumn: Bouc-Wen base hinge solved by Newton inside the lab's Newton on
// the strokes, forces and equilibrium, eq. W1-W4 of docs/setups.md; a lagging lateral
// actuator).
void bmCantileverColumnLabStep(benchmark::State& state)
{
    frameSteps(state, loadConfigFile(std::string(HSMU_SOURCE_DIR) +
                                     "/resources/presets/cantilever-column-lab.json"));
}
BENCHMARK(bmCantileverColumnLabStep);

void bmWholeElCentroRun(benchmark::State& state)
{
    const bool have = std::filesystem::exists(kElCentro);
    if (!have)
        state.SetLabel("El Centro absent: built-in synthetic 30 s record");
    const TestConfig cfg = frameConfig(have);
    for (auto _ : state) {
        auto test = buildHybridTest(cfg);
        test->prepare();
        while (test->step() == HybridTest::StepResult::Advanced) {
        }
        benchmark::DoNotOptimize(test->currentStep());
    }
}
BENCHMARK(bmWholeElCentroRun)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
