#pragma once
// RunCommand: `hsmu run CONFIG --out DIR [--ground-motion FILE] [--scale S] [--dt DT]
// [--duration T] [--allow-unstable] [--plots]`: a hybrid test headless, start to end.
//
// Progress on stderr (about every 5 %: percent, test time, steps/s); a short summary on stdout
// (steps, times, peak displacement per DOF, peak force per element, alarms). Outputs in DIR:
// summary.json, steps.csv and with --plots the PNGs of PlotExporter.
// Exit codes: 0 finished; 1 an error (bad configuration or record, the test cannot start,
// e.g. unstable); 2 the test went to a safe hold (limit or fault): the reason is printed and
// the outputs hold every committed step.
// Thread rules: main thread; --plots needs a QApplication (see Launcher).

#include <QCoreApplication>
#include <QStringList>

namespace hsmu::gui {

class RunCommand {
    Q_DECLARE_TR_FUNCTIONS(RunCommand)
public:
    /// arguments: the process arguments (program, "run", ...). Returns the exit code.
    static int exec(const QStringList& arguments);
};

} // namespace hsmu::gui
