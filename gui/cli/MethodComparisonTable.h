#pragma once
// MethodComparisonTable: the table `hsmu replay --method all` prints on stdout (docs/cli.md):
// one row per method (calibration, ukf, nelder-mead) with the final model's NRMSE over the
// whole history [%], the CPU time [s], the parameters on a bound, the rejected samples and the
// verdict (core/offline/MethodComparison.h), then the recommended method, the law's verdict
// and where the outputs are.
// Thread rules: pure functions, any thread.

#include "core/offline/MethodComparison.h"

#include <QCoreApplication>
#include <QString>

namespace hsmu::gui {

class MethodComparisonTable {
    Q_DECLARE_TR_FUNCTIONS(MethodComparisonTable)
public:
    /// The whole text, lines ending in '\n'.
    static QString format(const MethodComparison& c, const SpecimenHistory& history,
                          const QString& dir);
};

} // namespace hsmu::gui
