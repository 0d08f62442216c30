// RTHS benchmarks (issue 23 targets on the 2-core dev machine, docs/benchmarks.md "RTHS"):
//   plant + PID + compensator, one loop tick                    <= 1 us
//   the whole RTHS tick of the benchmark (3-DOF substructure, plant, compensator, sensors,
//   record row)                                                  <= 30 us (4096 Hz: 85 % free)
// Run: build/bin/hsmu_bench --benchmark_filter=Rths

#include "core/rths/RthsBenchmark.h"

#include <benchmark/benchmark.h>

#include <cmath>

namespace {

using namespace hsmu;
using namespace hsmu::rths;

void bmRthsServoCompensatorTick(benchmark::State& state)
{
    const RthsSettings s = defaultCompensation(); // ATS + lead: the costliest compensator
    ServoHydraulicPlant plant(s.plant);
    Pid pid(s.pid, 1.0 / s.rate);
    Compensator comp(s.compensation, 1.0 / s.rate);
    comp.reset(0.0);
    const double h = 1.0 / s.rate;
    long k = 0;
    for (auto _ : state) {
        const double t = double(k++) * h, w = 2 * M_PI * 2.0;
        const TargetState target{0.002 * std::sin(w * t), 0.002 * w * std::cos(w * t),
                                 -0.002 * w * w * std::sin(w * t)};
        const double x = plant.displacement();
        const double cmd = comp.command(target);
        comp.observe(x);
        plant.advance(pid.step(cmd - x), h);
        benchmark::DoNotOptimize(plant.state());
    }
}
BENCHMARK(bmRthsServoCompensatorTick);

void bmRthsWholeTick(benchmark::State& state)
{
    GroundMotion ag;
    ag.dt = 0.02;
    for (int i = 0; i < 3000; ++i)
        ag.acceleration.push_back(1.0 * std::sin(2 * M_PI * 1.5 * i * 0.02) * std::sin(0.05 * i));
    const RthsSettings s = defaultCompensation();
    RthsLoop loop(benchmarkPartition(1, s.plant), ag, s);
    std::vector<double> rows;
    rows.reserve(8 * 250000);
    for (auto _ : state) {
        if (!loop.tick() || rows.size() + 8 > rows.capacity()) {
            state.SkipWithError("the loop held or the record filled");
            break;
        }
        const RthsTick& t = loop.last();
        rows.insert(rows.end(), {t.time, t.desired, t.command, t.measured, t.force, t.floors(0),
                                 t.floors(1), t.floors(2)});
    }
    benchmark::DoNotOptimize(rows.data());
}
BENCHMARK(bmRthsWholeTick)->Iterations(200000);

} // namespace
