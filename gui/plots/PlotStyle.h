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
    /// The room [px] a label of axis has along it: centred on the axis, up to the plot's edges;
    /// a vertical label enters the title row only where the title's text is not, and never a
    /// legend row under the axis rect.
    static int labelRoom(const QCustomPlot& plot, const QCPAxis& axis);
    /// Set (or create) the title row above the axis rect.
    static void setTitle(QCustomPlot& plot, const QString& title);
    /// rescaleAxes() with a 5 % margin on each side; a flat range gets a unit span; visible
    /// horizontal lines of addLine() (thresholds, bounds) are kept inside the y range.
    /// A plot with no data point yet (before a test) shows its references instead of
    /// QCustomPlot's arbitrary 0..5: x over setEmptyXRange()'s span, y over its visible
    /// horizontal lines (a threshold alone: 0 to the threshold, with a 25 % margin); an axis
    /// with no reference shows no numbers until data arrive. A single sample (one time, or one
    /// value) is not centred in a span of QCustomPlot's choosing (-3..3 s): time goes over the
    /// setEmptyXRange() span, a flat value over its reference lines (an axis with neither
    /// shows no numbers).
    static void rescaleWithMargin(QCustomPlot& plot);
    /// The x span an empty plot shows, e.g. a time axis over the loaded test, 0 to T [s];
    /// lower >= upper (or NaN): none.
    static void setEmptyXRange(QCustomPlot& plot, double lower, double upper);
    /// True if a visible plottable holds at least one point.
    static bool hasData(const QCustomPlot& plot);
    /// A horizontal (value = y) or vertical (value = x) reference line in plot coordinates,
    /// e.g. a threshold, a bound or a time cursor; hidden while value is not finite.
    static QCPItemStraightLine* addLine(QCustomPlot& plot, Qt::Orientation orientation,
                                        const QPen& pen);
    static void placeLine(QCPItemStraightLine& line, Qt::Orientation orientation, double value);
    /// Widen axis so that value (if finite) lies inside with a 5 % margin of the new span.
    static void includeInRange(QCPAxis& axis, double value);
};

} // namespace hsmu::gui
