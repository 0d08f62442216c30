#pragma once
// ComparisonPlotExporter: the PNGs of `hsmu compare --plots`, like the paper's figures
// (rendered offscreen; a QApplication must exist, the "offscreen" platform works):
//   parameters.png               Fig. 10: one small ParameterPlot per identified parameter
//                                (updated run's estimate, ± 2 sigma band, true value dashed)
//   hysteresis_<element>.png     Fig. 12: the compared element's loop, reference / initial /
//                                updated overlaid
//   force_<element>.png          Fig. 13: its force history, three runs
//   displacement_<dof>.png       Fig. 14: the compared DOF's displacement, three runs
// Names are made file-safe (PlotExporter::fileSafe).
// Thread rules: GUI thread only.

#include "core/session/ComparisonProtocol.h"
#include "core/identification/ParameterSet.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>

namespace hsmu::gui {

class ComparisonPlotExporter {
    Q_DECLARE_TR_FUNCTIONS(ComparisonPlotExporter)
public:
    /// Write every plot into dir; truth: the specimen's true parameters (may be empty).
    /// Returns the files written; a file that could not be written is named in *errors.
    static QStringList write(const QString& dir, const ComparisonResult& result,
                             const ParameterValues& truth, QStringList* errors = nullptr);
};

} // namespace hsmu::gui
