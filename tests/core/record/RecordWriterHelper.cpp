// record_writer_helper OUT.h5 STEPS_PER_SECOND [DT]: runs the preset paper-condition-3 (30 s,
// UKF updating; integration step DT if given) paced at STEPS_PER_SECOND steps of wall time
// per second (0: as fast as it goes) while a RecordWriter records it to OUT.h5, and prints
// "flushed N" (N rows on disk) after every flush, "step N" every 100 steps (the step is
// published to the writer before the line is printed) and "done N" at the end.
// TestRecordCrash reads the file while it grows and kills this process.

#include "RecordFixture.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <thread>

int main(int argc, char** argv) {
    using namespace hsmu;
    if (argc != 3 && argc != 4) {
        std::fprintf(stderr, "usage: record_writer_helper OUT.h5 STEPS_PER_SECOND [DT]\n");
        return 2;
    }
    try {
        const double rate = std::atof(argv[2]);
        TestConfig cfg = testsupport::condition3(0.0);
        if (argc == 4) {
            nlohmann::json j = cfg.raw;
            j["analysis"]["dt"] = std::atof(argv[3]);
            cfg = parseConfig(j, "helper.json");
        }
        auto test = buildHybridTest(cfg);
        RecordWriter writer(argv[1], RunLayout::of(*test), testsupport::recordStart(cfg));
        writer.trackAlarms(&test->alarms());
        test->addObserver(&writer);
        if (!test->prepare()) {
            std::fprintf(stderr, "%s\n", test->lastError().c_str());
            return 1;
        }
        const auto start = std::chrono::steady_clock::now();
        int flushed = writer.rowsFlushed();
        for (long n = 1; test->step() == HybridTest::StepResult::Advanced; ++n) {
            if (writer.rowsFlushed() != flushed) {
                flushed = writer.rowsFlushed();
                std::printf("flushed %d\n", flushed);
                std::fflush(stdout);
            }
            if (n % 100 == 0) {
                std::printf("step %ld\n", n);
                std::fflush(stdout);
            }
            if (rate > 0.0)
                std::this_thread::sleep_until(start +
                                              std::chrono::duration<double>(double(n) / rate));
        }
        writer.finish();
        std::printf("done %d\n", writer.rowsFlushed());
        return writer.ok() ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
