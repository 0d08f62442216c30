#include "gui/cli/RunCommand.h"

#include "core/config/TestFactory.h"
#include "core/output/RunStatistics.h"
#include "core/output/RunSummary.h"
#include "core/output/StepCsvWriter.h"
#include "core/test/HybridTest.h"
#include "gui/ConfigOverrides.h"
#include "gui/PresetLibrary.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/cli/RecordCollector.h"
#include "gui/plots/PlotExporter.h"

#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QTextStream>

#include <cmath>
#include <memory>
#include <optional>

namespace hsmu::gui {

namespace {

QTextStream& out() {
    return ConsoleStreams::out();
}
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

struct RunOptions {
    QString config;
    QString outDir;
    bool plots = false;
    ConfigOverrides overrides;
};

/// Parse the arguments; returns an error message, or nothing with `options` filled.
std::optional<QString> parse(const QStringList& arguments, RunOptions& options) {
    QCommandLineParser p;
    p.setApplicationDescription(RunCommand::tr("Run a hybrid test headless."));
    p.addHelpOption();
    p.addPositionalArgument(QStringLiteral("run"), RunCommand::tr("The subcommand."));
    p.addPositionalArgument(QStringLiteral("config"),
                            RunCommand::tr("Configuration file or preset name."));
    const QCommandLineOption outOpt(QStringLiteral("out"), RunCommand::tr("Output directory."),
                                    QStringLiteral("dir"));
    const QCommandLineOption gmOpt(QStringLiteral("ground-motion"),
                                   RunCommand::tr("Ground-motion record file."),
                                   QStringLiteral("file"));
    const QCommandLineOption scaleOpt(QStringLiteral("scale"),
                                      RunCommand::tr("Ground-motion scale factor."),
                                      QStringLiteral("s"));
    const QCommandLineOption dtOpt(QStringLiteral("dt"), RunCommand::tr("Integration step [s]."),
                                   QStringLiteral("dt"));
    const QCommandLineOption durOpt(QStringLiteral("duration"),
                                    RunCommand::tr("Test duration [s]."), QStringLiteral("t"));
    const QCommandLineOption unstableOpt(
        QStringLiteral("allow-unstable"),
        RunCommand::tr("Run an explicit scheme past its stability limit."));
    const QCommandLineOption plotsOpt(QStringLiteral("plots"), RunCommand::tr("Write PNG plots."));
    p.addOptions({outOpt, gmOpt, scaleOpt, dtOpt, durOpt, unstableOpt, plotsOpt});
    if (!p.parse(arguments))
        return p.errorText();
    if (p.isSet(QStringLiteral("help"))) {
        out() << p.helpText();
        return QString();
    }
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2)
        return RunCommand::tr("expected exactly one CONFIG (a file or a preset name)");
    options.config = pos[1];
    options.outDir = p.value(outOpt);
    if (options.outDir.isEmpty())
        return RunCommand::tr("missing --out DIR");
    options.plots = p.isSet(plotsOpt);
    options.overrides.groundMotionFile = p.value(gmOpt);
    options.overrides.allowUnstable = p.isSet(unstableOpt);
    auto number = [&](const QCommandLineOption& o, std::optional<double>& target,
                      bool positive) -> std::optional<QString> {
        if (!p.isSet(o))
            return std::nullopt;
        bool ok = false;
        const double v = p.value(o).toDouble(&ok);
        if (!ok || !std::isfinite(v) || (positive && v <= 0.0))
            return RunCommand::tr("--%1: expected a %2 number, found '%3'")
                .arg(o.names().front(), positive ? RunCommand::tr("positive") : QString(),
                     p.value(o))
                .simplified();
        target = v;
        return std::nullopt;
    };
    if (auto e = number(scaleOpt, options.overrides.scale, false))
        return e;
    if (auto e = number(dtOpt, options.overrides.dt, true))
        return e;
    if (auto e = number(durOpt, options.overrides.duration, true))
        return e;
    return std::nullopt;
}

void printSummary(const HybridTest& test, const RunStatistics& stats, const RunInfo& info,
                  const QString& outDir) {
    const RunLayout& layout = stats.layout();
    out() << RunCommand::tr("Test: %1").arg(QString::fromStdString(info.configName)) << '\n';
    out() << RunCommand::tr("  state: %1, steps: %2 of %3, test time: %4 s, wall time: %5 s")
                 .arg(QString::fromLatin1(testStateName(test.state())))
                 .arg(test.currentStep())
                 .arg(test.totalSteps())
                 .arg(num(test.time(), 6), num(info.wallTimeS, 3))
          << '\n';
    out() << RunCommand::tr("  peak displacement:") << '\n';
    for (std::size_t i = 0; i < layout.dofNames.size(); ++i)
        out() << "    " << QString::fromStdString(layout.dofNames[i]) << ": "
              << num(stats.peakDisplacement()[i]) << " m\n";
    out() << RunCommand::tr("  peak force:") << '\n';
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        out() << "    " << QString::fromStdString(layout.elements[i].name) << ": "
              << num(stats.peakForce()[i]) << ' '
              << QString::fromStdString(layout.elements[i].units.force) << '\n';
    if (test.alarms().empty())
        out() << RunCommand::tr("  alarms: none") << '\n';
    else
        out() << RunCommand::tr("  alarms:") << '\n';
    for (const Alarm& a : test.alarms())
        out() << "    t = " << num(a.time, 6) << " s (step " << a.step << ") "
              << alarmSeverityName(a.severity) << ", " << alarmKindName(a.kind) << ": "
              << QString::fromStdString(a.message) << '\n';
    out() << RunCommand::tr("  outputs: %1").arg(QDir::toNativeSeparators(outDir)) << Qt::endl;
}

} // namespace

