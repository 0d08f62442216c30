#pragma once
// One benchmark loop for the identifiers whose anchors run on a worker (RobustUkfIdentifier,
// PinchingUkfIdentifier; core/updating/ScheduledJob.h): the stepping thread's cost per step
// over steps 1600..2299 of a 2400-sample history (the identifier warmed up on the first 1600
// and made afresh, untimed, each time the window is used up), with the worker's cost beside it.
// Counters: the worker's CPU per timed step, per job, per anchor (calibration) and per guard
// replay [us]; jobs, anchors and waits per 1000 timed steps.

#include <benchmark/benchmark.h>

#include <cstddef>
#include <vector>

namespace hsmu::bench {

/// make(): a fresh identifier (std::unique_ptr) with workerCpuSeconds(), anchorCpuSeconds(),
/// jobs(), waits(), anchors() and observe(u, f, update). u and f hold >= 2300 samples.
template <class Make>
void workerIdentifierSteps(benchmark::State& state, const std::vector<double>& u,
                           const std::vector<double>& f, Make make) {
    constexpr std::size_t kWarm = 1600, kEnd = 2300;
    const auto fresh = [&] {
        auto id = make();
        for (std::size_t k = 0; k < kWarm; ++k)
            id->observe(u[k], f[k], false);
        return id;
    };
    auto id = fresh();
    std::size_t k = kWarm;
    double workerCpu = 0.0, cpu0 = id->workerCpuSeconds(), anchorCpu = 0.0,
           anchorCpu0 = id->anchorCpuSeconds();
    int jobs = 0, jobs0 = id->jobs(), waits = 0, waits0 = id->waits(), anchors = 0,
        anchors0 = id->anchors();
    const auto account = [&] {
        workerCpu += id->workerCpuSeconds() - cpu0;
        anchorCpu += id->anchorCpuSeconds() - anchorCpu0;
        jobs += id->jobs() - jobs0;
        waits += id->waits() - waits0;
        anchors += id->anchors() - anchors0;
    };
    for (auto _ : state) {
        if (k == kEnd) {
            state.PauseTiming();
            account();
            id = fresh();
            cpu0 = id->workerCpuSeconds();
            anchorCpu0 = id->anchorCpuSeconds();
            jobs0 = id->jobs(), waits0 = id->waits(), anchors0 = id->anchors();
            k = kWarm;
            state.ResumeTiming();
        }
        benchmark::DoNotOptimize(id->observe(u[k], f[k], false));
        ++k;
    }
    account();
    const double steps = double(state.iterations());
    state.counters["workerUsPerStep"] = 1e6 * workerCpu / steps;
    state.counters["workerUsPerJob"] = jobs > 0 ? 1e6 * workerCpu / jobs : 0.0;
    state.counters["workerUsPerAnchor"] = anchors > 0 ? 1e6 * anchorCpu / anchors : 0.0;
    state.counters["workerUsPerGuard"] =
        jobs > anchors ? 1e6 * (workerCpu - anchorCpu) / (jobs - anchors) : 0.0;
    state.counters["jobsPer1000"] = 1000.0 * jobs / steps;
    state.counters["anchorsPer1000"] = 1000.0 * anchors / steps;
    state.counters["waitsPer1000"] = 1000.0 * waits / steps;
}

} // namespace hsmu::bench
