#include "gui/cli/CompareCommand.h"

#include "core/session/ComparisonSummary.h"
#include "core/session/ComparisonProtocol.h"
#include "core/experiment/HybridTest.h"
#include "gui/PresetLibrary.h"
#include "gui/cli/ComparisonTable.h"
#include "gui/cli/CliPlots.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/cli/OverrideOptions.h"

#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QTextStream>

#include <algorithm>
#include <optional>

namespace hsmu::gui {

namespace {

QTextStream& err() {
    return ConsoleStreams::err();
}

int fail(const QString& message) {
    err() << "hsmu compare: " << message << Qt::endl;
    return 1;
}

struct CompareOptions {
    QString config;
    QString outDir;
    bool plots = false;
    ConfigOverrides overrides;
    ComparisonOptions comparison;
};

/// Parse the arguments; nullopt with `options` filled, an empty string after --help, or
/// the message of what is wrong.
std::optional<QString> parse(const QStringList& arguments, CompareOptions& options) {
    QCommandLineParser p;
    p.setApplicationDescription(
        CompareCommand::tr("Run the paper's comparison protocol (reference, initial, updated)."));
    p.addHelpOption();
    p.addPositionalArgument(QStringLiteral("compare"), CompareCommand::tr("The subcommand."));
    p.addPositionalArgument(QStringLiteral("config"),
                            CompareCommand::tr("Configuration file or preset name."));
    const QCommandLineOption outOpt(QStringLiteral("out"), CompareCommand::tr("Output directory."),
                                    QStringLiteral("dir"));
    const OverrideOptions overrides;
    const QCommandLineOption plotsOpt(QStringLiteral("plots"),
                                      CompareCommand::tr("Write PNG plots."));
    const QCommandLineOption elementOpt(
        QStringLiteral("element"),
        CompareCommand::tr("Compared numerical element (default: the first updating target)."),
        QStringLiteral("name"));
    const QCommandLineOption dofOpt(
        QStringLiteral("dof"), CompareCommand::tr("Compared DOF (default: the element's DOF)."),
        QStringLiteral("name"));
    p.addOption(outOpt);
    overrides.addTo(p);
    p.addOptions({plotsOpt, elementOpt, dofOpt});
    if (auto parsed = ConsoleStreams::parse(p, arguments))
        return parsed;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2)
        return CompareCommand::tr("expected exactly one CONFIG (a file or a preset name)");
    options.config = pos[1];
    options.outDir = p.value(outOpt);
    if (options.outDir.isEmpty())
        return CompareCommand::tr("missing --out DIR");
    options.plots = p.isSet(plotsOpt);
    options.comparison.element = p.value(elementOpt).toStdString();
    options.comparison.dof = p.value(dofOpt).toStdString();
    return overrides.read(p, options.overrides);
}

/// Progress on stderr: each run's start and about every 10 % of it.
class Progress {
public:
    void operator()(int run, double fraction) {
        static const char* const names[] = {"reference", "initial", "updated"};
        const int percent = int(100.0 * fraction);
        if (run != m_run) {
            m_run = run;
            m_next = 10;
        }
        if (percent < m_next)
            return;
        m_next = (percent / 10 + 1) * 10;
        const double seconds = std::max(1e-9, m_wall.nsecsElapsed() * 1e-9);
        err() << CompareCommand::tr("%1 run %2/3: %3 %  (%4 s)")
                     .arg(QLatin1String(names[std::clamp(run, 0, 2)]))
                     .arg(run + 1)
                     .arg(percent, 3)
                     .arg(QString::number(seconds, 'f', 2))
              << Qt::endl;
    }
    void start() { m_wall.start(); }

private:
    QElapsedTimer m_wall;
    int m_run = -1;
    int m_next = 10;
};

} // namespace

int CompareCommand::exec(const QStringList& arguments) {
    CompareOptions options;
    if (auto error = parse(arguments, options))
        return error->isEmpty() ? 0 : fail(*error);

    TestConfig cfg;
    try {
        cfg = PresetLibrary::load(options.config);
        options.overrides.applyTo(cfg);
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }
    if (!cfg.updating.enabled)
        return fail(tr("%1: the configuration has no online model updating (an enabled "
                       "\"updating\" section); compare needs one to run the updated test")
                        .arg(QString::fromStdString(cfg.sourcePath)));
    if (!QDir().mkpath(options.outDir))
        return fail(tr("%1: cannot create the output directory").arg(options.outDir));
    const QDir dir(options.outDir);

    ComparisonResult result;
    options.comparison.recordDir = dir.absolutePath().toStdString(); // one record per run
    Progress progress;
    progress.start();
    err() << tr("hsmu compare: three runs (reference, initial, updated) of %1")
                 .arg(QString::fromStdString(cfg.name))
          << Qt::endl;
    try {
        result = runComparison(cfg, options.comparison,
                               [&progress](int run, double f) { progress(run, f); });
    } catch (const std::exception& e) {
        return fail(QString::fromStdString(e.what()));
    }

    int code = 0;
    for (const ComparisonRun* run : {&result.reference, &result.initial, &result.updated}) {
        err() << tr("%1: %2 steps, %3")
                     .arg(QString::fromStdString(run->name))
                     .arg(run->steps)
                     .arg(QString::fromStdString(run->finalState))
              << Qt::endl;
        if (run->finalState == "finished")
            continue;
        code = 2;
        err() << tr("hsmu compare: the %1 run stopped at step %2 (state %3)%4")
                     .arg(QString::fromStdString(run->name))
                     .arg(run->steps)
                     .arg(QString::fromStdString(run->finalState),
                          run->alarms.empty()
                              ? QString()
                              : QStringLiteral(": ") + QString::fromStdString(run->alarms.back()))
              << Qt::endl;
    }
    for (const ComparisonRun* run : {&result.reference, &result.initial, &result.updated})
        if (!run->recordError.empty())
            code = fail(QString::fromStdString(run->recordError));
    const ParameterValues truth = trueParameters(cfg, result.updated.parameterNames);
    try {
        writeComparisonJson(dir.filePath(QStringLiteral("compare.json")).toStdString(), result,
                            cfg);
    } catch (const std::exception& e) {
        code = fail(QString::fromStdString(e.what()));
    }
    if (options.plots) {
        if (!CliPlots::installed().compare)
            code = fail(tr("--plots: this program cannot draw (run it through hsmu)"));
        else
            for (const QString& f : CliPlots::installed().compare(dir.path(), result, truth))
                code = fail(tr("%1: the plot could not be written").arg(f));
    }
    ConsoleStreams::out() << ComparisonTable::format(result, truth)
                          << tr("  outputs: %1").arg(QDir::toNativeSeparators(dir.path()))
                          << Qt::endl;
    return code;
}

} // namespace hsmu::gui
