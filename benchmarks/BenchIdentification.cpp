// Identification benchmarks (issue 3 targets on the 2-core dev machine):
//   UKF update per step, Bouc-Wen, L = 9                  <= 4 us
//   one Nelder-Mead HistoryFit trigger (1000 points, 200 evaluations): reported, and its ratio
//   to the UKF step (docs/benchmarks.md)
// The UKF step is split into its parts: the 19 sigma points' Bouc-Wen integrations (one call of
// BoucWen::integrateStates, exact and fast pow) and the filter's own arithmetic (the same L = 9
// filter with a trivial process).
// Issue 12 targets: offline calibration of a 30,000-sample record <= 2 s; the robust UKF's
// step on the stepping thread <= 5 us (its calibrations run on a worker thread).
// Run: build/bin/hsmu_bench --benchmark_filter=Ident

#include "core/hysteresis/BoucWen.h"
#include "tests/support/BoucWenFixture.h"
#include "core/identification/BoucWenUkf.h"
#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryFit.h"
#include "core/updating/RobustUkfIdentifier.h"
#include "core/identification/UnscentedKalmanFilter.h"

#include "WorkerIdentifierSteps.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

namespace {

using namespace hsmu;

using test::truth;
using test::wrongStart;

struct History {
    std::vector<double> u, f;
};

// Cyclic deformation growing to 4 uRef over four cycles of `perCycle` points, then held.
History history(int points, int perCycle) {
    const BoucWenParameters p = truth();
    BoucWen law(p);
    History h;
    for (int k = 1; k <= points; ++k) {
        const double c = double(k) / perCycle;
        const double u = 4.0 * p.uRef * std::min(1.0, c / 4.0) * std::sin(2.0 * M_PI * c);
        law.setTrialDeformation(u);
        law.commit();
        h.u.push_back(u);
        h.f.push_back(law.committedForce());
    }
    return h;
}

void bmIdentUkfStep(benchmark::State& state) {
    const History h = history(2400, 400);
    BoucWenUkf ukf(wrongStart());
    std::size_t k = 0;
    for (auto _ : state) {
        if (k == h.u.size()) {
            state.PauseTiming();
            ukf.reset(wrongStart());
            k = 0;
            state.ResumeTiming();
        }
        benchmark::DoNotOptimize(ukf.step(h.u[k], h.f[k]));
        ++k;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(bmIdentUkfStep);

// The filter alone: L = 9, the same projection-free arithmetic with a trivial process.
void bmIdentUkfArithmetic(benchmark::State& state) {
    UnscentedKalmanFilter ukf;
    Eigen::MatrixXd P = 0.01 * Eigen::MatrixXd::Identity(9, 9);
    ukf.init(Eigen::VectorXd::Ones(9), P);
    ukf.setProcessNoise(1e-6 * Eigen::MatrixXd::Identity(9, 9));
    const Eigen::VectorXd z = Eigen::VectorXd::Constant(1, 9.0);
    for (auto _ : state) {
        ukf.predict([](const Eigen::Ref<const Eigen::VectorXd>& s,
                       Eigen::Ref<Eigen::VectorXd> out) { out = s; });
        ukf.update([](const Eigen::Ref<const Eigen::VectorXd>& s,
                      Eigen::Ref<Eigen::VectorXd> out) { out(0) = s.sum(); },
                   z);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(bmIdentUkfArithmetic);

// One sigma point's process: BoucWen::integrate over one increment of the same history.
void bmIdentBoucWenIntegrate(benchmark::State& state) {
    const History h = history(2400, 400);
    const BoucWenParameters p = truth();
    BoucWenState s;
    double x = 0.0;
    std::size_t k = 0;
    for (auto _ : state) {
        if (k == h.u.size()) {
            s = {};
            x = 0.0;
            k = 0;
        }
        const double next = h.u[k++] / p.uRef;
        const BoucWenIncrement inc = BoucWen::integrate(p, s, next - x);
        benchmark::DoNotOptimize(inc);
        s = inc.state;
        x = next;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(bmIdentBoucWenIntegrate);

// The process function of one UKF step alone: BoucWen::integrateStates over 19 sigma-point-like
// problems (the centre and +-1e-4 quarter-widths along each of the 9 state components), over
// the increments of the same history.
void bmIdentSigmaIntegrations(benchmark::State& state, BoucWen::BatchMath math) {
    const History h = history(2400, 400);
    const BoucWenParameters centre = wrongStart();
    std::vector<BoucWenParameters> p(19, centre);
    double BoucWenParameters::*fields[] = {&BoucWenParameters::k0,      &BoucWenParameters::alpha,
                                           &BoucWenParameters::beta,    &BoucWenParameters::gamma,
                                           &BoucWenParameters::n,       &BoucWenParameters::deltaNu,
                                           &BoucWenParameters::deltaEta};
    const double widths[] = {0.7, 0.049, 2.5, 2.5, 2.0, 0.099, 0.099};
    for (int k = 0; k < 7; ++k) {
        const double d = 1.7e-4 * 0.25 * widths[k];
        p[static_cast<std::size_t>(3 + k)].*fields[k] += d;
        p[static_cast<std::size_t>(12 + k)].*fields[k] -= d;
    }
    std::vector<BoucWenState> from(19);
    std::vector<BoucWenIncrement> out(19);
    BoucWenState centreState;
    double x = 0.0;
    std::size_t k = 0;
    for (auto _ : state) {
        if (k == h.u.size()) {
            centreState = {};
            x = 0.0;
            k = 0;
        }
        const double next = h.u[k++] / centre.uRef;
        for (std::size_t i = 0; i < from.size(); ++i) {
            from[i] = centreState;
        }
        from[1].z += 1e-5; // the z and e directions
        from[2].e += 1e-5;
        BoucWen::integrateStates(p, from, next - x, out, math);
        benchmark::DoNotOptimize(out.data());
        centreState = out[0].state;
        x = next;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK_CAPTURE(bmIdentSigmaIntegrations, exact, BoucWen::BatchMath::Exact);
BENCHMARK_CAPTURE(bmIdentSigmaIntegrations, fast, BoucWen::BatchMath::Fast);

// One Nelder-Mead trigger: Bouc-Wen, 7 parameters in Table III, 1000 points, 200 evaluations.
void bmIdentHistoryFitTrigger(benchmark::State& state) {
    const History h = history(1000, 250);
    HistoryFitSpec spec;
    spec.law = "boucWen";
    const BoucWenParameters w = wrongStart();
    spec.initial = {{"k0", w.k0},
                    {"alpha", w.alpha},
                    {"n", w.n},
                    {"beta", w.beta},
                    {"gamma", w.gamma},
                    {"deltaNu", w.deltaNu},
                    {"deltaEta", w.deltaEta},
                    {"uRef", w.uRef},
                    {"fRef", w.fRef}};
    spec.fitted = {{"k0", 0.7, 1.4},        {"alpha", 0.001, 0.05}, {"n", 1.0, 3.0},
                   {"beta", 2.5, 5.0},      {"gamma", 0.0, 2.5},    {"deltaNu", 0.001, 0.1},
                   {"deltaEta", 0.001, 0.1}};
    spec.optimizer.maxEvaluations = 200;
    const HistoryFit fit(spec);
    HistoryFitResult r;
    for (auto _ : state) {
        r = fit.fit(h.u, h.f);
        benchmark::DoNotOptimize(r);
    }
    state.counters["replays"] = r.evaluations;
    state.counters["rmsRatio"] = r.rmsBefore / r.rmsAfter;
}
BENCHMARK(bmIdentHistoryFitTrigger)->Unit(benchmark::kMillisecond);

// The default calibration (no scales, bounds or starts given) of a 30,000-sample record: the
// synthetic specimen above, 8 cycles growing to 4 uRef, with 1 % deterministic force noise.
void bmIdentCalibration30k(benchmark::State& state) {
    History h = history(30000, 3750);
    for (std::size_t k = 0; k < h.f.size(); ++k)
        h.f[k] += 0.2 * std::sin(0.37 * double(k)) * std::cos(1.3 * double(k));
    CalibrationResult r;
    for (auto _ : state) {
        r = calibrateHistory(h.u, h.f, CalibrationRequest{});
        benchmark::DoNotOptimize(r);
    }
    state.counters["nrmse"] = r.nrmse;
    state.counters["replays"] = r.residualEvaluations;
}
BENCHMARK(bmIdentCalibration30k)->Unit(benchmark::kMillisecond)->Iterations(3);

// The robust UKF per step, steps 1,600-2,300 of the cyclic record above (the first 1,600
// samples, warm-up and first anchors, outside the timing). Guard checks, anchors and their
// application happen in the timed part: the calibrations and the guard's replays run on the
// identifier's worker thread. CPU: the stepping thread's own (the target); real time also
// counts its waits for the worker at the steps where a job's result is due (this benchmark
// steps far faster than a test: a job gets max(50, N/20) steps, here about 0.3 ms).
// Counters: WorkerIdentifierSteps.h.
void bmIdentRobustUkfStep(benchmark::State& state) {
    const History h = history(2400, 400);
    bench::workerIdentifierSteps(state, h.u, h.f, [] {
        return std::make_unique<RobustUkfIdentifier>(wrongStart(), std::nullopt, std::nullopt,
                                                     ParameterBoundsMap{});
    });
}
BENCHMARK(bmIdentRobustUkfStep);

} // namespace
