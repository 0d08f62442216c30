#pragma once
// PlotStyle: the look shared by every plot of the console and of the PNG export (white
// background, grid, legend, a fixed series palette), and small helpers for titles and
// autoscaling. Thread rules: GUI thread only.

#include <QPen>
#include <QString>

class QCustomPlot;

namespace hsmu::gui {

class PlotStyle {
public:
    /// Fonts, grid, legend placement, interactions (drag / zoom).
    static void apply(QCustomPlot& plot);
    /// Pen of series number i (0: the reference series, drawn thicker).
    static QPen seriesPen(int i);
    /// Set (or create) the title row above the axis rect.
    static void setTitle(QCustomPlot& plot, const QString& title);
    /// rescaleAxes() with a 5 % margin on each side; a flat range gets a unit span.
    static void rescaleWithMargin(QCustomPlot& plot);
};

} // namespace hsmu::gui
