#include "gui/cli/CliLauncher.h"

#include "gui/app/ConsoleSettings.h"
#include "gui/app/Translations.h"
#include "gui/cli/CompareCommand.h"
#include "gui/cli/ExportCommand.h"
#include "gui/cli/FastRun.h"
#include "gui/cli/MaterialCommand.h"
#include "gui/cli/ReplayCommand.h"
#include "gui/cli/RthsCommand.h"
#include "gui/cli/RunCommand.h"

#include <QCoreApplication>
#include <QTextStream>

#include <cstring>
#include <initializer_list>
#include <string>

namespace hsmu::gui {

namespace {

/// Replace this process with hsmu-console (next to this executable), same arguments.
int execConsole(char** argv) {
    const auto [console, e] = FastRun::execSibling("hsmu-console", argv, "hsmu-console");
    QTextStream(stderr) << "hsmu: cannot start " << QString::fromStdString(console) << ": "
                        << QString::fromLocal8Bit(std::strerror(e))
                        << " (the console, the replay window and --plots are drawn by it)"
                        << Qt::endl;
    return 1;
}

} // namespace

bool CliLauncher::hasArgument(int argc, char** argv, std::initializer_list<const char*> names) {
    for (int i = 1; i < argc; ++i)
        for (const char* n : names)
            if (std::strcmp(argv[i], n) == 0)
                return true;
    return false;
}

int CliLauncher::guarded(const std::function<int()>& body) {
    return FastRun::guarded(body);
}

void CliLauncher::describeApplication() {
    QCoreApplication::setApplicationName(QStringLiteral("hsmu"));
    QCoreApplication::setOrganizationName(QStringLiteral("HSMU"));
    QCoreApplication::setApplicationVersion(QStringLiteral(HSMU_VERSION));
    Translations::install(*QCoreApplication::instance(),
                          ConsoleSettings::language()); // "" = the system locale
}

bool CliLauncher::headlessCommand(int argc, char** argv) {
    const std::string sub = argc > 1 ? argv[1] : "";
    if (sub == "run" || sub == "compare")
        return !hasArgument(argc, argv, {"--plots"});
    if (sub == "material" || sub == "export" || sub == "rths")
        return true;
    return sub == "replay" && hasArgument(argc, argv, {"--identify", "--import"});
}

int CliLauncher::runHeadless(const QStringList& arguments) {
    const QString sub = arguments.value(1);
    if (sub == QLatin1String("run"))
        return RunCommand::exec(arguments);
    if (sub == QLatin1String("compare"))
        return CompareCommand::exec(arguments);
    if (sub == QLatin1String("export"))
        return ExportCommand::exec(arguments);
    if (sub == QLatin1String("replay"))
        return ReplayCommand::exec(arguments); // --identify / --import
    if (sub == QLatin1String("rths"))
        return RthsCommand::exec(arguments);
    return MaterialCommand::exec(arguments);
}

int CliLauncher::main(int argc, char** argv) {
    return guarded([argc, argv] {
        if (!headlessCommand(argc, argv))
            return execConsole(argv);
        int count = argc; // QCoreApplication keeps a reference to it
        QCoreApplication app(count, argv); // no windowing system needed
        describeApplication();
        return runHeadless(app.arguments());
    });
}

} // namespace hsmu::gui
