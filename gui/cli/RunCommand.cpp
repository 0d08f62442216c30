#include "gui/cli/RunCommand.h"

#include "gui/PresetLibrary.h"
#include "gui/cli/CliPlots.h"
#include "gui/cli/CliText.h"
#include "gui/cli/RecordCollector.h"
#include "gui/cli/RunFlow.h"
#include "gui/cli/RunOptions.h"

#include <QDir>

namespace hsmu::gui {

std::string RunCommand::translated(const char* context, const char* source) {
    return QCoreApplication::translate(context, source).toStdString();
}

int RunCommand::exec(const QStringList& arguments) {
    RunOptions options;
    if (auto error = RunOptions::parse(arguments, options))
        return error->isEmpty() ? 0 : RunFlow::fail(error->toStdString());
    setTranslator(&RunCommand::translated);

    RunRequest r;
    r.config = options.config.toStdString();
    r.outDir = options.outDir.toStdString();
    r.presets = PresetLibrary::catalog();
    r.configure = [&options](TestConfig& cfg) { options.overrides.applyTo(cfg); };
    r.controller = options.controller;
    r.token = options.token.toStdString();
    r.approval = options.approval.toStdString();
    r.csv = options.csv == QLatin1String("none")  ? HeadlessOptions::Csv::None
            : options.csv == QLatin1String("all") ? HeadlessOptions::Csv::All
                                                  : HeadlessOptions::Csv::Auto;
    r.reconnect = options.reconnect;
    r.deflate = options.deflate;
    if (options.recordDofs)
        r.recordDofs = options.recordDofs->toStdString();
    r.recordEvery = options.recordEvery;
    RecordCollector records;
    if (options.plots) {
        r.observe = [&records](TestSession& session) { session.addObserver(&records); };
        r.afterRun = [&options, &records](const RunLayout& layout, const TestConfig& cfg) {
            if (!CliPlots::installed().run)
                return RunFlow::fail(
                    tr("--plots: this program cannot draw (run it through hsmu)").toStdString());
            int code = 0;
            for (const QString& f : CliPlots::installed().run(QDir(options.outDir).path(), layout,
                                                              records.records(), cfg))
                code = RunFlow::fail(tr("%1: the plot could not be written").arg(f).toStdString());
            return code;
        };
    }
    return RunFlow::exec(r);
}

} // namespace hsmu::gui
