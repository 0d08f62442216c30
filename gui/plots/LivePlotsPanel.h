#pragma once
// LivePlotsPanel: every plot of a running (or replayed) test in one widget, for the main
// window's centre and the replay window:
//   hysteresis     the specimen's measured loop, the auxiliary model and each numerical twin
//                  (HysteresisPlot::specimenWithTwins) overlaid
// The hysteresis, force and tracking plots each have an element picker in their header
// (PlotElementPicker, shown when there is a choice): by default the element the Parameters
// dock identifies; the operator's pick is kept across configure() while its element exists,
// and drawn from the first step (the rows' element samples are kept for that).
//   force          force / moment history of the specimen and its twins
//   displacement   every DOF's displacement history [m]
//   ground motion  the ground acceleration [m/s^2] with a time cursor at the latest row
//   tracking       the specimen's commanded vs measured deformation, the actuator's own command
//                  and (right axis) the ticks its controller held (HistoryPlot::showTracking)
//   fit error      the inspector's normalized RMS error with its threshold line (updating)
//   parameters     one small ParameterPlot per identified parameter: estimate, ± 2 sigma
//                  band, identification bounds (updating); overlaid histories (a replay's
//                  re-identification) are named in one note under them, not in a legend row
//                  that would squeeze a small plot to a strip
//   actuators      with multi-DOF elements (RunLayout::channels): every actuator's command,
//                  stroke and force, every basic DOF, one curve each, and the setup's sketch
//                  with its deformed shape (ActuatorsPanel), under the other plots
// Feeding (the PlotJuggler way): appendRecords() only appends; refresh() asks for one redraw
// of every plot. The owner calls refresh() once per coalesced batch (~30 Hz), never per step.
// Redraws are also budgeted: after a redraw that took c ms, the next one waits at least
// max(kMinIntervalMs, kBudgetFactor x c) (pending requests coalesce into one), so drawing
// never takes more than ~1/kBudgetFactor of the GUI thread however many points the plots
// hold, and the test worker keeps its step rate (docs/benchmarks.md, "Step rate").
// Each plot's one context menu (PlotTools) also exports it, or every plot, as PNG, SVG or PDF
// (PlotExporter).
// Thread rules: GUI thread only.

#include "core/output/RunLayout.h"
#include "core/experiment/StepRecord.h"
#include "gui/plots/PlotReferences.h"

#include <QElapsedTimer>
#include <QStringList>
#include <QVector>
#include <QWidget>

#include <functional>

#include <vector>

class QCustomPlot;
class QGridLayout;
class QLabel;
class QMenu;
class QTimer;

namespace hsmu {
struct TestConfig;
}

namespace hsmu::gui {

class ActuatorsPanel;
class HistoryPlot;
class HysteresisPlot;
class PlotElementPicker;
class ParameterPlot;

class LivePlotsPanel : public QWidget {
    Q_OBJECT
public:
    /// A plot and the base of its export file name (e.g. "hysteresis").
    struct NamedPlot {
        QString fileBase;
        QCustomPlot* plot = nullptr;
    };

    static constexpr int kMinIntervalMs = 33; ///< ~30 Hz at most
    static constexpr int kMaxIntervalMs = 1000;
    static constexpr int kBudgetFactor = 20;

    explicit LivePlotsPanel(QWidget* parent = nullptr);

    /// Set up every plot for a run of this layout (clears the data).
    void configure(const RunLayout& layout, const PlotReferences& references = {});
    /// configure() for a loaded test: its layout, PlotReferences::of(cfg) and the whole
    /// ground-motion record of cfg (scaled; falls back to the rows' ground acceleration if
    /// the record cannot be read).
    void configure(const RunLayout& layout, const TestConfig& cfg);
    /// Read and show cfg's ground-motion record (scaled, cut at the duration); false and
    /// *error (the reader's message, naming the file) if it cannot be read. The plot keeps
    /// what it showed.
    bool showGroundMotionOf(const TestConfig& cfg, QString* error = nullptr);
    /// Show this whole ground-motion record (time [s], acceleration [m/s^2]) instead of the
    /// rows' ground acceleration; the time cursor marks the latest row. The other time plots
    /// span 0 to its last time while they have no data (or one row).
    void setGroundMotion(const QVector<double>& time, const QVector<double>& acceleration);

