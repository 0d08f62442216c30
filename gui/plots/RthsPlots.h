#pragma once
// The console's RTHS plots (docs/rths.md, "The console's RTHS view"), in the look of every
// console plot (PlotStyle, PlotTools' menu and export):
//   SynchronizationPlot  measured displacement xm against desired y [mm], x-y, with the
//                        line xm = y (perfect tracking): a delay opens the loop into an
//                        ellipse, an amplitude error tilts it
//   TrackingHistoryPlot  the live window's delay [ms] (left axis, with the J1 warning and
//                        critical thresholds) and amplitude error [%] (right axis) against
//                        test time [s]
// Feeding: append*() only appends; refresh() rescales and asks for one replot.
// Thread rules: GUI thread only.

#include <qcustomplot.h>

namespace hsmu::gui {

class SynchronizationPlot : public QCustomPlot {
    Q_OBJECT
public:
    explicit SynchronizationPlot(QWidget* parent = nullptr);
    /// One sample: desired y and measured xm [m] (shown in mm).
    void append(double desired, double measured);
    void clearData();
    void refresh();
    int points() const;
    void retranslate();

protected:
    void changeEvent(QEvent* event) override;

private:
    QCPCurve* m_curve = nullptr;
    QCPItemStraightLine* m_ideal = nullptr;
};

class TrackingHistoryPlot : public QCustomPlot {
    Q_OBJECT
public:
    explicit TrackingHistoryPlot(QWidget* parent = nullptr);
    /// One estimate at time t [s]: delay [ms], amplitude error [%].
    void append(double time, double delay, double amplitudeError);
    /// J1's warning and critical thresholds [ms] as horizontal lines.
    void setDelayThresholds(double warning, double critical);
    void clearData();
    void refresh();
    int points() const;
    void retranslate();

protected:
    void changeEvent(QEvent* event) override;

private:
    QCPGraph* m_delay = nullptr;
    QCPGraph* m_amplitude = nullptr;
    QCPItemStraightLine* m_warning = nullptr;
    QCPItemStraightLine* m_critical = nullptr;
};

} // namespace hsmu::gui
