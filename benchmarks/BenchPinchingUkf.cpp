// The pinching UKF identifier (PinchingUkfIdentifier; issue 12: usable live on long records):
//   bmIdentPinchingUkfIdentifierStep  the identifier per step on the stepping thread (target
//       <= 25 us), steps 1,600-2,300 of a synthetic pinching record (the first 1,600 samples,
//       warm-up and first anchors, outside the timing); the anchors and guard replays run on
//       its worker. Counters as bmIdentRobustUkfStep: the worker's CPU per timed step, per
//       anchor and per guard replay [us]; anchors and waits per 1000 timed steps.
//   bmIdentPinchingUkfHdrb  the whole HDRB bearing record (26,379 samples, ../shared/data;
//       skipped when absent) through the identifier, once: the stepping thread's CPU per step
//       [us], the worker's CPU in all, per anchor and for the most expensive anchor [s], the
//       anchors (global ones), waits and divergences, and the final estimate's NRMSE over the
//       record.
// Run: build/bin/hsmu_bench --benchmark_filter=PinchingUkfIdentifier|PinchingUkfHdrb

#include "core/hysteresis/BoucWenPinching.h"
#include "core/updating/PinchingUkfIdentifier.h"
#include "core/updating/RobustUkfJobs.h"
#include "WorkerIdentifierSteps.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <vector>

namespace {

using namespace hsmu;

BoucWenPinchingParameters pinchedTruth() {
    BoucWenPinchingParameters p;
    p.boucWen.k0 = 1.0;
    p.boucWen.alpha = 0.05;
    p.boucWen.n = 1.5;
    p.boucWen.beta = 0.6;
    p.boucWen.gamma = 0.4;
    p.boucWen.deltaNu = 0.01;
    p.boucWen.deltaEta = 0.01;
    p.pinching = {0.7, 0.5, 0.1, 0.3, 0.0, 0.5};
    return p;
}

void pinchedHistory(int points, int perCycle, std::vector<double>& u, std::vector<double>& f) {
    BoucWenPinching law(pinchedTruth());
    for (int k = 1; k <= points; ++k) {
        const double c = double(k) / perCycle;
        const double v = 4.0 * std::min(1.0, c / 4.0) * std::sin(2.0 * M_PI * c);
        law.setTrialDeformation(v);
        law.commit();
        u.push_back(v);
        f.push_back(law.committedForce() + 0.01 * std::sin(0.37 * k) * std::cos(1.3 * k));
    }
}

BoucWenPinchingParameters wrongPinchedStart() {
    BoucWenPinchingParameters p;
    p.boucWen.k0 = 1.6;
    p.boucWen.beta = 2.0;
    p.boucWen.gamma = 1.0;
    p.pinching.zetaS = 0.0;
    return p;
}

void bmIdentPinchingUkfIdentifierStep(benchmark::State& state) {
    std::vector<double> u, f;
    pinchedHistory(2400, 400, u, f);
    bench::workerIdentifierSteps(state, u, f, [] {
        return std::make_unique<PinchingUkfIdentifier>(wrongPinchedStart(), std::nullopt,
                                                       std::nullopt, ParameterBoundsMap{});
    });
}
BENCHMARK(bmIdentPinchingUkfIdentifierStep)->Iterations(2100);

void bmIdentPinchingUkfHdrb(benchmark::State& state) {
    std::ifstream in(std::string(HSMU_SHARED_DATA_DIR) +
                     "/hysteresis/isolator-hdrb-gallardo2023/hdrb_test.txt");
    std::vector<double> u, f;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#')
            continue;
        std::istringstream s(line);
        double t, a, b;
        if (s >> t >> a >> b)
            u.push_back(a), f.push_back(b);
    }
    if (u.empty()) {
        state.SkipWithError("../shared/data/hysteresis/isolator-hdrb-gallardo2023 absent");
        return;
    }
    for (auto _ : state) {
        PinchingUkfIdentifier id(BoucWenPinchingParameters{}, std::nullopt, std::nullopt, {});
        double maxAnchor = 0.0;
        const double t0 = threadCpuSeconds(); // this thread's: the worker's is counted apart
        for (std::size_t k = 0; k < u.size(); ++k)
            if (id.observe(u[k], f[k], false).refit)
                maxAnchor = std::max(maxAnchor, id.lastComputeSeconds());
        const double stepping = threadCpuSeconds() - t0;
        BoucWenPinchingParameters p;
        const std::span<const double> e = id.estimate(); // layout: the 13, uRef, fRef
        for (int j = 0; j < kPinchingUkfParameters; ++j)
            PinchingUkf::field(p, j) = e[std::size_t(j)];
        p.boucWen.uRef = e[kPinchingUkfParameters];
        p.boucWen.fRef = e[kPinchingUkfParameters + 1];
        state.counters["steppingUsPerStep"] = 1e6 * stepping / double(u.size());
        state.counters["workerS"] = id.workerCpuSeconds();
        state.counters["workerSPerAnchor"] = id.anchorCpuSeconds() / std::max(id.anchors(), 1);
        state.counters["maxAnchorS"] = maxAnchor;
        state.counters["anchors"] = id.anchors();
        state.counters["globalAnchors"] = id.globalAnchors();
        state.counters["jobs"] = id.jobs();
        state.counters["waits"] = id.waits();
        state.counters["divergences"] = id.divergences();
        state.counters["finalNrmse"] = verifyJob(u, f, p).nrmse;
    }
}
BENCHMARK(bmIdentPinchingUkfHdrb)->Iterations(1)->Unit(benchmark::kSecond);

} // namespace
