#pragma once
// PlotExporter: renders plots to PNG, SVG (QSvgGenerator) or PDF (QPdfWriter) files without
// showing a window (the widgets are laid out and painted offscreen; a QApplication must
// exist, the "offscreen" platform works). writeRunPlots() draws a run with the console's own
// LivePlotsPanel (`hsmu run --plots`):
//   plots.png                 the whole panel, as the console shows it
//   hysteresis.png            the specimen's measured loop, auxiliary model and twins
//   hysteresis_<element>.png  one per nonlinear element: its loop (a specimen's is measured)
//   force.png                 force / moment history of the specimen and its twins
//   displacement.png          every DOF's displacement history
//   ground_motion.png         the ground acceleration applied by the test
//   tracking.png              with a specimen: commanded vs measured deformation
//   fit_error.png             with online model updating: the inspector's error and threshold
//   parameters.png            with online model updating: one ParameterPlot per identified
//                             parameter (estimate, ± 2 sigma band, bounds), in a grid
// Element names are made file-safe (non-alphanumerics become '_').
// Thread rules: GUI thread only.

#include "core/output/RunLayout.h"
#include "core/experiment/StepRecord.h"
#include "gui/plots/PlotReferences.h"

#include <QCoreApplication>

#include <QString>
#include <QStringList>

#include <vector>

class QCustomPlot;

namespace hsmu::gui {

class PlotExporter {
    Q_DECLARE_TR_FUNCTIONS(PlotExporter)
public:
    static constexpr int kWidth = 900;          ///< [px]
    static constexpr int kHeight = 600;         ///< [px]
    static constexpr int kGridCellWidth = 420;  ///< [px] per small plot of a grid
    static constexpr int kGridCellHeight = 280; ///< [px]
    static constexpr int kGridColumns = 3;
    static constexpr int kPanelWidth = 1600;  ///< [px] plots.png
    static constexpr int kPanelHeight = 1000; ///< [px]

    /// Write every plot into dir. Returns the files written; a file that could not be written
    /// is named in *errors (if given).
    static QStringList writeRunPlots(const QString& dir, const RunLayout& layout,
                                     const std::vector<StepRecord>& records,
                                     QStringList* errors = nullptr,
                                     const PlotReferences& references = {});
    /// Lay out, replot and save one plot. False if the file could not be written.
    static bool savePng(QCustomPlot& plot, const QString& path, int width = kWidth,
                        int height = kHeight);
    /// The same as a vector drawing (SVG 1.2 tiny, QSvgGenerator) or a one-page PDF.
    static bool saveSvg(QCustomPlot& plot, const QString& path, int width = kWidth,
                        int height = kHeight);
    static bool savePdf(QCustomPlot& plot, const QString& path, int width = kWidth,
                        int height = kHeight);
    /// By the path's suffix (png, svg or pdf, any case); false with a reason in *why for
    /// another suffix or a write error.
    static bool saveAs(QCustomPlot& plot, const QString& path, int width, int height,
                       QString* why = nullptr);
    /// Lay out and replot each plot in a cell of cellWidth x cellHeight and save them as one
    /// PNG, `columns` per row (e.g. the parameter histories). False if it could not be written.
    static bool saveGridPng(const std::vector<QCustomPlot*>& plots, const QString& path,
                            int columns, int cellWidth, int cellHeight);
    /// "Element 1" -> "Element_1".
    static QString fileSafe(const QString& name);
};

} // namespace hsmu::gui
