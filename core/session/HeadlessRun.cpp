#include "core/session/HeadlessRun.h"

#include "core/config/TestConfig.h"
#include "core/output/StepCsvWriter.h"

#include <chrono>
#include <filesystem>
#include <stdexcept>

namespace fs = std::filesystem;

namespace hsmu {

namespace {

std::string inFolder(const std::string& dir, const char* file) {
    return dir.empty() ? std::string() : (fs::path(dir) / file).string();
}

/// The folder exists before anything else is built (the session's record goes there).
const std::string& createFolder(const std::string& dir) {
    if (dir.empty())
        return dir;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (!fs::is_directory(dir, ec))
        throw std::runtime_error(dir + ": cannot create the output directory");
    return dir;
}

SessionOptions sessionOptions(const TestConfig& cfg, const HeadlessOptions& o) {
    SessionOptions s;
    s.reconnect = o.reconnect;
    s.recordPath = inFolder(o.outDir, "record.h5");
    s.recordStart = RecordStart{cfg.raw.dump(), cfg.name, {}, cfg.analysis.dt};
    s.recordStart.deflate = o.deflate;
    s.recordStart.siteSecurity = o.siteSecurity;
    s.recordStart.dofRecording = cfg.record; // the "record" block, or hsmu run's options
    return s;
}

} // namespace

HeadlessRun::HeadlessRun(const TestConfig& cfg, std::unique_ptr<HybridTest> test,
                         HeadlessOptions options)
    : m_options((createFolder(options.outDir), std::move(options))), m_layout(RunLayout::of(*test)),
      m_session(std::move(test), sessionOptions(cfg, m_options)), m_stats(m_layout) {
    m_info.configName = cfg.name;
    m_info.configFile = cfg.sourcePath;
    m_info.siteSecurity = m_options.siteSecurity;
    m_info.dofRecording = cfg.record;
    const std::size_t columns = StepCsvWriter::columnCount(m_layout);
    if (!m_options.outDir.empty() && m_options.csv != HeadlessOptions::Csv::None) {
        if (m_options.csv == HeadlessOptions::Csv::Auto && columns > StepCsvWriter::kMaxColumns)
            m_csvSkipped = columns;
        else
            m_csv =
                std::make_unique<StepCsvWriter>(inFolder(m_options.outDir, "steps.csv"), m_layout);
    }
    if (!m_session.openRecord())
        throw std::runtime_error(m_session.lastError());
    if (m_csv)
        m_session.addObserver(m_csv.get());
    m_session.addObserver(&m_stats);
}

HeadlessRun::~HeadlessRun() {
    m_session.removeObserver(&m_stats);
    if (m_csv)
        m_session.removeObserver(m_csv.get());
}

bool HeadlessRun::prepare() {
    return m_session.prepare();
}

TestSession::Status HeadlessRun::runToEnd() {
    const auto started = std::chrono::steady_clock::now();
    const TestSession::Status status = m_session.runToEnd();
    m_info.wallTimeS =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    return status;
}

HeadlessRun::Failures HeadlessRun::finish() {
    Failures failed;
    if (m_csv)
        m_session.removeObserver(m_csv.get());
    if (!m_session.finish())
        failed.record = m_session.lastError();
    if (m_csv && !m_csv->finish())
        failed.stepsCsv = m_csv->path();
    if (!m_options.outDir.empty()) {
        try {
            writeSummaryJson(inFolder(m_options.outDir, "summary.json"), m_session.test(), m_stats,
                             m_info);
        } catch (const std::exception& e) {
            failed.summary = e.what();
        }
    }
    return failed;
}

} // namespace hsmu
