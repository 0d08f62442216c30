// Online refit and pinching-UKF benchmarks (issue 12; docs/benchmarks.md):
//   bmIdentNelderMeadRefit/0  one Nelder-Mead trigger with the paper's simplex (the history and
//                             budget of bmIdentHistoryFitTrigger: Bouc-Wen, 7 parameters in
//                             Table III, 1000 points, maxEvaluations 200)
//   bmIdentNelderMeadRefit/1  the same trigger through the calibration, the first one (warm
//                             start plus the multi-start)
//   bmIdentNelderMeadRefit/2  a later trigger through the calibration (warm start only)
//   bmIdentPinchingUkfStep    one step of the pinching UKF (PinchingUkf: L = 15, 31 sigma
//                             points through the pinching law) between anchors
// Run: build/bin/hsmu_bench --benchmark_filter='NelderMeadRefit|PinchingUkf'

#include "core/hysteresis/BoucWen.h"
#include "tests/support/BoucWenFixture.h"
#include "core/hysteresis/BoucWenPinching.h"
#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryFit.h"
#include "core/identification/PinchingUkf.h"
#include "core/updating/NelderMeadIdentifier.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

namespace {

using namespace hsmu;

using test::truth;
using test::wrongStart;

template <class Law>
void cyclic(Law& law, double uRef, int points, int perCycle, std::vector<double>& u,
            std::vector<double>& f) {
    for (int k = 1; k <= points; ++k) {
        const double c = double(k) / perCycle;
        const double v = 4.0 * uRef * std::min(1.0, c / 4.0) * std::sin(2.0 * M_PI * c);
        law.setTrialDeformation(v);
        law.commit();
        u.push_back(v);
        f.push_back(law.committedForce());
    }
}

std::map<std::string, double> allOf(const BoucWenParameters& p) {
    return {{"k0", p.k0},       {"alpha", p.alpha},       {"n", p.n},
            {"beta", p.beta},   {"gamma", p.gamma},       {"A0", p.A0},
            {"deltaA", p.deltaA}, {"deltaNu", p.deltaNu}, {"deltaEta", p.deltaEta},
            {"uRef", p.uRef},   {"fRef", p.fRef}};
}

void bmIdentNelderMeadRefit(benchmark::State& state) {
    const int mode = int(state.range(0));
    BoucWen law(truth());
    std::vector<double> u, f;
    cyclic(law, truth().uRef, 1002, 250, u, f);
    NelderMeadIdentifierSettings s;
    s.parameters = {"k0", "alpha", "n", "beta", "gamma", "deltaNu", "deltaEta"};
    s.bounds = {{"k0", {0.7, 1.4}},        {"alpha", {0.001, 0.05}}, {"n", {1.0, 3.0}},
                {"beta", {2.5, 5.0}},      {"gamma", {0.0, 2.5}},    {"deltaNu", {0.001, 0.1}},
                {"deltaEta", {0.001, 0.1}}};
    s.maxEvaluations = 200;
    s.cooldownSteps = 1;
    s.calibrated = mode > 0;
    const std::size_t timed = mode == 2 ? 1001 : 999; // the sample whose trigger is timed
    std::unique_ptr<NelderMeadIdentifier> id;
    int evaluations = 0;
    for (auto _ : state) {
        state.PauseTiming();
        id = std::make_unique<NelderMeadIdentifier>(BoucWen(wrongStart()), s);
        for (std::size_t k = 0; k < timed; ++k) // mode 2: the first trigger at sample 999
            id->observe(u[k], f[k], mode == 2 && k == 999);
        state.ResumeTiming();
        benchmark::DoNotOptimize(id->observe(u[timed], f[timed], true));
        evaluations = id->lastEvaluations();
    }
    std::map<std::string, double> fitted = allOf(wrongStart());
    for (std::size_t k = 0; k < id->layout().size(); ++k)
        fitted[id->layout().name(k)] = id->estimate()[k];
    const std::vector<double> uu(u.begin(), u.begin() + long(timed) + 1),
        ff(f.begin(), f.begin() + long(timed) + 1);
    state.counters["replays"] = evaluations;
    state.counters["rmsRatio"] = HistoryFit::rmsError("boucWen", allOf(wrongStart()), uu, ff, 0) /
                                 HistoryFit::rmsError("boucWen", fitted, uu, ff, 0);
    state.counters["globalFits"] = id->globalFits();
}
BENCHMARK(bmIdentNelderMeadRefit)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

void bmIdentPinchingUkfStep(benchmark::State& state) {
    BoucWenPinchingParameters p;
    p.boucWen.k0 = 1.0;
    p.boucWen.alpha = 0.05;
    p.boucWen.n = 1.5;
    p.boucWen.beta = 0.6;
    p.boucWen.gamma = 0.4;
    p.boucWen.deltaNu = 0.01;
    p.boucWen.deltaEta = 0.01;
    p.pinching = {0.7, 0.5, 0.1, 0.3, 0.0, 0.5};
    BoucWenPinching law(p);
    std::vector<double> u, f;
    cyclic(law, 1.0, 2400, 400, u, f);
    // the box and P0 an anchor of PinchingUkfIdentifier gives on this history: the default
    // box in the law's scales (uRef = fRef = 1) with the history's energy, 3 % of each
    // parameter's typical scale (the identifier: 1 % to 10 %, from the calibration)
    CalibrationRequest request;
    request.law = "boucWenPinching";
    request.uRef = 1.0;
    request.fRef = 1.0;
    PinchingUkf::Box box;
    std::array<double, kPinchingUkfParameters> sd{};
    for (const auto& b : defaultCalibrationSpec(request, deriveHistoryScales(u, f)).fitted)
        for (int j = 0; j < kPinchingUkfParameters; ++j)
            if (b.name == pinchingUkfParameterNames()[std::size_t(j)]) {
                box[std::size_t(j)] = {b.lower, b.upper};
                sd[std::size_t(j)] = 0.03 * b.typical;
            }
    PinchingUkfSettings us;
    us.forceNoise = 0.01;
    BoucWenPinchingParameters start = p; // a little off the truth, as after an anchor
    start.boucWen.k0 = 1.1;
    start.pinching.zetaS = 0.6;
    PinchingUkf ukf(start, box, us);
    ukf.restart(start, {}, 0.0, sd);
    std::size_t k = 0;
    int rejected = 0;
    for (auto _ : state) {
        if (k == u.size()) {
            state.PauseTiming();
            ukf.restart(start, {}, 0.0, sd);
            k = 0;
            state.ResumeTiming();
        }
        const PinchingUkfStep s = ukf.step(u[k], f[k]);
        rejected += !s.status.ok;
        benchmark::DoNotOptimize(s);
        ++k;
    }
    state.counters["rejected"] = rejected;
    state.counters["zetaS"] = ukf.estimate().pinching.zetaS;
}
BENCHMARK(bmIdentPinchingUkfStep);

} // namespace
