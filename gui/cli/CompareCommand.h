#pragma once
// CompareCommand: `hsmu compare CONFIG --out DIR [--ground-motion FILE] [--scale S] [--dt DT]
// [--duration T] [--plots] [--element NAME] [--dof NAME]`: the paper's protocol (reference,
// initial, updated; core's runComparison, ComparisonProtocol.h) for one configuration with
// online model updating.
//
// --element: the compared numerical element (default: the first updating target);
// --dof: the compared DOF (default: that element's DOF).
// Progress on stderr (each run, about every 10 %); on stdout the table of ComparisonTable.
// Outputs in DIR: compare.json (ComparisonSummary), one HDF5 record per run
// (reference/record.h5, initial/record.h5, updated/record.h5; docs/recording.md, root
// attribute "run") and with --plots the PNGs of ComparisonPlotExporter (the paper's
// Figures 10, 12, 13, 14).
// Exit codes: 0 all three runs finished; 1 an error (bad arguments, configuration, record, a
// configuration without updating, an element that cannot be compared, a file that cannot be
// written); 2 a run went to a safe hold: the outputs are written, the metrics cover the steps
// common to the runs.
// Thread rules: main thread; --plots needs a QApplication (see Launcher).

#include <QCoreApplication>
#include <QStringList>

namespace hsmu::gui {

class CompareCommand {
    Q_DECLARE_TR_FUNCTIONS(CompareCommand)
public:
    /// arguments: the process arguments (program, "compare", ...). Returns the exit code.
    static int exec(const QStringList& arguments);
};

} // namespace hsmu::gui
