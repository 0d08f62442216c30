#include "gui/Launcher.h"

#include "gui/app/ConsoleCommand.h"
#include "gui/cli/CliLauncher.h"
#include "gui/cli/CliPlots.h"
#include "gui/plots/ComparisonPlotExporter.h"
#include "gui/plots/PlotExporter.h"
#include "gui/plots/PlotReferences.h"
#include "gui/replay/ReplayWindowCommand.h"

#include <QApplication>
#include <QTextStream>


namespace hsmu::gui {

namespace {

/// --plots of `hsmu run` / `hsmu compare` draw with the console's plots (gui/cli/CliPlots.h).
void installPlots() {
    CliPlots& plots = CliPlots::installed();
    plots.run = [](const QString& dir, const RunLayout& layout,
                   const std::vector<StepRecord>& records, const TestConfig& cfg) {
        QStringList errors;
        PlotExporter::writeRunPlots(dir, layout, records, &errors, PlotReferences::of(cfg));
        return errors;
    };
    plots.compare = [](const QString& dir, const ComparisonResult& result,
                       const ParameterValues& truth) {
        QStringList errors;
        ComparisonPlotExporter::write(dir, result, truth, &errors);
        return errors;
    };
}

/// Headless commands print only their own messages (through ConsoleStreams): Qt's notes about
/// the environment (QStandardPaths' "XDG_RUNTIME_DIR not set", the offscreen platform's
/// "does not support propagateSizeHints()") are not the command's, and the console's code
/// uses no qDebug / qWarning. Critical and fatal messages still reach stderr.
void onlyCriticalQtMessages(QtMsgType type, const QMessageLogContext& context,
                            const QString& text) {
    if (type == QtDebugMsg || type == QtInfoMsg || type == QtWarningMsg)
        return;
    QTextStream(stderr) << qFormatLogMessage(type, context, text) << Qt::endl;
}

bool headless() {
    return qEnvironmentVariableIsEmpty("DISPLAY") &&
           qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") &&
           qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
}

int dispatch(int argc, char** argv) {
    const QString sub = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QString();
    const bool plotting = sub == QLatin1String("run") || sub == QLatin1String("compare");
    // `hsmu replay FILE` opens the replay window; --identify / --import are headless (gui/cli).
    const bool replayWindow =
        sub == QLatin1String("replay") && !CliLauncher::hasArgument(argc, argv, {"--identify", "--import"});
    if (CliLauncher::headlessCommand(argc, argv)) {
        QCoreApplication app(argc, argv); // no windowing system needed
        CliLauncher::describeApplication();
        return CliLauncher::runHeadless(app.arguments());
    }
    if (!plotting && !replayWindow && !sub.isEmpty() && !sub.startsWith(QLatin1Char('-'))) {
        QTextStream(stderr) << "hsmu: unknown subcommand '" << sub
                            << "' (available: run, compare, replay, export, material; "
                               "without one the console opens)"
                            << Qt::endl;
        return 1;
    }
    if (headless()) {
        // Plots and window grabs render offscreen; an interactive window needs a display.
        const bool offscreenOk =
            plotting ||
            CliLauncher::hasArgument(argc, argv, {"--screenshot", "-h", "--help", "-v", "--version"});
        if (!offscreenOk && replayWindow) {
            QTextStream(stderr) << "hsmu replay: no display (DISPLAY / WAYLAND_DISPLAY are not "
                                   "set); the replay window needs one"
                                << Qt::endl;
            return 1;
        }
        if (!offscreenOk) {
            QTextStream(stderr) << "hsmu: no display (DISPLAY / WAYLAND_DISPLAY are not set); "
                                   "use `hsmu run CONFIG --out DIR` to run a test headless"
                                << Qt::endl;
            return 1;
        }
        qputenv("QT_QPA_PLATFORM", "offscreen"); // before the QApplication exists
    }
    if (plotting)
        qInstallMessageHandler(onlyCriticalQtMessages); // before Qt looks at the environment
    QApplication app(argc, argv);
    CliLauncher::describeApplication();
    installPlots();
    if (plotting)
        return CliLauncher::runHeadless(app.arguments());
    if (replayWindow)
        return ReplayWindowCommand::exec(app.arguments());
    return ConsoleCommand::exec(app.arguments());
}

} // namespace

int Launcher::main(int argc, char** argv) {
    return CliLauncher::guarded([argc, argv] { return dispatch(argc, argv); });
}

} // namespace hsmu::gui
