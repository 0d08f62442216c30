#include "gui/cli/RunCommand.h"

#include "comms/link/ControlFactory.h"
#include "core/config/TestFactory.h"
#include "core/output/RunStatistics.h"
#include "core/output/RunSummary.h"
#include "core/output/StepCsvWriter.h"
#include "core/record/RecordWriter.h"
#include "core/experiment/HybridTest.h"
#include "core/session/TestSession.h"
#include "gui/PresetLibrary.h"
#include "gui/cli/CliPlots.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/cli/RecordCollector.h"
#include "gui/cli/RunOptions.h"
#include "gui/cli/RunReport.h"
#include "gui/cli/SignalHold.h"

#include <QDir>
#include <QElapsedTimer>
#include <QTextStream>

#include <algorithm>
#include <memory>

namespace hsmu::gui {

namespace {

QTextStream& err() {
    return ConsoleStreams::err();
}

int fail(const QString& message) {
    err() << "hsmu run: " << message << Qt::endl;
    return 1;
}

QString num(double x, int digits = 4) {
    return QString::number(x, 'g', digits);
}

/// Connection settings for a headless run: the session's timeouts (LinkTimeouts), the token.
comms::TcpControlOptions linkOptions(const RunOptions& options) {
    comms::TcpControlOptions o;
    o.token = options.token.toStdString();
    return o;
}

/// Progress on stderr about every 5 %: percent, test time, steps/s.
class Progress final : public StepObserver {
public:
    explicit Progress(const HybridTest& test) : m_test(test) { m_wall.start(); }
    void onStep(const StepRecord& row) override {
        if (row.step == 0)
            return;
        const int percent = int(100.0 * row.step / std::max(1, m_test.totalSteps()));
        if (percent < m_next && row.step < m_test.totalSteps())
            return;
        const double seconds = std::max(1e-9, m_wall.nsecsElapsed() * 1e-9);
        err() << RunCommand::tr("%1 %  t = %2 s  %3 steps/s")
                     .arg(percent, 3)
                     .arg(QString::number(row.time, 'f', 2))
                     .arg(QString::number(row.step / seconds, 'f', 0))
              << Qt::endl;
        m_next = (percent / 5 + 1) * 5;
    }

private:
    const HybridTest& m_test;
    QElapsedTimer m_wall;
    int m_next = 5;
};

} // namespace

int RunCommand::exec(const QStringList& arguments) {
    RunOptions options;
    if (auto error = RunOptions::parse(arguments, options))
        return error->isEmpty() ? 0 : fail(*error);

    TestConfig cfg;
    std::unique_ptr<HybridTest> test;
    try {
        cfg = PresetLibrary::load(options.config);
        options.overrides.applyTo(cfg);
        if (!options.approval.isEmpty()) {
            if (!cfg.updating.enabled)
                err() << tr("hsmu run: --approval ignored: the configuration has no updating")
                      << Qt::endl;
            cfg.updating.approval = options.approval.toStdString();
        }
        test = buildHybridTest(
            cfg, comms::makeControlFactory(options.controller, linkOptions(options), cfg));
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    if (!QDir().mkpath(options.outDir))
        return fail(tr("%1: cannot create the output directory").arg(options.outDir));
    const QDir dir(options.outDir);

    const RunLayout layout = RunLayout::of(*test);
    std::unique_ptr<StepCsvWriter> csv;
    const std::size_t csvColumns = StepCsvWriter::columnCount(layout);
    if (options.csv == QLatin1String("none")) {
        // steps.csv not wanted: record.h5 holds every column
    } else if (csvColumns > StepCsvWriter::kMaxColumns && options.csv != QLatin1String("all")) {
        err() << tr("hsmu run: steps.csv not written (%1 columns); record.h5 holds every "
                    "column (hsmu export writes CSV from it)")
                     .arg(csvColumns)
              << Qt::endl;
    } else {
        try {
            csv = std::make_unique<StepCsvWriter>(
                dir.filePath(QStringLiteral("steps.csv")).toStdString(), layout);
        } catch (const std::exception& e) {
            return fail(QString::fromStdString(e.what()));
        }
    }
    // Every run writes its HDF5 record (docs/recording.md), flushed at least twice a second;
    // stepping, record and the --reconnect policy are the session's (core/session).
    SessionOptions sessionOptions;
    sessionOptions.reconnect.attempts = options.reconnect;
    sessionOptions.recordPath = dir.filePath(QStringLiteral("record.h5")).toStdString();
    sessionOptions.recordStart = RecordStart{cfg.raw.dump(), cfg.name, {}, cfg.analysis.dt};
    sessionOptions.recordStart.deflate = options.deflate;
    sessionOptions.recordStart.siteSecurity = comms::siteSecurity(options.controller, cfg);
    TestSession session(std::move(test), sessionOptions);
    HybridTest* const run = &session.test();
    if (!session.openRecord())
        return fail(QString::fromStdString(session.lastError()));
    RunStatistics stats(layout);
    RecordCollector records;
    if (csv)
        session.addObserver(csv.get());
    session.addObserver(&stats);
    if (options.plots)
        session.addObserver(&records);
    session.onReconnect = [run](const TestSession::Reconnect& r) {
        err() << tr("hsmu run: link fault at t = %1 s (step %2): %3; reconnecting in %4 s "
                    "(attempt %5 of %6)")
                     .arg(num(run->time(), 6))
                     .arg(run->currentStep())
                     .arg(QString::fromStdString(r.reason))
                     .arg(num(r.delay, 3))
                     .arg(r.attempt)
                     .arg(r.of)
              << Qt::endl;
    };

    if (options.controller.kind != comms::LinkAddress::Kind::Builtin)
        err() << tr("hsmu run: connecting to %1 (%2 protocol, %3)")
                     .arg(QString::fromStdString(options.controller.toString()),
                          QString::fromStdString(comms::linkProtocol(options.controller, cfg.link)),
                          QString::fromStdString(options.controller.security()))
              << Qt::endl;
    // SIGINT / SIGTERM from here on hold every site out of band (even mid-step); the
    // session never resumes an operator hold.
    SignalHold signalHold(*run);
    if (!session.prepare())
        return fail(
            tr("the test cannot start: %1").arg(QString::fromStdString(session.lastError())));

    QElapsedTimer wall;
    wall.start();
    Progress progress(*run);
    session.addObserver(&progress);
    const TestSession::Status result = session.runToEnd();
    session.removeObserver(&progress);
    RunInfo info;
    info.configName = cfg.name;
    info.configFile = cfg.sourcePath;
    info.wallTimeS = wall.nsecsElapsed() * 1e-9;

    int code = result == TestSession::Status::Finished ? 0 : 1;
    if (result == TestSession::Status::Held) {
        code = 2;
        err() << tr("hsmu run: test held at t = %1 s (step %2): %3")
                     .arg(num(run->time(), 6))
                     .arg(run->currentStep())
                     .arg(QString::fromStdString(holdReason(*run).value_or("held")))
              << Qt::endl;
    } else if (code != 0) {
        err() << tr("hsmu run: the test stopped unexpectedly (state %1)")
                     .arg(QString::fromLatin1(testStateName(run->state())))
              << Qt::endl;
    }
    if (csv)
        session.removeObserver(csv.get());
    if (!session.finish())
        code = fail(QString::fromStdString(session.lastError()));
    if (csv && !csv->finish())
        code = fail(tr("%1: write failed").arg(QString::fromStdString(csv->path())));
    try {
        writeSummaryJson(dir.filePath(QStringLiteral("summary.json")).toStdString(), *run, stats,
                         info);
    } catch (const std::exception& e) {
        code = fail(QString::fromStdString(e.what()));
    }
    if (options.plots) {
        if (!CliPlots::installed().run)
            code = fail(tr("--plots: this program cannot draw (run it through hsmu)"));
        else
            for (const QString& f :
                 CliPlots::installed().run(dir.path(), layout, records.records(), cfg))
                code = fail(tr("%1: the plot could not be written").arg(f));
    }
    RunReport::print(ConsoleStreams::out(), *run, stats, info, dir.path());
    return code;
}

} // namespace hsmu::gui
