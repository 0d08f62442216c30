#pragma once
// HistoryPlot: time histories of quantities taken from StepRecords (one graph per channel),
// e.g. the displacement of every DOF [m] or the ground acceleration [m/s^2]. Used live by the
// console (LivePlotsPanel), by the replay window and offscreen by `hsmu run --plots`; with
// addSeries() also precomputed histories (`hsmu compare --plots`: the three runs overlaid).
// Optional reference lines: a horizontal threshold (e.g. the inspector's fit-error threshold,
// kept inside the y range) and a vertical time cursor (e.g. the replay position on the
// ground motion).
// Thread rules: GUI thread only.

#include "core/output/RunLayout.h"
#include "core/experiment/StepRecord.h"

#include <qcustomplot.h>

#include <functional>
#include <vector>

namespace hsmu::gui {

class HistoryPlot : public QCustomPlot {
    Q_OBJECT
public:
    struct Channel {
        QString name;
        std::function<double(const StepRecord&)> value;
        bool rightAxis = false; ///< plotted against the right y axis (rightLabel)
        /// NaN samples are left out instead of breaking the line: a decimated record's DOF
        /// (docs/recording.md) shows its kept rows joined, not isolated invisible points.
        bool skipGaps = false;
    };

    explicit HistoryPlot(QWidget* parent = nullptr);

    /// Replace the graphs: one per channel; y axis labelled yLabel (with its unit); channels
    /// with rightAxis against a right y axis labelled rightLabel (shown only then).
    void setChannels(const QString& title, const QString& yLabel, std::vector<Channel> channels,
                     const QString& rightLabel = QString());
    /// Channels for the displacement of every DOF of layout [m].
    void showDisplacements(const RunLayout& layout);
    /// One channel: the ground acceleration [m/s^2].
    void showGroundAcceleration();
    /// The whole ground-motion record (time [s], acceleration [m/s^2]) as a fixed series;
    /// appendRecords() adds nothing (pair it with setTimeCursor()).
    void showGroundMotion(const QVector<double>& time, const QVector<double>& acceleration);
    /// Force (moment for rotational elements) of each element in `elements` (indices into
    /// layout), which must share one force unit (that of the first).
    void showForces(const RunLayout& layout, const std::vector<int>& elements);
    /// Commanded and measured deformation of element `specimen` (an experimental element),
    /// the actuator's own command as its control reported it (ElementSample::actuator; the
    /// predictor-corrector's command for hsmu-controller) and, on the right axis, the ticks
    /// the controller held waiting for a late target. Channels a control does not report
    /// stay empty.
    void showTracking(const RunLayout& layout, int specimen);
    /// The inspector's normalized fit error [-] (StepRecord::updating.fitError) and its
    /// threshold line (NaN: none).
    void showFitError(double threshold);

    /// Horizontal threshold line at y = value (NaN hides it), kept in the y range.
    void setThreshold(double value);
    double threshold() const { return m_threshold; }
    /// Vertical time cursor at t [s] (NaN hides it).
    void setTimeCursor(double time);
    double timeCursor() const { return m_cursorTime; }
    /// Add a graph of precomputed samples (time [s], value), e.g. one run of `hsmu compare`;
    /// it is not fed by appendRecords() and is removed by the next setChannels().
    void addSeries(const QString& name, const QVector<double>& time, const QVector<double>& value);

    void appendRecords(const std::vector<StepRecord>& records);
    void clearData();
    /// The texts of the show*() methods again in the current language (also done on each
    /// QEvent::LanguageChange; texts given to setChannels() / addSeries() stay as given).
    void retranslate();
    /// Rescale to the data (with a margin) and replot (queued).
    void refresh();

private:
    /// Title, y label(s) and the names of the first graphs, without touching their data.
    void relabel(const QString& title, const QString& yLabel, const QStringList& names,
                 const QString& rightLabel = QString());
    /// Keep texts() (tr() calls) for retranslate() and apply it now.
    void setTexts(std::function<void()> texts);

    std::function<void()> m_texts; ///< the current show*()'s texts, or empty
    std::vector<Channel> m_channels;
    std::vector<QCPGraph*> m_graphs;
    double m_threshold = qQNaN();
    double m_cursorTime = qQNaN();
    QCPItemStraightLine* m_thresholdLine = nullptr;
    QCPItemStraightLine* m_cursor = nullptr;
};

} // namespace hsmu::gui
