#pragma once
// RunCommand: `hsmu run CONFIG --out DIR [--ground-motion FILE] [--scale S] [--dt DT]
// [--duration T] [--allow-unstable] [--plots] [--controller builtin|tcp://HOST:PORT]
// [--token T] [--reconnect N] [--approval manual|approveAll|rejectAll]`: a hybrid test
// headless, start to end (options: RunOptions; reference: docs/cli.md).
//
// --controller tcp://HOST:PORT runs the specimens on an actuator controller over the link
// (comms::makeControlFactory; the timeouts of LinkTimeouts, core/config/LinkConfig.h, or the
// configuration's controller.connectTimeout / stepDeadline). The stepping, the record and the
// hold / reconnect policy are a TestSession's (core/session/TestSession.h), as in the console:
// --reconnect N lets it resume after a control fault (lost link, timeout), which reconnects,
// up to N times in a row with a doubling backoff (0.5 s, 1 s, 2 s ... 8 s; the count restarts
// once the test advances again), each attempt printed on stderr. --approval overrides the
// configuration's updating.approval.
//
// Progress on stderr (about every 5 %: percent, test time, steps/s); a short summary on stdout
// (RunReport). Outputs in DIR: summary.json (RunSummary), steps.csv (StepCsvWriter; with
// updating also the identified parameters, their std, the auxiliary force and the fit error)
// and with --plots the PNGs of PlotExporter.
// Exit codes: 0 finished; 1 an error (bad arguments, configuration, record or controller
// address, the test cannot start, e.g. unstable or no controller listening); 2 the test went
// to a safe hold (limit or fault, retries exhausted): the reason is printed and the outputs
// hold every committed step.
// The run itself is RunFlow's (Qt-free, shared with the Qt-free `hsmu`, gui/cli/FastRun.h);
// this adds Qt's option parser (--help, the errors), the embedded presets and --plots.
// Thread rules: main thread; --plots needs a QApplication (see Launcher).

#include <QCoreApplication>
#include <QStringList>

#include <string>

namespace hsmu::gui {

class RunCommand {
    Q_DECLARE_TR_FUNCTIONS(RunCommand)
public:
    /// arguments: the process arguments (program, "run", ...). Returns the exit code.
    static int exec(const QStringList& arguments);
    /// QCoreApplication::translate as CliText's translator (gui/cli/CliText.h).
    static std::string translated(const char* context, const char* source);
};

} // namespace hsmu::gui
