#pragma once
// HeadlessRun: one hybrid test run headless into an output folder, the set-up and the end that
// `hsmu run` (gui/cli/RunCommand) and hsmu.run in Python (python/PyRun) share (docs/cli.md
// "hsmu run", docs/python.md "Runs"): the folder; steps.csv (StepCsvWriter, unless "none", or
// "auto" and wider than StepCsvWriter::kMaxColumns); the HDF5 record (docs/recording.md) and
// the run statistics, around the one TestSession (core/session/TestSession.h) that steps it;
// at the end the record and steps.csv closed and summary.json written (RunSummary.h).
// The front end builds the test (its control factory: builtin or a link) and adds its own
// observers (progress, arrays) and reports; an empty out folder writes no file at all.
// Thread rules: construct, prepare and finish on one thread; runToEnd() may run on another
// (the Python module's worker) while nothing else touches the run.

#include "core/output/RunLayout.h"
#include "core/output/RunStatistics.h"
#include "core/output/RunSummary.h"
#include "core/session/TestSession.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hsmu {

class StepCsvWriter;
struct TestConfig;

struct HeadlessOptions {
    /// The output folder (created with its parents); "" writes nothing (hsmu.run(out=None)).
    std::string outDir;
    /// steps.csv: Auto (when a row has at most StepCsvWriter::kMaxColumns values), All, None.
    enum class Csv { Auto, All, None } csv = Csv::Auto;
    ReconnectPolicy reconnect; ///< `--reconnect N` (SessionOptions)
    int deflate = 0;           ///< the record's deflate level (RecordStart::deflate)
    /// Each site's link security for the record and summary.json (RecordStart::siteSecurity,
    /// RunInfo::siteSecurity; comms' siteSecurity() of the controller address and the
    /// configuration).
    SiteSecurity siteSecurity;
};

class HeadlessRun {
public:
    /// Creates the folder and steps.csv and opens the record. Throws std::runtime_error with
    /// the message to print ("DIR: cannot create the output directory", steps.csv that cannot
    /// be opened, the record's error). `hsmu run` creates the folder first itself (its words).
    HeadlessRun(const TestConfig& cfg, std::unique_ptr<HybridTest> test, HeadlessOptions options);
    ~HeadlessRun();
    HeadlessRun(const HeadlessRun&) = delete;
    HeadlessRun& operator=(const HeadlessRun&) = delete;

    TestSession& session() { return m_session; }
    HybridTest& test() { return m_session.test(); }
    const RunLayout& layout() const { return m_layout; }
    const RunStatistics& statistics() const { return m_stats; }
    /// The row width when steps.csv was left out for it (Csv::Auto); 0 otherwise.
    std::size_t csvSkippedColumns() const { return m_csvSkipped; }

    /// TestSession::prepare (connects the links); false with the reason in lastError(). The
    /// front ends say "the test cannot start: REASON".
    bool prepare();
    const std::string& lastError() const { return m_session.lastError(); }
    /// TestSession::runToEnd, timing it (RunInfo::wallTimeS).
    TestSession::Status runToEnd();
    /// What finish() could not write; every field empty when everything was written.
    struct Failures {
        std::string record;   ///< the record's error (TestSession::finish), a sentence
        std::string stepsCsv; ///< the path of a steps.csv that could not be written
        std::string summary;  ///< the summary.json error, a sentence naming the file
    };
    /// Closes the record and steps.csv and writes summary.json (with an out folder).
    Failures finish();
    /// The run's configuration name and file and its wall time (after runToEnd).
    const RunInfo& info() const { return m_info; }
    /// The folder ("" for none).
    const std::string& outDir() const { return m_options.outDir; }

private:
    HeadlessOptions m_options;
    RunLayout m_layout;
    std::unique_ptr<StepCsvWriter> m_csv;
    std::size_t m_csvSkipped = 0;
    TestSession m_session;
    RunStatistics m_stats;
    RunInfo m_info;
};

} // namespace hsmu
