// Recording benchmarks (issue 4 target on the 2-core dev machine):
//   RecordWriter::onStep, amortized over buffering, extend + write + H5Fflush   <= 2 us
//   bytes per 1000 steps of the condition-3 frame (2 DOFs, 3 elements, 7 parameters)
// The rows are real StepRecords of the preset paper-condition-3 (UKF updating), replayed
// into a writer on a temporary file so that only the recording is timed.
// Offline re-identification (hsmu replay --identify): the UKF re-run over the recorded
// specimen history of the same 30 s run (3000 samples), per sample.
// Run: build/bin/hsmu_bench --benchmark_filter=Record

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/offline/OfflineIdentification.h"
#include "core/output/RunLayout.h"
#include "core/record/RecordWriter.h"
#include "core/experiment/HybridTest.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace hsmu;

class Keep final : public StepObserver {
public:
    void onStep(const StepRecord& r) override { records.push_back(r); }
    std::vector<StepRecord> records;
};

struct Recorded {
    TestConfig cfg;
    RunLayout layout;
    std::vector<StepRecord> records;
};

/// The 30 s preset run's StepRecords (3001 rows).
const Recorded& recorded() {
    static const Recorded r = [] {
        Recorded out;
        out.cfg = loadConfigFile(std::string(HSMU_SOURCE_DIR) +
                                 "/resources/presets/paper-condition-3.json");
        auto test = buildHybridTest(out.cfg);
        Keep keep;
        test->addObserver(&keep);
        test->prepare();
        while (test->step() == HybridTest::StepResult::Advanced) {
        }
        out.layout = RunLayout::of(*test);
        out.records = std::move(keep.records);
        return out;
    }();
    return r;
}

RecordStart startOf(const TestConfig& cfg) {
    RecordStart s;
    s.configuration = cfg.raw.dump();
    s.configName = cfg.name;
    s.dt = cfg.analysis.dt;
    return s;
}

std::string tempRecordPath() {
    return (std::filesystem::temp_directory_path() / "hsmu_bench_record.h5").string();
}

/// The same rows without their applied-update events (a reporter policy other than
/// everyStep applies far fewer updates than one per step).
const std::vector<StepRecord>& withoutEvents() {
    static const std::vector<StepRecord> rows = [] {
        std::vector<StepRecord> out = recorded().records;
        for (StepRecord& r : out)
            r.updating.applied.clear();
        return out;
    }();
    return rows;
}

/// Arg 1: every row carries its update event (condition 3 applies every step); 0: none.
void bmRecordStep(benchmark::State& state) {
    const Recorded& r = recorded();
    const std::vector<StepRecord>& rows = state.range(0) ? r.records : withoutEvents();
    const std::string path = tempRecordPath();
    {
        RecordWriter writer(path, r.layout, startOf(r.cfg));
        std::size_t i = 0;
        for (auto _ : state) {
            writer.onStep(rows[i]);
            if (++i == r.records.size())
                i = 0;
        }
        writer.finish();
        if (!writer.ok())
            state.SkipWithError(writer.error().c_str());
    }
    state.SetItemsProcessed(state.iterations());
    std::filesystem::remove(path);
}
BENCHMARK(bmRecordStep)->Arg(1)->Arg(0)->MinTime(2.0);

void bmRecordBytesPer1000Steps(benchmark::State& state) {
    const Recorded& r = recorded();
    const std::string path = tempRecordPath();
    const int steps = int(state.range(0));
    double bytes = 0.0;
    for (auto _ : state) {
        RecordWriter writer(path, r.layout, startOf(r.cfg));
        for (int k = 0; k < steps; ++k)
            writer.onStep(r.records[std::size_t(k) % r.records.size()]);
        writer.finish();
        bytes = double(std::filesystem::file_size(path));
    }
    state.counters["bytes_per_1000_steps"] = bytes / steps * 1000.0;
    state.counters["file_bytes"] = bytes;
    std::filesystem::remove(path);
}
BENCHMARK(bmRecordBytesPer1000Steps)->Arg(3001)->Arg(100000)->Unit(benchmark::kMillisecond);

void bmRecordOfflineUkfPerSample(benchmark::State& state) {
    const Recorded& r = recorded();
    const IdentificationSettings settings = identificationSettingsFrom(r.cfg);
    SpecimenHistory h;
    h.source = "benchmark";
    for (std::size_t k = 1; k < r.records.size(); ++k) { // Element 1, the specimen
        h.time.push_back(r.records[k].time);
        h.deformation.push_back(r.records[k].elements[0].deformation);
        h.force.push_back(r.records[k].elements[0].force);
    }
    for (auto _ : state)
        benchmark::DoNotOptimize(identifyOffline(h, settings).finalNrmse);
    state.SetItemsProcessed(state.iterations() * h.size()); // samples per second
}
BENCHMARK(bmRecordOfflineUkfPerSample)->Unit(benchmark::kMillisecond);

} // namespace
