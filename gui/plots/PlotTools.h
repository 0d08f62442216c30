#pragma once
// PlotTools: the scope tools every console plot has (live, replay, exported):
//   cursor read-out  moving the mouse over the plot shows x and y under the cursor and, for
//                    each visible time-history graph, its value at that x (nearest sample), in
//                    a framed box on a white background at the top right of the data area,
//                    kept inside the plot (long lines shortened in the middle); it goes when
//                    the pointer leaves the plot or the plot's data are cleared; a plot of
//                    a picked element names it first (setSubject())
//   zoom / pan       wheel zooms, drag pans; either turns autoscale off
//   autoscale        on: each refresh fits the data (PlotStyle::rescaleWithMargin); off: the
//                    operator's window stays (a time window can be pinned); double-click or
//                    the context menu turns it back on
//   channels         the context menu shows / hides each curve
//   export           the context menu writes the visible data (points inside the shown x
//                    range, and y range for loops) as CSV: series,x,y with the axis labels
// The context menu is the plot's only one: its owner adds its own entries (e.g. the image
// export of LivePlotsPanel) through menuRequested().
// attach() is called by PlotStyle::apply(), so every plot gets them.
// Thread rules: GUI thread only.

#include <QObject>
#include <QString>

class QCustomPlot;
class QLabel;
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
    /// What the plot shows, e.g. the element a per-element plot is picked to ("" = the
    /// title says it all); the read-out's first line names it.
    void setSubject(const QString& subject) { m_subject = subject; }
    const QString& subject() const { return m_subject; }
    /// The read-out for plot coordinates (x, y) (what the cursor label shows).
    QString readout(double x, double y) const;
    /// The cursor label's text ("" while the mouse is not over the plot).
    QString cursorText() const;
    /// The read-out box (hidden while the mouse is not over the plot).
    QLabel* cursorLabel() const { return m_label; }
    /// Hide the read-out (the pointer left, the data were cleared or replaced).
    void hideReadout();
    /// Write the visible data of the visible channels to path (CSV, UTF-8); false and *error
    /// naming the file on failure. Returns the number of data rows in *rows if given.
    bool exportVisibleCsv(const QString& path, QString* error = nullptr, int* rows = nullptr) const;
    /// The context menu (built for the plot's current channels, then menuRequested()).
    QMenu* buildMenu(QWidget* parent);

signals:
    /// The context menu is being built: the plot's owner adds its own entries to it.
    void menuRequested(QMenu* menu);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    explicit PlotTools(QCustomPlot& plot);
    void onMouseMove(QMouseEvent* event);
    void exportWithDialog();
    /// Place the read-out box at the top right of the data area, inside the plot.
    void placeReadout();

    QCustomPlot& m_plot;
    bool m_autoscale = true;
    QLabel* m_label = nullptr;
    QString m_readout; ///< the whole text (the box may show it shortened)
    QString m_subject;
};

} // namespace hsmu::gui
