#include "gui/cli/RunCommand.h"

#include "comms/link/ControlFactory.h"
#include "core/config/TestFactory.h"
#include "core/output/RunStatistics.h"
#include "core/output/RunSummary.h"
#include "core/output/StepCsvWriter.h"
#include "core/record/RecordWriter.h"
#include "core/experiment/HybridTest.h"
#include "gui/PresetLibrary.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/cli/RecordCollector.h"
#include "gui/cli/RunOptions.h"
#include "gui/cli/RunReport.h"
#include "gui/plots/PlotExporter.h"

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

/// Connection settings for a headless run: a short connect timeout, so that a controller
/// that is not there is an error within seconds rather than a long wait.
comms::TcpControlOptions linkOptions(const RunOptions& options) {
    comms::TcpControlOptions o;
    o.token = options.token.toStdString();
    o.connectTimeout = 2.0;
    return o;
}

bool heldOnControlFault(const HybridTest& test) {
    return test.state() == HybridTest::State::Holding && !test.alarms().empty() &&
           test.alarms().back().kind == AlarmKind::ControlFault;
}

/// Steps to the end, a hold or a failure, printing progress on stderr; resumes after a
/// control fault as the --reconnect policy allows.
HybridTest::StepResult runLoop(HybridTest& test, const RunOptions& options, RecordWriter& record) {
    QElapsedTimer wall;
    wall.start();
    const int total = std::max(1, test.totalSteps());
    int nextPercent = 5;
    int attempts = 0;
    int stepAtResume = -1;
    for (;;) {
        const HybridTest::StepResult result = test.step();
        const int percent = int(100.0 * test.currentStep() / total);
        if (percent >= nextPercent || result == HybridTest::StepResult::Finished) {
            const double seconds = std::max(1e-9, wall.nsecsElapsed() * 1e-9);
            err() << RunCommand::tr("%1 %  t = %2 s  %3 steps/s")
                         .arg(percent, 3)
                         .arg(QString::number(test.time(), 'f', 2))
                         .arg(QString::number(test.currentStep() / seconds, 'f', 0))
                  << Qt::endl;
            nextPercent = (percent / 5 + 1) * 5;
        }
        if (result == HybridTest::StepResult::Advanced)
            continue;
        if (result != HybridTest::StepResult::Held)
            return result;
        if (test.currentStep() > stepAtResume)
            attempts = 0; // the test advanced since the last resume: a new fault
        if (attempts >= options.reconnect || !heldOnControlFault(test))
            return result;
        ++attempts;
        stepAtResume = test.currentStep();
        record.flush(); // the hold and its alarm reach the file before a reconnect may block
        err() << RunCommand::tr("hsmu run: link fault at t = %1 s (step %2): %3; reconnecting "
                                "(attempt %4 of %5)")
                     .arg(num(test.time(), 6))
                     .arg(test.currentStep())
                     .arg(QString::fromStdString(holdReason(test).value_or("held")))
                     .arg(attempts)
                     .arg(options.reconnect)
              << Qt::endl;
        test.resume();
    }
}

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
            cfg, comms::makeControlFactory(options.controller, linkOptions(options), cfg.link));
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    if (!QDir().mkpath(options.outDir))
        return fail(tr("%1: cannot create the output directory").arg(options.outDir));
    const QDir dir(options.outDir);

    const RunLayout layout = RunLayout::of(*test);
    std::unique_ptr<StepCsvWriter> csv;
    const std::size_t csvColumns = StepCsvWriter::columnCount(layout);
    if (csvColumns > StepCsvWriter::kMaxColumns) {
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
    // Every run writes its HDF5 record (docs/recording.md), flushed at least twice a second.
    std::unique_ptr<RecordWriter> record;
    try {
        RecordStart start{cfg.raw.dump(), cfg.name, {}, cfg.analysis.dt};
        record = std::make_unique<RecordWriter>(
            dir.filePath(QStringLiteral("record.h5")).toStdString(), layout, start);
        record->trackAlarms(&test->alarms());
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    RunStatistics stats(layout);
    RecordCollector records;
    test->addObserver(record.get());
    if (csv)
        test->addObserver(csv.get());
    test->addObserver(&stats);
    if (options.plots)
        test->addObserver(&records);

    if (options.controller.kind != comms::LinkAddress::Kind::Builtin)
        err() << tr("hsmu run: connecting to %1 (%2 protocol)")
                     .arg(QString::fromStdString(options.controller.toString()),
                          QString::fromStdString(comms::linkProtocol(options.controller, cfg.link)))
              << Qt::endl;
    if (!test->prepare())
        return fail(tr("the test cannot start: %1").arg(QString::fromStdString(test->lastError())));

    QElapsedTimer wall;
    wall.start();
    const HybridTest::StepResult result = runLoop(*test, options, *record);
    RunInfo info;
    info.configName = cfg.name;
    info.configFile = cfg.sourcePath;
    info.wallTimeS = wall.nsecsElapsed() * 1e-9;

    int code = result == HybridTest::StepResult::Finished ? 0 : 1;
    if (result == HybridTest::StepResult::Held) {
        code = 2;
        err() << tr("hsmu run: test held at t = %1 s (step %2): %3")
                     .arg(num(test->time(), 6))
                     .arg(test->currentStep())
                     .arg(QString::fromStdString(holdReason(*test).value_or("held")))
              << Qt::endl;
    } else if (code != 0) {
        err() << tr("hsmu run: the test stopped unexpectedly (state %1)")
                     .arg(QString::fromLatin1(testStateName(test->state())))
              << Qt::endl;
    }
    if (csv)
        test->removeObserver(csv.get());
    test->removeObserver(record.get());
    if (!record->finish())
        code = fail(tr("%1: the record could not be written: %2")
                        .arg(QString::fromStdString(record->path()),
                             QString::fromStdString(record->error())));
    if (csv && !csv->finish())
        code = fail(tr("%1: write failed").arg(QString::fromStdString(csv->path())));
    try {
        writeSummaryJson(dir.filePath(QStringLiteral("summary.json")).toStdString(), *test, stats,
                         info);
    } catch (const std::exception& e) {
        code = fail(QString::fromStdString(e.what()));
    }
    if (options.plots) {
        QStringList errors;
        PlotExporter::writeRunPlots(dir.path(), layout, records.records(), &errors,
                                    PlotReferences::of(cfg));
        for (const QString& f : errors)
            code = fail(tr("%1: the plot could not be written").arg(f));
    }
    RunReport::print(ConsoleStreams::out(), *test, stats, info, dir.path());
    return code;
}

} // namespace hsmu::gui
