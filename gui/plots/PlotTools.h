#pragma once
// PlotTools: the scope tools every console plot has (live, replay, exported):
//   cursor read-out  moving the mouse over the plot shows x and y under the cursor and, for
//                    each visible time-history graph, its value at that x (nearest sample)
//   zoom / pan       wheel zooms, drag pans; either turns autoscale off
//   autoscale        on: each refresh fits the data (PlotStyle::rescaleWithMargin); off: the
//                    operator's window stays (a time window can be pinned); double-click or
//                    the context menu turns it back on
//   channels         the context menu shows / hides each curve
//   export           the context menu writes the visible data (points inside the shown x
//                    range, and y range for loops) as CSV: series,x,y with the axis labels
// attach() is called by PlotStyle::apply(), so every plot gets them.
// Thread rules: GUI thread only.

#include <QObject>
#include <QString>

class QCustomPlot;
class QCPItemText;
class QMenu;
class QMouseEvent;
class QWheelEvent;

namespace hsmu::gui {

class PlotTools : public QObject {
    Q_OBJECT
public:
    /// The tools of plot (created on first use, a child of the plot).
    static PlotTools* attach(QCustomPlot& plot);
    static PlotTools* of(const QCustomPlot& plot);
    /// false when the operator zoomed, panned or switched autoscale off.
    static bool autoscale(const QCustomPlot& plot);

    bool autoscale() const { return m_autoscale; }
    void setAutoscale(bool on);
    /// Show or hide plottable i (a channel).
    void setChannelVisible(int i, bool visible);
    /// The read-out for plot coordinates (x, y) (what the cursor label shows).
    QString readout(double x, double y) const;
    /// The cursor label's text ("" while the mouse is not over the plot).
    QString cursorText() const;
    /// Write the visible data of the visible channels to path (CSV, UTF-8); false and *error
    /// naming the file on failure. Returns the number of data rows in *rows if given.
    bool exportVisibleCsv(const QString& path, QString* error = nullptr, int* rows = nullptr) const;
    /// The context menu (built for the plot's current channels).
    QMenu* buildMenu(QWidget* parent);

private:
    explicit PlotTools(QCustomPlot& plot);
    void onMouseMove(QMouseEvent* event);
    void exportWithDialog();

    QCustomPlot& m_plot;
    bool m_autoscale = true;
    QCPItemText* m_label = nullptr;
};

} // namespace hsmu::gui
