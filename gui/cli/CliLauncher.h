#pragma once
// CliLauncher: the `hsmu-cli` executable, started by the Qt-free `hsmu` (gui/cli/FastRun.h)
// for every command line it does not run itself; Qt Core only (no Widgets, no QCustomPlot: a headless
// `hsmu run` stays small, docs/benchmarks.md "Memory"). The first argument selects what runs:
//   hsmu run | compare CONFIG ...     in this process, on a QCoreApplication
//   hsmu material | export ...       in this process
//   hsmu replay FILE --identify | --import ...   in this process
//   anything else (the console, the replay window, --plots, --help of the console) is
//   handed to the console executable `hsmu-console` next to this one (execv, same
//   arguments), which draws (gui/Launcher.h).
// Thread rules: main thread, once per process.

#include <QStringList>

#include <functional>
#include <initializer_list>

namespace hsmu::gui {

class CliLauncher {
public:
    static int main(int argc, char** argv);
    /// Whether this command line runs without any window or plot (see above).
    static bool headlessCommand(int argc, char** argv);
    /// Run a headless subcommand (arguments: program, subcommand, ...); exit code.
    static int runHeadless(const QStringList& arguments);
    /// Application name, organisation, version and the user's language (both executables).
    static void describeApplication();
    /// Whether any argument after the program is one of names (both executables).
    static bool hasArgument(int argc, char** argv, std::initializer_list<const char*> names);
    /// body()'s exit code; an exception escaping it is the last line of defence: a message
    /// on stderr ("hsmu: internal error: ...") and exit code 1, never an abort (both
    /// executables' main).
    static int guarded(const std::function<int()>& body);
};

} // namespace hsmu::gui
