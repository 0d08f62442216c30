#include "gui/plots/HistoryPlot.h"

#include "gui/app/LiveText.h"
#include "gui/plots/PlotSelection.h"
#include "gui/plots/PlotStyle.h"

#include <cmath>

namespace hsmu::gui {

HistoryPlot::HistoryPlot(QWidget* parent) : QCustomPlot(parent) {
    PlotStyle::apply(*this);
    xAxis->ticker()->setTickCount(4); // small cells at 1280x720: time labels must not touch
    m_thresholdLine =
        PlotStyle::addLine(*this, Qt::Horizontal, QPen(QColor(200, 30, 30), 1.2, Qt::DashLine));
    m_cursor = PlotStyle::addLine(*this, Qt::Vertical, QPen(QColor(30, 30, 30), 1.5));
    LiveText::bind(this, [this] { retranslate(); });
}

void HistoryPlot::retranslate() {
    xAxis->setLabel(tr("Time [s]"));
    if (m_texts)
        m_texts();
    replot(QCustomPlot::rpQueuedReplot);
}

void HistoryPlot::setTexts(std::function<void()> texts) {
    m_texts = std::move(texts);
    m_texts();
    replot();
}

void HistoryPlot::relabel(const QString& title, const QString& yLabel, const QStringList& names,
                          const QString& rightLabel) {
    PlotStyle::setTitle(*this, title);
    yAxis->setLabel(yLabel);
    if (yAxis2->visible())
        yAxis2->setLabel(rightLabel);
    for (int i = 0; i < names.size() && i < graphCount(); ++i)
        graph(i)->setName(names[i]);
}

void HistoryPlot::setChannels(const QString& title, const QString& yLabel,
                              std::vector<Channel> channels, const QString& rightLabel) {
    clearGraphs();
    m_graphs.clear();
    m_texts = nullptr;
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
             [index](const StepRecord& r) { return index < r.u.size() ? r.u[index] : qQNaN(); },
             false, true});
    }
    setChannels(QString(), QString(), std::move(channels));
    setTexts([this] { relabel(tr("Displacement history"), tr("Displacement [m]"), {}); });
}

void HistoryPlot::showGroundAcceleration() {
    setChannels(QString(), QString(),
                {{QString(), [](const StepRecord& r) { return r.groundAcceleration; }}});
    setTexts([this] {
        relabel(tr("Ground motion"), tr("Ground acceleration [m/s²]"),
                {tr("Ground acceleration")});
    });
}

void HistoryPlot::showGroundMotion(const QVector<double>& time,
                                   const QVector<double>& acceleration) {
    setChannels(QString(), QString(), {});
    addSeries(QString(), time, acceleration);
    setTexts([this] {
        relabel(tr("Ground motion"), tr("Ground acceleration [m/s²]"),
                {tr("Ground acceleration")});
    });
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
    setChannels(QString(), QString(), std::move(channels));
    if (elements.empty()) {
        setTexts([this] { relabel(tr("Force history"), QString(), {}); }); // no unit known
        return;
    }
    const ElementUnits& units = layout.elements[std::size_t(elements.front())].units;
    const QString unit = QString::fromStdString(units.force);
    const bool rotational = units.deformation == "rad";
    setTexts([this, unit, rotational] {
        relabel(rotational ? tr("Moment history") : tr("Force history"),
                rotational ? tr("Moment [%1]").arg(unit) : tr("Force [%1]").arg(unit), {});
    });
}

void HistoryPlot::showTracking(const RunLayout& layout, int specimen) {
    const auto i = std::size_t(specimen);
    const ElementInfo& e = layout.elements[i];
    const QString unit = QString::fromStdString(e.units.deformation);
    const bool rotational = e.units.deformation == "rad";
    setChannels(QString(), QString(),
                {{QString(),
                  [i](const StepRecord& r) {
                      return i < r.elements.size() ? r.elements[i].commanded : qQNaN();
                  }},
                 {QString(),
                  [i](const StepRecord& r) {
                      return i < r.elements.size() ? r.elements[i].deformation : qQNaN();
                  }},
                 {QString(),
                  [i](const StepRecord& r) {
                      return i < r.elements.size() ? r.elements[i].actuator.commanded : qQNaN();
                  }},
                 {QString(),
                  [i](const StepRecord& r) {
                      const std::int64_t t =
                          i < r.elements.size() ? r.elements[i].actuator.heldTicks : -1;
                      return t < 0 ? qQNaN() : double(t);
                  },
                  true}});
    const QString name = QString::fromStdString(e.name);
    setTexts([this, name, unit, rotational] {
        relabel(tr("Tracking of %1").arg(name),
                rotational ? tr("Rotation [%1]").arg(unit) : tr("Deformation [%1]").arg(unit),
                {tr("commanded"), tr("measured"), tr("actuator command"), tr("held ticks")},
                tr("Held ticks [-]"));
    });
}

void HistoryPlot::showFitError(double threshold) {
    setChannels(QString(), QString(), {{QString(), [](const StepRecord& r) {
                                             return r.hasUpdating ? r.updating.fitError : qQNaN();
                                         }}});
    setTexts(
        [this] { relabel(tr("Inspector fit error"), tr("Fit error [-]"), {tr("fit error")}); });
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
            const double value = m_channels[i].value(r);
            if (m_channels[i].skipGaps && std::isnan(value))
                continue;
            t.push_back(r.time);
            y.push_back(value);
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
