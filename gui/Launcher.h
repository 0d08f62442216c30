#pragma once
// Launcher: the `hsmu-console` executable's entry point (the console, the replay window and
// every --plots command; the light `hsmu` runs headless commands itself and hands the rest
// here, gui/cli/CliLauncher.h). The first argument selects what runs:
//   hsmu run CONFIG ...       RunCommand (a QCoreApplication; with --plots a QApplication,
//                             on the "offscreen" platform when no display is set)
//   hsmu compare CONFIG ...   CompareCommand (like run: --plots needs a QApplication)
//   hsmu material ...         MaterialCommand (QCoreApplication)
//   hsmu replay FILE.h5 ...   ReplayWindowCommand (the replay window; needs a display
//                             except with --screenshot / --help)
//   hsmu [options]            ConsoleCommand (the window; without a display only --help,
//                             --version and --screenshot, rendered offscreen, are possible)
// Anything else is an unknown subcommand: a message and exit code 1.
// Thread rules: main thread, once per process.

namespace hsmu::gui {

class Launcher {
public:
    static int main(int argc, char** argv);
};

} // namespace hsmu::gui
