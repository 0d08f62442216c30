#pragma once
// RecordedRun: a real short run of a preset on the built-in virtual specimen (no window, no
// thread): every StepRecord, its layout and configuration, and optionally the HDF5 record
// written by the real RecordWriter. Shared by the plot and replay tests.

#include "core/config/TestFactory.h"
#include "core/output/RunLayout.h"
#include "core/record/RecordWriter.h"
#include "core/experiment/HybridTest.h"
#include "gui/PresetLibrary.h"
#include "gui/cli/RecordCollector.h"

#include <QString>

#include <memory>
#include <stdexcept>
#include <vector>

namespace recordedrun {

struct Run {
    hsmu::TestConfig config;
    hsmu::RunLayout layout;
    std::vector<hsmu::StepRecord> records;
};

/// Runs preset `id` for `duration` test seconds; with recordPath, also writes the record.
inline Run run(const QString& id, double duration, const QString& recordPath = {}) {
    Run out;
    out.config = hsmu::gui::PresetLibrary::load(id);
    out.config.analysis.duration = duration;
    std::unique_ptr<hsmu::HybridTest> test = hsmu::buildHybridTest(out.config);
    out.layout = hsmu::RunLayout::of(*test);
    hsmu::gui::RecordCollector collector;
    std::unique_ptr<hsmu::RecordWriter> writer;
    if (!recordPath.isEmpty()) {
        writer = std::make_unique<hsmu::RecordWriter>(
            recordPath.toStdString(), out.layout,
            hsmu::RecordStart{out.config.raw.dump(), out.config.name, {}, out.config.analysis.dt});
        writer->trackAlarms(&test->alarms());
        test->addObserver(writer.get());
    }
    test->addObserver(&collector);
    if (!test->prepare())
        throw std::runtime_error("the test cannot start: " + test->lastError());
    hsmu::HybridTest::StepResult r = hsmu::HybridTest::StepResult::Advanced;
    while (r == hsmu::HybridTest::StepResult::Advanced)
        r = test->step();
    if (r != hsmu::HybridTest::StepResult::Finished)
        throw std::runtime_error("the test did not finish");
    if (writer) {
        test->removeObserver(writer.get());
        if (!writer->finish())
            throw std::runtime_error("the record could not be written: " + writer->error());
    }
    test->removeObserver(&collector);
    out.records = collector.records();
    return out;
}

} // namespace recordedrun
