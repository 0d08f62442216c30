#include "gui/plots/HistoryPlot.h"

#include "gui/plots/PlotStyle.h"

namespace hsmu::gui {

HistoryPlot::HistoryPlot(QWidget* parent) : QCustomPlot(parent) {
    PlotStyle::apply(*this);
    xAxis->setLabel(tr("Time [s]"));
    axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
}

void HistoryPlot::setChannels(const QString& title, const QString& yLabel,
                              std::vector<Channel> channels) {
    clearGraphs();
    m_graphs.clear();
    m_channels = std::move(channels);
    for (std::size_t i = 0; i < m_channels.size(); ++i) {
        QCPGraph* g = addGraph(xAxis, yAxis);
        g->setName(m_channels[i].name);
        g->setPen(PlotStyle::seriesPen(int(i)));
        m_graphs.push_back(g);
    }
    yAxis->setLabel(yLabel);
    PlotStyle::setTitle(*this, title);
    legend->setVisible(!m_channels.empty());
    replot();
}

void HistoryPlot::showDisplacements(const RunLayout& layout) {
    std::vector<Channel> channels;
    for (std::size_t i = 0; i < layout.dofNames.size(); ++i) {
        const auto index = Eigen::Index(i);
        channels.push_back(
            {QString::fromStdString(layout.dofNames[i]),
             [index](const StepRecord& r) { return index < r.u.size() ? r.u[index] : qQNaN(); }});
    }
    setChannels(tr("Displacement history"), tr("Displacement [m]"), std::move(channels));
}

void HistoryPlot::showGroundAcceleration() {
    setChannels(
        tr("Ground motion"), tr("Ground acceleration [m/s²]"),
        {{tr("Ground acceleration"), [](const StepRecord& r) { return r.groundAcceleration; }}});
}

void HistoryPlot::addSeries(const QString& name, const QVector<double>& time,
                            const QVector<double>& value) {
    QCPGraph* g = addGraph(xAxis, yAxis);
    g->setName(name);
    g->setPen(PlotStyle::seriesPen(graphCount() - 1));
    g->setData(time, value);
    legend->setVisible(true);
}

void HistoryPlot::appendRecords(const std::vector<StepRecord>& records) {
    for (std::size_t i = 0; i < m_channels.size(); ++i) {
        QVector<double> t, y;
        t.reserve(qsizetype(records.size()));
        y.reserve(qsizetype(records.size()));
        for (const StepRecord& r : records) {
            t.push_back(r.time);
            y.push_back(m_channels[i].value(r));
        }
        m_graphs[i]->addData(t, y, true);
    }
}

void HistoryPlot::clearData() {
    for (QCPGraph* g : m_graphs)
        g->data()->clear();
}

void HistoryPlot::refresh() {
    PlotStyle::rescaleWithMargin(*this);
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace hsmu::gui
