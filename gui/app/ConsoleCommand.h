#pragma once
// ConsoleCommand: `hsmu [--start CONFIG] [--ground-motion FILE [--record-dt DT]] [--speed S]
// [--controller builtin|tcp://HOST:PORT] [--screenshot FILE [--screenshot-after SECONDS]]`:
// the console window.
//   --controller         where the specimens run: the built-in virtual lab or a controller
//                        over the native TCP link (e.g. hsmu-controller)
//   --start              load a preset name or configuration file and start it at once
//                        (the command line is the operator's confirmation: no pre-flight)
//   --ground-motion      use this record for every configuration loaded
//   --record-dt          the record's own sample step [s] (a one-column file needs it)
//   --speed              test time per wall time (1 = real time, 0 = as fast as possible)
//   --screenshot         grab the window into FILE (PNG) after --screenshot-after seconds
//                        (default 4), then quit: exit 0 if the file was written, else 1
// Thread rules: main thread, with a QApplication.

#include <QCoreApplication>
#include <QStringList>

namespace hsmu::gui {

class ConsoleCommand {
    Q_DECLARE_TR_FUNCTIONS(ConsoleCommand)
public:
    /// Runs the event loop; returns the exit code.
    static int exec(const QStringList& arguments);
};

} // namespace hsmu::gui
