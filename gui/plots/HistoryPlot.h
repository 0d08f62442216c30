#pragma once
// HistoryPlot: time histories of quantities taken from StepRecords (one graph per channel),
// e.g. the displacement of every DOF [m] or the ground acceleration [m/s^2]. Used live by the
// console and offscreen by `hsmu run --plots`; with addSeries() also precomputed histories
// (`hsmu compare --plots`: the three runs overlaid).
// Thread rules: GUI thread only.

#include "core/output/RunLayout.h"
#include "core/test/StepRecord.h"

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
    };

    explicit HistoryPlot(QWidget* parent = nullptr);

    /// Replace the graphs: one per channel; y axis labelled yLabel (with its unit).
    void setChannels(const QString& title, const QString& yLabel, std::vector<Channel> channels);
    /// Channels for the displacement of every DOF of layout [m].
    void showDisplacements(const RunLayout& layout);
    /// One channel: the ground acceleration [m/s^2].
    void showGroundAcceleration();

    /// Add a graph of precomputed samples (time [s], value), e.g. one run of `hsmu compare`;
    /// it is not fed by appendRecords() and is removed by the next setChannels().
    void addSeries(const QString& name, const QVector<double>& time, const QVector<double>& value);

    void appendRecords(const std::vector<StepRecord>& records);
    void clearData();
    /// Rescale to the data (with a margin) and replot (queued).
    void refresh();

private:
    std::vector<Channel> m_channels;
    std::vector<QCPGraph*> m_graphs;
};

} // namespace hsmu::gui
