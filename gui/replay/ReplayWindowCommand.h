#pragma once
// ReplayWindowCommand: `hsmu replay FILE.h5 [--speed S] [--play] [--screenshot FILE
// [--screenshot-after SECONDS]]`: the ReplayWindow on a run record (docs/cli.md, "Replay").
//   --speed              test seconds per wall second (default 1)
//   --play               start playing at once (otherwise the initial state is shown, paused)
//   --screenshot         grab the window into FILE (PNG) after --screenshot-after seconds
//                        (default 3), then quit: exit 0 if the file was written, else 1
// A bad file: the reason on stderr and exit code 1 (no window).
// (`hsmu replay FILE --identify ...`, offline re-identification, is a headless command of
// gui/cli; Launcher sends only the plain form here.)
// Thread rules: main thread, with a QApplication.

#include <QCoreApplication>
#include <QStringList>

namespace hsmu::gui {

class ReplayWindowCommand {
    Q_DECLARE_TR_FUNCTIONS(ReplayWindowCommand)
public:
    /// arguments: the process arguments (program, "replay", FILE, ...). Runs the event loop;
    /// returns the exit code.
    static int exec(const QStringList& arguments);
};

} // namespace hsmu::gui
