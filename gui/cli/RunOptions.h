#pragma once
// RunOptions: the arguments of `hsmu run` (see RunCommand.h and docs/cli.md):
//   CONFIG --out DIR [--ground-motion FILE] [--scale S] [--dt DT] [--duration T]
//   [--allow-unstable] [--plots] [--controller builtin|tcp://|simapp://|generictcp://HOST:PORT]
//   [--token-file F] [--reconnect N] [--approval manual|approveAll|rejectAll]
//   [--csv auto|all|none] [--compress LEVEL] [--record-dofs LIST] [--record-every N]
// Thread rules: plain data; parse() on the main thread.

#include "comms/LinkAddress.h"
#include "gui/ConfigOverrides.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

#include <optional>

namespace hsmu::gui {

struct RunOptions {
    Q_DECLARE_TR_FUNCTIONS(RunOptions)
public:
    QString config; ///< file or preset name
    QString outDir;
    bool plots = false;
    ConfigOverrides overrides;
    comms::LinkAddress controller; ///< builtin (in-process virtual specimens) or a link
    QString token;                 ///< shared secret for the controller's hello
    int reconnect = 0;             ///< headless resumes after a link fault (per fault)
    QString approval;              ///< "" keeps the configuration's updating.approval
    /// steps.csv: "auto" (when a row has at most StepCsvWriter::kMaxColumns values), "all"
    /// or "none"; record.h5 always holds every column (hsmu export writes CSV from it).
    QString csv = QStringLiteral("auto");
    int deflate = 0; ///< the record's deflate level (RecordStart::deflate), 0: uncompressed
    /// --record-dofs: the numerical DOFs the record keeps (checked against the
    /// configuration by RunFlow); unset: the configuration's record.dofs.
    std::optional<QString> recordDofs;
    int recordEvery = 0; ///< --record-every N (>= 1); 0: the configuration's record.every

    /// Parse the process arguments (program, "run", ...). nullopt: options filled; an empty
    /// string: --help was printed; otherwise the message of what is wrong.
    static std::optional<QString> parse(const QStringList& arguments, RunOptions& options);
};

} // namespace hsmu::gui
