#pragma once
// PlotStyle: the look shared by every plot of the console and of the PNG export (white
// background, grid, legend, a fixed series palette), and small helpers for titles and
// autoscaling. Thread rules: GUI thread only.

#include <QPen>
#include <QString>

class QCPAxis;
class QCPItemStraightLine;
class QCustomPlot;

namespace hsmu::gui {

class PlotStyle {
public:
    /// Fonts, grid, legend placement, interactions (drag / zoom).
    static void apply(QCustomPlot& plot);
    /// Pen of series number i (0: the reference series, drawn thicker).
    static QPen seriesPen(int i);
    /// An axis' whole label: apply()'s plots cut a label longer than its axis with "..." at
    /// each replot (the full labels in the plot's tool tip); this gives the label as set.
    static QString axisLabel(const QCustomPlot& plot, const QCPAxis& axis);
    /// The room [px] a label of axis has along it: centred on the axis, up to the plot's edges.
    static int labelRoom(const QCustomPlot& plot, const QCPAxis& axis);
    /// Set (or create) the title row above the axis rect.
    static void setTitle(QCustomPlot& plot, const QString& title);
    /// rescaleAxes() with a 5 % margin on each side; a flat range gets a unit span; visible
    /// horizontal lines of addLine() (thresholds, bounds) are kept inside the y range.
    static void rescaleWithMargin(QCustomPlot& plot);
    /// A horizontal (value = y) or vertical (value = x) reference line in plot coordinates,
    /// e.g. a threshold, a bound or a time cursor; hidden while value is not finite.
    static QCPItemStraightLine* addLine(QCustomPlot& plot, Qt::Orientation orientation,
                                        const QPen& pen);
    static void placeLine(QCPItemStraightLine& line, Qt::Orientation orientation, double value);
    /// Widen axis so that value (if finite) lies inside with a 5 % margin of the new span.
    static void includeInRange(QCPAxis& axis, double value);
};

} // namespace hsmu::gui
