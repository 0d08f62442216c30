// record_writer_helper OUT.h5 STEPS_PER_SECOND: runs the preset paper-condition-3 (30 s,
// UKF updating) paced at STEPS_PER_SECOND steps of wall time per second while a RecordWriter
// records it to OUT.h5, and prints "flushed N" (N rows on disk) after every flush and
// "done N" at the end. TestRecordCrash reads the file while it grows and kills this process.

#include "RecordFixture.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <thread>

int main(int argc, char** argv) {
    using namespace hsmu;
    if (argc != 3) {
        std::fprintf(stderr, "usage: record_writer_helper OUT.h5 STEPS_PER_SECOND\n");
        return 2;
    }
    try {
        const double rate = std::atof(argv[2]);
        const TestConfig cfg = testsupport::condition3(0.0);
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
            std::this_thread::sleep_until(start + std::chrono::duration<double>(double(n) / rate));
        }
        writer.finish();
        std::printf("done %d\n", writer.rowsFlushed());
        return writer.ok() ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
