#pragma once
// ReplayCommand: `hsmu replay FILE.h5 --identify [--method ukf|nelder-mead]
// [--config OVERRIDE.json] [--specimen NAME] --out DIR` and
// `hsmu replay --import DATA.csv [--units T,D,F] [--method ...] [--config SETTINGS.json]
// --out DIR`: offline re-identification of a recorded specimen, or of measured data from an
// older test (core: OfflineIdentification.h, IdentificationSettings.h, MeasuredDataCsv.h;
// reference: docs/cli.md).
//
// Settings: a record's configuration (its updating section when it identified the specimen),
// or for an import the defaults (a boucWen model, the UKF); then --config (the override
// document of IdentificationSettings.h), then --method. dt of an import: its mean time step.
// Outputs in DIR: parameters.csv and summary.json (OfflineIdentificationReport.h); on stdout
// a table of the initial, final (and the run's own online) estimates and the fit errors.
// `hsmu replay FILE.h5` without --identify opens the replay viewer, which this build does
// not include: a clear error, exit code 1.
// Exit codes: 0 identified; 1 an error (bad arguments, an unreadable record or CSV with the
// line and what is wrong, settings the method cannot use, a file that cannot be written).
// Thread rules: main thread.

#include <QCoreApplication>
#include <QStringList>

namespace hsmu::gui {

class ReplayCommand {
    Q_DECLARE_TR_FUNCTIONS(ReplayCommand)
public:
    /// arguments: the process arguments (program, "replay", ...). Returns the exit code.
    static int exec(const QStringList& arguments);
};

} // namespace hsmu::gui
