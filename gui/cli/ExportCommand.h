#pragma once
// ExportCommand: `hsmu export FILE.h5 --csv DIR`: a run record (docs/recording.md) as CSV
// files, one per dataset group, units in the header (core's exportRecordCsv,
// RecordCsvExport.h; docs/cli.md). Prints the files written on stdout.
// Exit codes: 0 written; 1 an error (bad arguments, a file that is not a readable record,
// a directory or file that cannot be written), with the reason on stderr.
// Thread rules: main thread.

#include <QCoreApplication>
#include <QStringList>

namespace hsmu::gui {

class ExportCommand {
    Q_DECLARE_TR_FUNCTIONS(ExportCommand)
public:
    /// arguments: the process arguments (program, "export", ...). Returns the exit code.
    static int exec(const QStringList& arguments);
};

} // namespace hsmu::gui
