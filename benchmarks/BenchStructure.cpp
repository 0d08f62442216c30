// Numerical substructures at scale (issue 17), on the generated shear buildings
// (core/config/ShearBuilding.h; docs/presets.md): N = 10, 100, 1,000, 10,000 DOFs, Bouc-Wen
// or elastic storeys, Rayleigh damping at modes 1 and 2 (sparse LDL^T left-hand side) or
// mass-proportional damping (diagonal: no solve). Targets (docs/benchmarks.md):
//   one HybridTest step (explicit Newmark, outputs not attached, after 1 s of the record):
//   1,000 DOFs <= 0.3 ms,
//   10,000 DOFs <= 3 ms; set-up (parse, build, finalize with modal analysis, prepare) of
//   10,000 DOFs <= 1 s.
// Run: build/bin/hsmu_bench --benchmark_filter='Shear'

#include "core/config/ConfigLoader.h"
#include "core/config/ShearBuilding.h"
#include "core/config/TestFactory.h"
#include "core/output/RunLayout.h"
#include "core/record/RecordWriter.h"
#include "core/structure/Structure.h"
#include "core/experiment/HybridTest.h"

#include <benchmark/benchmark.h>

#include <filesystem>

namespace {

using namespace hsmu;

constexpr int kWarmUpSteps = 1000;

TestConfig shearConfig(int n, bool boucWen, bool massDamped, const std::string& integrator)
{
    ShearBuildingSpec spec;
    spec.storeys = n;
    spec.boucWen = boucWen;
    spec.massDamped = massDamped;
    TestConfig cfg = parseConfig(shearBuildingConfig(spec), "shear-building");
    cfg.analysis.integrator = integrator;
    cfg.analysis.duration = 0.0; // the whole record: the benchmark restarts at its end
    return cfg;
}

void steps(benchmark::State& state, bool boucWen, bool massDamped, const std::string& integrator)
{
    const TestConfig cfg = shearConfig(int(state.range(0)), boucWen, massDamped, integrator);
    auto test = buildHybridTest(cfg);
    if (!test->prepare()) {
        state.SkipWithError(test->lastError().c_str());
        return;
    }
    // 1 s of the record first: the storeys then respond in earnest (in the first steps the
    // Bouc-Wen laws see tiny deformations, where |z|^n is cheap, and the step looks faster).
    for (int k = 0; k < kWarmUpSteps; ++k)
        test->step();
    double peak = 0.0;
    for (const auto& e : test->structure().elements())
        peak = std::max(peak, std::abs(e->deformation()));
    state.counters["peak_drift_m"] = peak;
    for (auto _ : state) {
        if (test->step() != HybridTest::StepResult::Advanced) {
            state.PauseTiming();
            test = buildHybridTest(cfg);
            test->prepare();
            for (int k = 0; k < kWarmUpSteps; ++k)
                test->step();
            state.ResumeTiming();
        }
    }
    state.SetItemsProcessed(state.iterations());
}

void bmShearStepBoucWen(benchmark::State& s) { steps(s, true, false, "explicitNewmark"); }
void bmShearStepElastic(benchmark::State& s) { steps(s, false, false, "explicitNewmark"); }
void bmShearStepBoucWenMassDamped(benchmark::State& s) { steps(s, true, true, "explicitNewmark"); }
void bmShearStepBoucWenAlphaOS(benchmark::State& s) { steps(s, true, false, "alphaOS"); }
BENCHMARK(bmShearStepBoucWen)->RangeMultiplier(10)->Range(10, 10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(bmShearStepElastic)->RangeMultiplier(10)->Range(10, 10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(bmShearStepBoucWenMassDamped)->RangeMultiplier(10)->Range(10, 10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(bmShearStepBoucWenAlphaOS)->RangeMultiplier(10)->Range(10, 10000)->Unit(benchmark::kMicrosecond);

/// Parse the generated document, build, finalize (modal analysis), prepare (factor).
void setUp(benchmark::State& state, bool boucWen)
{
    ShearBuildingSpec spec;
    spec.storeys = int(state.range(0));
    spec.boucWen = boucWen;
    const nlohmann::json doc = shearBuildingConfig(spec);
    for (auto _ : state) {
        TestConfig cfg = parseConfig(doc, "shear-building");
        auto test = buildHybridTest(cfg);
        if (!test->prepare())
            state.SkipWithError(test->lastError().c_str());
        benchmark::DoNotOptimize(test->totalSteps());
    }
}
void bmShearSetUpBoucWen(benchmark::State& s) { setUp(s, true); }
void bmShearSetUpElastic(benchmark::State& s) { setUp(s, false); }
BENCHMARK(bmShearSetUpBoucWen)->RangeMultiplier(10)->Range(10, 10000)->Unit(benchmark::kMillisecond);
BENCHMARK(bmShearSetUpElastic)->RangeMultiplier(10)->Range(10, 10000)->Unit(benchmark::kMillisecond);

/// RecordWriter::onStep per step on an N-DOF shear building (rows of 3 N DOF values and
/// 3 N element values; flushes, extends and H5Fflush amortized), the file in the temporary
/// folder (the page cache: the disk's own speed is not measured).
void bmShearRecordStep(benchmark::State& state)
{
    const TestConfig cfg = shearConfig(int(state.range(0)), true, false, "explicitNewmark");
    auto test = buildHybridTest(cfg);
    struct Last final : StepObserver {
        StepRecord r;
        void onStep(const StepRecord& rec) override { r = rec; }
    } last;
    test->addObserver(&last);
    test->prepare();
    for (int k = 0; k < kWarmUpSteps; ++k)
        test->step();
    const std::string path =
        (std::filesystem::temp_directory_path() / "hsmu_bench_shear_record.h5").string();
    {
        RecordWriter writer(path, RunLayout::of(*test), {cfg.raw.dump(), cfg.name, {}, 0.001});
        for (auto _ : state)
            writer.onStep(last.r);
        writer.finish();
        if (!writer.ok())
            state.SkipWithError(writer.error().c_str());
    }
    state.counters["bytes_per_step"] =
        double(std::filesystem::file_size(path)) / double(state.iterations());
    state.SetItemsProcessed(state.iterations());
    std::filesystem::remove(path);
}
BENCHMARK(bmShearRecordStep)->RangeMultiplier(10)->Range(10, 10000)->Unit(benchmark::kMicrosecond);

} // namespace
