#include "gui/cli/CompareCommand.h"

#include "core/output/ComparisonSummary.h"
#include "core/output/RunLayout.h"
#include "core/record/RecordWriter.h"
#include "core/experiment/ComparisonProtocol.h"
#include "core/experiment/HybridTest.h"
#include "gui/PresetLibrary.h"
#include "gui/cli/ComparisonTable.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/cli/OverrideOptions.h"
#include "gui/plots/ComparisonPlotExporter.h"

#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QTextStream>

#include <algorithm>
#include <array>
#include <memory>
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

/// One HDF5 record per run: DIR/reference/record.h5, DIR/initial/record.h5,
/// DIR/updated/record.h5 (docs/recording.md; root attribute "run" names the run).
class CompareRecords {
public:
    explicit CompareRecords(const QDir& dir) : m_dir(dir) {}

    ComparisonHooks hooks() {
        ComparisonHooks h;
        h.started = [this](int run, const TestConfig& cfg, HybridTest& test) {
            start(run, cfg, test);
        };
        h.finished = [this](int run, HybridTest& test) { finish(run, test); };
        return h;
    }
    /// Why a record failed, one entry per failure.
    const QStringList& errors() const { return m_errors; }

private:
    static constexpr const char* kRuns[] = {"reference", "initial", "updated"};

    void start(int run, const TestConfig& cfg, HybridTest& test) {
        const QString sub = QLatin1String(kRuns[run]);
        if (!m_dir.mkpath(sub))
            throw std::runtime_error(m_dir.filePath(sub).toStdString() +
                                     ": cannot create the output directory");
        const std::string path = m_dir.filePath(sub + QStringLiteral("/record.h5")).toStdString();
        RecordStart start{cfg.raw.dump(), cfg.name, {}, cfg.analysis.dt, kRuns[run]};
        m_writers[std::size_t(run)] =
            std::make_unique<RecordWriter>(path, RunLayout::of(test), start);
        test.addObserver(m_writers[std::size_t(run)].get());
    }

    void finish(int run, HybridTest& test) {
        RecordWriter& w = *m_writers[std::size_t(run)];
        test.removeObserver(&w);
        w.writeAlarms(test.alarms());
        if (!w.finish())
            m_errors << QString::fromStdString(w.path() +
                                               ": the record could not be written: " + w.error());
    }

    QDir m_dir;
    std::array<std::unique_ptr<RecordWriter>, 3> m_writers;
    QStringList m_errors;
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
    CompareRecords records(dir);
    Progress progress;
    progress.start();
    err() << tr("hsmu compare: three runs (reference, initial, updated) of %1")
                 .arg(QString::fromStdString(cfg.name))
          << Qt::endl;
    try {
        result = runComparison(
            cfg, options.comparison, [&progress](int run, double f) { progress(run, f); },
            records.hooks());
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
    for (const QString& e : records.errors())
        code = fail(e);
    const ParameterValues truth = trueParameters(cfg, result.updated.parameterNames);
    try {
        writeComparisonJson(dir.filePath(QStringLiteral("compare.json")).toStdString(), result,
                            cfg);
    } catch (const std::exception& e) {
        code = fail(QString::fromStdString(e.what()));
    }
    if (options.plots) {
        QStringList errors;
        ComparisonPlotExporter::write(dir.path(), result, truth, &errors);
        for (const QString& f : errors)
            code = fail(tr("%1: the plot could not be written").arg(f));
    }
    ConsoleStreams::out() << ComparisonTable::format(result, truth)
                          << tr("  outputs: %1").arg(QDir::toNativeSeparators(dir.path()))
                          << Qt::endl;
    return code;
}

} // namespace hsmu::gui
