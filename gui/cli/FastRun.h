#pragma once
// FastRun: the `hsmu` executable's entry, without Qt (issue 27: a headless `hsmu run` maps
// no Qt Core, ICU or glib; docs/benchmarks.md, "The strong SDOF without Qt"). It runs
// `hsmu run` itself (RunFlow, the same code as the Qt front end) when every part of the
// command line is one it reads exactly as RunOptions would and the output is English:
//   hsmu run FILE --out DIR [--scale S] [--dt DT] [--duration T] [--record-dt DT]
//            [--allow-unstable] [--csv auto|all|none] [--compress LEVEL] [--reconnect N]
//            [--record-dofs LIST] [--record-every N]
// (FILE an existing file, each option once, "--name value" or "--name=value", numbers in
// their plain form), no language setting or locale other than English (the settings files
// of QSettings for HSMU/hsmu and LANGUAGE, LC_ALL, LC_MESSAGES, LANG: C, POSIX or en*) and
// no HSMU_CONTROLLER_TOKEN. Anything else (a preset name, --ground-motion, --controller,
// --plots, --help, an error to report, another subcommand, the console) goes, with the same
// arguments, to `hsmu-cli` next to this executable (gui/cli/CliLauncher.h, Qt Core), which
// hands the console to `hsmu-console`.
// Thread rules: main thread, once per process.

#include "gui/cli/RunFlow.h"

#include <functional>
#include <optional>

namespace hsmu::gui {

class FastRun {
public:
    static int main(int argc, char** argv);
    /// The run request of this command line if this process runs it (see above).
    static std::optional<RunRequest> request(int argc, char** argv);
    /// Whether the settings and the locale leave every message in English (see above).
    static bool englishOnly();
    /// body()'s exit code; an exception escaping it is the last line of defence: a message on
    /// stderr ("hsmu: internal error: ...") and exit code 1, never an abort (every executable).
    static int guarded(const std::function<int()>& body);
    /// Replace this process with the executable `name` next to it (/proc/self/exe, else
    /// argv[0]'s folder), argv[0] set to argv0 (nullptr: unchanged); on failure its path and
    /// errno are returned.
    static std::pair<std::string, int> execSibling(const char* name, char** argv,
                                                   const char* argv0);
};

} // namespace hsmu::gui