    /// Append rows (oldest first) to every plot; no replot.
    void appendRecords(const std::vector<StepRecord>& rows);
    /// Overlay a second history of `parameter` on its plot as the curve `curveName` (time [s],
    /// values in the parameter's units; a curve of that name is replaced) and redraw. False if
    /// no plot shows that parameter.
    bool overlayParameterHistory(const QString& curveName, const QString& parameter,
                                 const QVector<double>& time, const QVector<double>& values);
    /// Draw `parameter`'s identification bounds at [lower, upper] (an edit the updater
    /// accepted); redraws only when they changed. False if no plot shows that parameter.
    bool setParameterBounds(const QString& parameter, double lower, double upper);
    /// Remove every point (the configuration stays).
    void clearData();
    /// Ask for a redraw: now if the budget allows, else once when it does.
    void refresh();
    /// Rescale and redraw each plot now (before a grab or an export).
    void refreshNow();
    /// Redraws done since construction, and the wait the budget imposes now [ms].
    int redraws() const { return m_redraws; }
    int redrawIntervalMs() const { return m_intervalMs; }

    /// The plots that exist for this layout, in display order; parameter plots separately.
    std::vector<NamedPlot> plots() const;
    const std::vector<ParameterPlot*>& parameterPlots() const { return m_parameters; }
    HysteresisPlot& hysteresis() const { return *m_hysteresis; }
    HistoryPlot& forceHistory() const { return *m_force; }
    HistoryPlot& displacementHistory() const { return *m_displacement; }
    HistoryPlot& groundMotion() const { return *m_ground; }
    HistoryPlot& tracking() const { return *m_tracking; }
    HistoryPlot& fitError() const { return *m_fitError; }
    ActuatorsPanel& actuators() const { return *m_actuators; }
    /// The element pickers of the hysteresis, force and tracking plots.
    PlotElementPicker& hysteresisPicker() const { return *m_hysteresisPicker; }
    PlotElementPicker& forcePicker() const { return *m_forcePicker; }
    PlotElementPicker& trackingPicker() const { return *m_trackingPicker; }
    /// Rows appended since configure() / clearData().
    qint64 rowsShown() const { return m_rows; }

    /// Write every plot into dir as fileBase.suffix (suffix: png, svg or pdf; the parameter
    /// plots as parameter_<name>.suffix). Returns the files written; failures in *errors.
    QStringList exportAll(const QString& dir, const QString& suffix, QStringList* errors = nullptr);

private:
    void enableExportMenu(QCustomPlot* plot);
    /// Show element (index into m_layout) with its twins / its tracking channels.
    void showHysteresisOf(int element);
    void showForceOf(int element);
    void showTrackingOf(int element);
    /// The read-out names the picked element when there is a choice.
    void nameSubject(QCustomPlot& plot, const PlotElementPicker& picker);
    /// After a pick: show(), then the picked element's whole history from m_history.
    void showPicked(QCustomPlot& plot, const std::function<void()>& show);
    void addExportActions(QCustomPlot* plot, QMenu* menu);
    void exportPlotWithDialog(QCustomPlot* plot);
    void exportAllWithDialog();
    void rebuildParameterPlots(const RunLayout& layout, const PlotReferences& references);
    /// The note naming the overlaid parameter histories (hidden without).
    void showOverlayNote();
    std::vector<QCustomPlot*> visiblePlots() const;
    /// Every plot, shown or not (the parameter plots last).
    std::vector<QCustomPlot*> allPlots() const;

    RunLayout m_layout;
    /// The rows so far, slimmed to time and element samples (~60 B per element per step), so
    /// that a picked element is drawn from the first step.
    std::vector<StepRecord> m_history;
    PlotElementPicker* m_hysteresisPicker = nullptr;
    PlotElementPicker* m_forcePicker = nullptr;
    PlotElementPicker* m_trackingPicker = nullptr;
    HysteresisPlot* m_hysteresis = nullptr;
    HistoryPlot* m_force = nullptr;
    HistoryPlot* m_displacement = nullptr;
    HistoryPlot* m_ground = nullptr;
    HistoryPlot* m_tracking = nullptr;
    HistoryPlot* m_fitError = nullptr;
    ActuatorsPanel* m_actuators = nullptr;
    QWidget* m_parameterArea = nullptr;
    QGridLayout* m_parameterGrid = nullptr;
    QLabel* m_overlayNote = nullptr; ///< names the overlaid curves (dashed), hidden without
    QStringList m_overlays;          ///< the overlaid curves' names, in the order added
    std::vector<ParameterPlot*> m_parameters;
    bool m_fixedGroundMotion = false;
    bool m_hasSpecimen = false;
    bool m_hasUpdating = false;
    qint64 m_rows = 0;
    QTimer* m_redrawTimer = nullptr; ///< single shot: a redraw the budget postponed
    QElapsedTimer m_sinceRedraw;
    int m_intervalMs = kMinIntervalMs;
    int m_redraws = 0;
};

} // namespace hsmu::gui
