#include "gui/cli/RunCommand.h"

#include "comms/link/ControlFactory.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/session/HeadlessRun.h"
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
    HeadlessOptions headless;
    headless.outDir = options.outDir.toStdString();
    headless.csv = options.csv == QLatin1String("none")  ? HeadlessOptions::Csv::None
                   : options.csv == QLatin1String("all") ? HeadlessOptions::Csv::All
                                                         : HeadlessOptions::Csv::Auto;
    headless.reconnect.attempts = options.reconnect;
    headless.deflate = options.deflate;
    headless.siteSecurity = comms::siteSecurity(options.controller, cfg);
    // Folder, steps.csv, the HDF5 record (docs/recording.md, flushed at least twice a second),
    // statistics and summary.json: core/session/HeadlessRun, as hsmu.run in Python.
    std::unique_ptr<HeadlessRun> headlessRun;
    try {
        headlessRun = std::make_unique<HeadlessRun>(cfg, std::move(test), headless);
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    if (const std::size_t columns = headlessRun->csvSkippedColumns())
        err() << tr("hsmu run: steps.csv not written (%1 columns); record.h5 holds every "
                    "column (hsmu export writes CSV from it)")
                     .arg(columns)
              << Qt::endl;
    TestSession& session = headlessRun->session();
    HybridTest* const run = &session.test();
    const RunLayout& layout = headlessRun->layout();
    RecordCollector records;
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
    if (!headlessRun->prepare())
        return fail(
            tr("the test cannot start: %1").arg(QString::fromStdString(headlessRun->lastError())));

    Progress progress(*run);
    session.addObserver(&progress);
    const TestSession::Status result = headlessRun->runToEnd();
    session.removeObserver(&progress);

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
    const HeadlessRun::Failures failed = headlessRun->finish();
    if (!failed.record.empty())
        code = fail(QString::fromStdString(failed.record));
    if (!failed.stepsCsv.empty())
        code = fail(tr("%1: write failed").arg(QString::fromStdString(failed.stepsCsv)));
    if (!failed.summary.empty())
        code = fail(QString::fromStdString(failed.summary));
    if (options.plots) {
        if (!CliPlots::installed().run)
            code = fail(tr("--plots: this program cannot draw (run it through hsmu)"));
        else
            for (const QString& f : CliPlots::installed().run(QDir(options.outDir).path(), layout,
                                                              records.records(), cfg))
                code = fail(tr("%1: the plot could not be written").arg(f));
    }
    RunReport::print(ConsoleStreams::out(), *run, headlessRun->statistics(), headlessRun->info(),
                     QDir(options.outDir).path());
    return code;
}

} // namespace hsmu::gui
