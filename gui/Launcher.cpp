#include "gui/Launcher.h"

#include "gui/app/ConsoleCommand.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/Translations.h"
#include "gui/cli/CompareCommand.h"
#include "gui/cli/ConsoleStreams.h"
#include "gui/cli/ExportCommand.h"
#include "gui/cli/MaterialCommand.h"
#include "gui/cli/ReplayCommand.h"
#include "gui/cli/RunCommand.h"
#include "gui/replay/ReplayWindowCommand.h"

#include <QApplication>
#include <QTextStream>

#include <cstring>
#include <exception>
#include <initializer_list>

namespace hsmu::gui {

namespace {

void describeApplication() {
    QCoreApplication::setApplicationName(QStringLiteral("hsmu"));
    QCoreApplication::setOrganizationName(QStringLiteral("HSMU"));
    QCoreApplication::setApplicationVersion(QStringLiteral(HSMU_VERSION));
}

void installTranslator(QCoreApplication& app) {
    Translations::install(app, ConsoleSettings::language()); // "" = the system locale
}

bool headless() {
    return qEnvironmentVariableIsEmpty("DISPLAY") &&
           qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY") &&
           qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM");
}

bool hasArgument(int argc, char** argv, std::initializer_list<const char*> names) {
    for (int i = 1; i < argc; ++i)
        for (const char* n : names)
            if (std::strcmp(argv[i], n) == 0)
                return true;
    return false;
}

/// A headless subcommand that draws nothing unless --plots is given.
int runHeadless(const QString& sub, const QStringList& arguments) {
    if (sub == QLatin1String("run"))
        return RunCommand::exec(arguments);
    if (sub == QLatin1String("compare"))
        return CompareCommand::exec(arguments);
    if (sub == QLatin1String("export"))
        return ExportCommand::exec(arguments);
    if (sub == QLatin1String("replay"))
        return ReplayCommand::exec(arguments); // --identify / --import
    return MaterialCommand::exec(arguments);
}

int dispatch(int argc, char** argv) {
    const QString sub = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QString();
    const bool plotting = sub == QLatin1String("run") || sub == QLatin1String("compare");
    const bool plots = plotting && hasArgument(argc, argv, {"--plots"});
    // `hsmu replay FILE` opens the replay window; --identify / --import are headless (gui/cli).
    const bool replayWindow =
        sub == QLatin1String("replay") && !hasArgument(argc, argv, {"--identify", "--import"});
    const bool dataOnly = sub == QLatin1String("material") || sub == QLatin1String("export") ||
                          (sub == QLatin1String("replay") && !replayWindow);
    if (dataOnly || (plotting && !plots)) {
        QCoreApplication app(argc, argv); // no windowing system needed
        describeApplication();
        installTranslator(app);
        return runHeadless(sub, app.arguments());
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
            hasArgument(argc, argv, {"--screenshot", "-h", "--help", "-v", "--version"});
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
    QApplication app(argc, argv);
    describeApplication();
    installTranslator(app);
    if (plotting)
        return runHeadless(sub, app.arguments());
    if (replayWindow)
        return ReplayWindowCommand::exec(app.arguments());
    return ConsoleCommand::exec(app.arguments());
}

} // namespace

int Launcher::main(int argc, char** argv) {
    try {
        return dispatch(argc, argv);
    } catch (const std::exception& e) { // last line of defence: a message, never an abort
        QTextStream(stderr) << "hsmu: internal error: " << e.what() << Qt::endl;
    } catch (...) {
        QTextStream(stderr) << "hsmu: internal error" << Qt::endl;
    }
    return 1;
}

} // namespace hsmu::gui
