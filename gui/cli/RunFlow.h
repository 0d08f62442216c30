#pragma once
// RunFlow: `hsmu run` once its arguments are read, without Qt (docs/cli.md "hsmu run"): the
// configuration (the CONFIG rule of core/config/PresetCatalog.h, then the command line's
// overrides), the test and its controller, the output folder, the HeadlessRun (steps.csv, the
// record, summary.json), SIGINT / SIGTERM as a hold (SignalHold), progress on stderr about
// every 5 % (percent, test time, steps/s), the exit code and the summary on stdout
// (RunReport). One code path for both front ends: RunCommand (Qt Core: the option parser,
// the embedded presets, --plots) and the Qt-free `hsmu` executable (FastRun), so both print
// the same bytes; messages are translated through CliText in the context "RunCommand".
// Exit codes: 0 finished; 1 an error; 2 the test went to a safe hold (RunCommand.h).
// Thread rules: main thread, once per process.

#include "comms/LinkAddress.h"
#include "core/config/PresetCatalog.h"
#include "core/session/HeadlessRun.h"

#include <functional>
#include <optional>
#include <string>

namespace hsmu::gui {

struct RunRequest {
    std::string config; ///< CONFIG: a file or a preset name
    std::string outDir; ///< --out as given
    PresetCatalog presets;
    /// The command line's overrides of the configuration (ConfigOverrides).
    std::function<void(TestConfig&)> configure;
    comms::LinkAddress controller; ///< builtin or a link
    std::string token;             ///< the controller's shared secret
    std::string approval;          ///< "" keeps the configuration's updating.approval
    HeadlessOptions::Csv csv = HeadlessOptions::Csv::Auto;
    int reconnect = 0;
    int deflate = 0;
    /// --record-dofs LIST (over the configuration's record.dofs) and --record-every N (> 0;
    /// 0: the configuration's record.every): core/config/RecordConfig.h.
    std::optional<std::string> recordDofs;
    int recordEvery = 0;
    /// Optional: called once the session exists, before the test starts (observers).
    std::function<void(TestSession&)> observe;
    /// Optional: after the outputs are closed, before the summary; returns 1 if it failed
    /// (and printed why through fail()), else 0 (--plots).
    std::function<int(const RunLayout&, const TestConfig&)> afterRun;
};

class RunFlow {
public:
    /// The run of r; the exit code.
    static int exec(const RunRequest& r);
    /// "hsmu run: MESSAGE" on stderr; returns 1.
    static int fail(const std::string& message);
    /// QDir(outDir).path(): the folder as printed in the summary.
    static std::string printedDir(const std::string& outDir);
};

} // namespace hsmu::gui