int RunCommand::exec(const QStringList& arguments) {
    RunOptions options;
    if (auto error = parse(arguments, options))
        return error->isEmpty() ? 0 : fail(*error);

    TestConfig cfg;
    std::unique_ptr<HybridTest> test;
    try {
        cfg = PresetLibrary::load(options.config);
        options.overrides.applyTo(cfg);
        test = buildHybridTest(cfg);
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    if (!QDir().mkpath(options.outDir))
        return fail(tr("%1: cannot create the output directory").arg(options.outDir));
    const QDir dir(options.outDir);

    const RunLayout layout = RunLayout::of(test->structure());
    std::unique_ptr<StepCsvWriter> csv;
    try {
        csv = std::make_unique<StepCsvWriter>(
            dir.filePath(QStringLiteral("steps.csv")).toStdString(), layout);
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    RunStatistics stats(layout);
    RecordCollector records;
    test->addObserver(csv.get());
    test->addObserver(&stats);
    if (options.plots)
        test->addObserver(&records);

    if (!test->prepare())
        return fail(tr("the test cannot start: %1").arg(QString::fromStdString(test->lastError())));

    QElapsedTimer wall;
    wall.start();
    const int total = std::max(1, test->totalSteps());
    int nextPercent = 5;
    HybridTest::StepResult result = HybridTest::StepResult::Advanced;
    while (result == HybridTest::StepResult::Advanced) {
        result = test->step();
        const int percent = int(100.0 * test->currentStep() / total);
        if (percent >= nextPercent || result == HybridTest::StepResult::Finished) {
            const double seconds = std::max(1e-9, wall.nsecsElapsed() * 1e-9);
            err() << tr("%1 %  t = %2 s  %3 steps/s")
                         .arg(percent, 3)
                         .arg(QString::number(test->time(), 'f', 2))
                         .arg(QString::number(test->currentStep() / seconds, 'f', 0))
                  << Qt::endl;
            nextPercent = (percent / 5 + 1) * 5;
        }
    }
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
    test->removeObserver(csv.get());
    if (!csv->finish())
        code = fail(tr("%1: write failed").arg(QString::fromStdString(csv->path())));
    try {
        writeSummaryJson(dir.filePath(QStringLiteral("summary.json")).toStdString(), *test, stats,
                         info);
    } catch (const std::exception& e) {
        code = fail(QString::fromStdString(e.what()));
    }
    if (options.plots) {
        QStringList errors;
        PlotExporter::writeRunPlots(dir.path(), layout, records.records(), &errors);
        for (const QString& f : errors)
            code = fail(tr("%1: the plot could not be written").arg(f));
    }
    printSummary(*test, stats, info, dir.path());
    return code;
}

} // namespace hsmu::gui
