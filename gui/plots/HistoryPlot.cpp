#include "gui/plots/HistoryPlot.h"

#include "gui/plots/PlotSelection.h"
#include "gui/plots/PlotStyle.h"

namespace hsmu::gui {

HistoryPlot::HistoryPlot(QWidget* parent) : QCustomPlot(parent) {
    PlotStyle::apply(*this);
    xAxis->setLabel(tr("Time [s]"));
    axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    m_thresholdLine =
        PlotStyle::addLine(*this, Qt::Horizontal, QPen(QColor(200, 30, 30), 1.2, Qt::DashLine));
    m_cursor = PlotStyle::addLine(*this, Qt::Vertical, QPen(QColor(30, 30, 30), 1.5));
}

void HistoryPlot::setChannels(const QString& title, const QString& yLabel,
                              std::vector<Channel> channels, const QString& rightLabel) {
    clearGraphs();
    m_graphs.clear();
    m_channels = std::move(channels);
    bool right = false;
    for (std::size_t i = 0; i < m_channels.size(); ++i) {
        right = right || m_channels[i].rightAxis;
        QCPGraph* g = addGraph(xAxis, m_channels[i].rightAxis ? yAxis2 : yAxis);
        g->setName(m_channels[i].name);
        g->setPen(PlotStyle::seriesPen(int(i)));
        m_graphs.push_back(g);
    }
    yAxis->setLabel(yLabel);
    yAxis2->setVisible(right);
    yAxis2->setLabel(right ? rightLabel : QString());
    PlotStyle::setTitle(*this, title);
    legend->setVisible(!m_channels.empty());
    replot();
}

void HistoryPlot::showDisplacements(const RunLayout& layout) {
    std::vector<Channel> channels;
    for (const int dof : spreadIndices(int(layout.dofNames.size()), kMaxPlottedDofs)) {
        const auto i = std::size_t(dof);
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

void HistoryPlot::showGroundMotion(const QVector<double>& time,
                                   const QVector<double>& acceleration) {
    setChannels(tr("Ground motion"), tr("Ground acceleration [m/s²]"), {});
    addSeries(tr("Ground acceleration"), time, acceleration);
}

void HistoryPlot::showForces(const RunLayout& layout, const std::vector<int>& elements) {
    std::vector<Channel> channels;
    for (const int index : elements) {
        const auto i = std::size_t(index);
        channels.push_back(
            {QString::fromStdString(layout.elements[i].name), [i](const StepRecord& r) {
                 return i < r.elements.size() ? r.elements[i].force : qQNaN();
             }});
    }
    if (elements.empty()) {
        setChannels(tr("Force history"), tr("Force"), {});
        return;
    }
    const ElementUnits& units = layout.elements[std::size_t(elements.front())].units;
    const QString unit = QString::fromStdString(units.force);
    const bool rotational = units.deformation == "rad";
    setChannels(rotational ? tr("Moment history") : tr("Force history"),
                rotational ? tr("Moment [%1]").arg(unit) : tr("Force [%1]").arg(unit),
                std::move(channels));
}

void HistoryPlot::showTracking(const RunLayout& layout, int specimen) {
    const auto i = std::size_t(specimen);
    const ElementInfo& e = layout.elements[i];
    const QString unit = QString::fromStdString(e.units.deformation);
    const bool rotational = e.units.deformation == "rad";
    setChannels(tr("Tracking of %1").arg(QString::fromStdString(e.name)),
                rotational ? tr("Rotation [%1]").arg(unit) : tr("Deformation [%1]").arg(unit),
                {{tr("commanded"),
                  [i](const StepRecord& r) {
                      return i < r.elements.size() ? r.elements[i].commanded : qQNaN();
                  }},
                 {tr("measured"),
                  [i](const StepRecord& r) {
                      return i < r.elements.size() ? r.elements[i].deformation : qQNaN();
                  }},
                 {tr("actuator command"),
                  [i](const StepRecord& r) {
                      return i < r.elements.size() ? r.elements[i].actuator.commanded : qQNaN();
                  }},
                 {tr("held ticks"),
                  [i](const StepRecord& r) {
                      const std::int64_t t =
                          i < r.elements.size() ? r.elements[i].actuator.heldTicks : -1;
                      return t < 0 ? qQNaN() : double(t);
                  },
                  true}},
                tr("Held ticks [-]"));
}

void HistoryPlot::showFitError(double threshold) {
    setChannels(tr("Inspector fit error"), tr("Fit error [-]"),
                {{tr("fit error"), [](const StepRecord& r) {
                      return r.hasUpdating ? r.updating.fitError : qQNaN();
                  }}});
    setThreshold(threshold);
}

void HistoryPlot::setThreshold(double value) {
    m_threshold = value;
    PlotStyle::placeLine(*m_thresholdLine, Qt::Horizontal, value);
}

void HistoryPlot::setTimeCursor(double time) {
    m_cursorTime = time;
    PlotStyle::placeLine(*m_cursor, Qt::Vertical, time);
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
