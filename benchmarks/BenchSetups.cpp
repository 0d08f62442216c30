// Experimental-setup benchmarks (issue 24; docs/setups.md):
//   ThreeActuators2d -nlGeom trial transformation (basic d -> 3 strokes)   <= 1 us
//   the measured path (3 strokes -> basic d by Newton from the trial, forces by J^T f), the
//   measurement off the trial by a tracking error of 0.2 mm, 0.1 mm, 0.5 mrad   reported
// Run: build/bin/hsmu_bench --benchmark_filter=Setup

#include "core/experimental/setup/PlanarSetups.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

namespace {

using namespace hsmu;

std::unique_ptr<PlanarActuatorSetup> threeActuatorsNlGeom() {
    ThreeActuators2dParams p;
    p.La1 = 1.6;
    p.La2 = 1.1;
    p.La3 = 1.3;
    p.L1 = 0.7;
    p.L2 = 0.5;
    p.geometry = SetupGeometry::Exact;
    std::string error;
    return makeThreeActuators2d(p, error);
}

// A cyclic history: u 0.08 m, v 0.03 m, theta 0.3 rad, 400 steps per cycle.
Eigen::VectorXd basicAt(long i) {
    const double t = 2.0 * std::numbers::pi * double(i % 400) / 400.0;
    Eigen::VectorXd d(3);
    d << 0.08 * std::sin(1.3 * t), 0.03 * std::sin(0.7 * t + 0.4), 0.3 * std::sin(t + 0.2);
    return d;
}

void bmSetupStrokesThreeActuatorsNlGeom(benchmark::State& state) {
    const auto setup = threeActuatorsNlGeom();
    std::vector<Eigen::VectorXd> history;
    for (long i = 0; i < 400; ++i)
        history.push_back(basicAt(i));
    Eigen::VectorXd s(3);
    long i = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(setup->strokes(history[i++ % 400], s).ok);
        benchmark::DoNotOptimize(s.data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(bmSetupStrokesThreeActuatorsNlGeom);

void bmSetupMeasuredThreeActuatorsNlGeom(benchmark::State& state) {
    const auto setup = threeActuatorsNlGeom();
    std::vector<Eigen::VectorXd> history, strokes;
    for (long i = 0; i < 400; ++i) {
        history.push_back(basicAt(i));
        Eigen::VectorXd s, measured = history.back();
        measured += Eigen::Vector3d(2e-4, -1e-4, 5e-4);
        setup->strokes(measured, s);
        strokes.push_back(s);
    }
    const Eigen::Vector3d f(1.0e5, -2.0e5, 1.5e5);
    Eigen::VectorXd d(3), q(3);
    long i = 0;
    for (auto _ : state) {
        const long k = i++ % 400;
        benchmark::DoNotOptimize(setup->basicDisplacements(strokes[k], history[k], d).ok);
        benchmark::DoNotOptimize(setup->basicForces(d, f, q).ok);
        benchmark::DoNotOptimize(q.data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(bmSetupMeasuredThreeActuatorsNlGeom);

} // namespace
