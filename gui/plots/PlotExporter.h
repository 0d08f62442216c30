#pragma once
// PlotExporter: renders a run's plots to PNG files without showing a window (the widgets are
// laid out and painted offscreen; a QApplication must exist, the "offscreen" platform works):
//   hysteresis_<element>.png  one per nonlinear element: its loop (a specimen's is measured)
//   displacement.png          every DOF's displacement history
//   ground_motion.png         the ground acceleration applied by the test
//   parameters.png            with online model updating: one ParameterPlot per identified
//                             parameter (estimate and its ± 2 sigma band), in a grid
// Element names are made file-safe (non-alphanumerics become '_').
// Thread rules: GUI thread only.

#include "core/output/RunLayout.h"
#include "core/test/StepRecord.h"

#include <QString>
#include <QStringList>

#include <vector>

class QCustomPlot;

namespace hsmu::gui {

class PlotExporter {
public:
    static constexpr int kWidth = 900;          ///< [px]
    static constexpr int kHeight = 600;         ///< [px]
    static constexpr int kGridCellWidth = 420;  ///< [px] per small plot of a grid
    static constexpr int kGridCellHeight = 280; ///< [px]
    static constexpr int kGridColumns = 3;

    /// Write every plot into dir. Returns the files written; a file that could not be written
    /// is named in *errors (if given).
    static QStringList writeRunPlots(const QString& dir, const RunLayout& layout,
                                     const std::vector<StepRecord>& records,
                                     QStringList* errors = nullptr);
    /// Lay out, replot and save one plot. False if the file could not be written.
    static bool savePng(QCustomPlot& plot, const QString& path, int width = kWidth,
                        int height = kHeight);
    /// Lay out and replot each plot in a cell of cellWidth x cellHeight and save them as one
    /// PNG, `columns` per row (e.g. the parameter histories). False if it could not be written.
    static bool saveGridPng(const std::vector<QCustomPlot*>& plots, const QString& path,
                            int columns, int cellWidth, int cellHeight);
    /// "Element 1" -> "Element_1".
    static QString fileSafe(const QString& name);
};

} // namespace hsmu::gui
