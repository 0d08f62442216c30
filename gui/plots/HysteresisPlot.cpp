#include "gui/plots/HysteresisPlot.h"

#include "gui/plots/PlotStyle.h"

namespace hsmu::gui {

HysteresisPlot::HysteresisPlot(QWidget* parent) : QCustomPlot(parent) {
    PlotStyle::apply(*this);
    xAxis->setLabel(tr("Deformation"));
    yAxis->setLabel(tr("Force"));
}

std::vector<int> HysteresisPlot::specimenWithTwins(const RunLayout& layout) {
    int specimen = -1;
    for (std::size_t i = 0; i < layout.elements.size() && specimen < 0; ++i)
        if (layout.elements[i].experimental)
            specimen = int(i);
    for (std::size_t i = 0; i < layout.elements.size() && specimen < 0; ++i)
        if (layout.elements[i].nonlinear)
            specimen = int(i);
    if (specimen < 0)
        return {};
    std::vector<int> out{specimen};
    const std::string& type = layout.elements[std::size_t(specimen)].type;
    for (std::size_t i = 0; i < layout.elements.size(); ++i) {
        const ElementInfo& e = layout.elements[i];
        if (int(i) != specimen && e.nonlinear && !e.experimental && e.type == type)
            out.push_back(int(i));
    }
    return out;
}

void HysteresisPlot::showElements(const RunLayout& layout, const std::vector<int>& elements) {
    clearPlottables();
    m_series.clear();
    for (std::size_t k = 0; k < elements.size(); ++k) {
        const ElementInfo& e = layout.elements[std::size_t(elements[k])];
        auto* curve = new QCPCurve(xAxis, yAxis);
        const QString name = QString::fromStdString(e.name);
        curve->setName(e.experimental ? tr("%1 (specimen, measured)").arg(name)
                                      : tr("%1 (numerical)").arg(name));
        curve->setPen(PlotStyle::seriesPen(int(k)));
        m_series.push_back({elements[k], curve});
    }
    if (!elements.empty()) {
        const ElementInfo& first = layout.elements[std::size_t(elements.front())];
        const bool rotational = first.units.deformation == "rad";
        const QString def = QString::fromStdString(first.units.deformation);
        const QString force = QString::fromStdString(first.units.force);
        xAxis->setLabel(rotational ? tr("Rotation [%1]").arg(def)
                                   : tr("Deformation [%1]").arg(def));
        yAxis->setLabel(rotational ? tr("Moment [%1]").arg(force) : tr("Force [%1]").arg(force));
        PlotStyle::setTitle(*this,
                            elements.size() == 1
                                ? tr("Hysteresis of %1").arg(QString::fromStdString(first.name))
                                : tr("Hysteresis: specimen and numerical twins"));
    }
    legend->setVisible(!m_series.empty());
    replot();
}

void HysteresisPlot::appendRecords(const std::vector<StepRecord>& records) {
    for (const Series& s : m_series) {
        QVector<double> t, x, y;
        t.reserve(qsizetype(records.size()));
        x.reserve(qsizetype(records.size()));
        y.reserve(qsizetype(records.size()));
        for (const StepRecord& r : records) {
            if (std::size_t(s.element) >= r.elements.size())
                continue;
            t.push_back(r.time);
            x.push_back(r.elements[std::size_t(s.element)].deformation);
            y.push_back(r.elements[std::size_t(s.element)].force);
        }
        s.curve->addData(t, x, y, true);
    }
}

void HysteresisPlot::clearData() {
    for (const Series& s : m_series)
        s.curve->data()->clear();
}

void HysteresisPlot::refresh() {
    PlotStyle::rescaleWithMargin(*this);
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace hsmu::gui
