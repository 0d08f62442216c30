#include "gui/plots/ParameterPlot.h"

#include "gui/app/LiveText.h"
#include "gui/plots/PlotStyle.h"

#include <algorithm>
#include <cmath>

namespace hsmu::gui {

ParameterPlot::ParameterPlot(QWidget* parent) : QCustomPlot(parent) {
    PlotStyle::apply(*this);
    yAxis->ticker()->setTickCount(3); // small cells: few, readable value labels
    xAxis->ticker()->setTickCount(3); // "12.515 17.5" ran together at 1280x720

    const QPen valuePen = PlotStyle::seriesPen(0);
    QColor band = valuePen.color();
    band.setAlpha(55);
    QColor edge = valuePen.color();
    edge.setAlpha(90);

    m_lower = addGraph(xAxis, yAxis);
    m_lower->setPen(QPen(edge, 0));
    m_lower->removeFromLegend();
    m_upper = addGraph(xAxis, yAxis);
    m_upper->setPen(QPen(edge, 0));
    m_upper->setBrush(band);
    m_upper->setChannelFillGraph(m_lower);
    m_value = addGraph(xAxis, yAxis);
    m_value->setPen(valuePen);
    m_true = addGraph(xAxis, yAxis);
    QPen truePen(QColor(60, 60, 60), 1.2, Qt::DashLine);
    m_true->setPen(truePen);
    m_true->removeFromLegend();
    const QPen boundPen(QColor(200, 30, 30), 1.0, Qt::DotLine);
    m_lowerBound = PlotStyle::addLine(*this, Qt::Horizontal, boundPen);
    m_upperBound = PlotStyle::addLine(*this, Qt::Horizontal, boundPen);
    legend->setVisible(true);
    QFont small = font();
    small.setPointSizeF(std::max(6.0, small.pointSizeF() - 1.5));
    legend->setFont(small);
    LiveText::bind(this, [this] {
        xAxis->setLabel(tr("Time [s]"));
        m_upper->setName(tr("± %1σ").arg(kBandSigmas));
        m_value->setName(tr("estimate"));
        m_true->setName(tr("true value"));
        replot(QCustomPlot::rpQueuedReplot);
    });
}

void ParameterPlot::showParameter(const QString& name, int index) {
    m_index = index;
    m_name = name;
    for (QCPGraph* g : m_overlays)
        removeGraph(g);
    m_overlays.clear();
    clearData();
    setTrueValue(qQNaN());
    yAxis->setLabel(name);
    PlotStyle::setTitle(*this, name);
    replot();
}

void ParameterPlot::setTrueValue(double value) {
    m_trueValue = value;
    if (std::isfinite(value))
        m_true->addToLegend();
    else
        m_true->removeFromLegend();
    updateTrueLine();
}

bool ParameterPlot::setBounds(double lower, double upper) {
    const double low = std::isfinite(lower) ? lower : qQNaN();
    const double high = std::isfinite(upper) ? upper : qQNaN();
    const auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
    if (same(low, m_boundLow) && same(high, m_boundHigh))
        return false;
    m_boundLow = low;
    m_boundHigh = high;
    PlotStyle::placeLine(*m_lowerBound, Qt::Horizontal, m_boundLow);
    PlotStyle::placeLine(*m_upperBound, Qt::Horizontal, m_boundHigh);
    return true;
}

void ParameterPlot::updateTrueLine() {
    m_true->data()->clear();
    if (!std::isfinite(m_trueValue) || m_value->data()->isEmpty())
        return;
    const double t0 = m_value->data()->constBegin()->key;
    const double t1 = (m_value->data()->constEnd() - 1)->key;
    m_true->addData({t0, t1}, {m_trueValue, m_trueValue}, true);
}

void ParameterPlot::appendRecords(const std::vector<StepRecord>& records) {
    QVector<double> t, v, s;
    const auto i = std::size_t(m_index);
    for (const StepRecord& r : records) {
        if (!r.hasUpdating || i >= r.updating.parameters.size())
            continue;
        t.push_back(r.time);
        v.push_back(r.updating.parameters[i]);
        s.push_back(i < r.updating.stddev.size() ? r.updating.stddev[i] : 0.0);
    }
    appendSamples(t, v, s);
}

void ParameterPlot::appendSamples(const QVector<double>& time, const QVector<double>& value,
                                  const QVector<double>& sigma) {
    const qsizetype n = std::min({time.size(), value.size(), sigma.size()});
    QVector<double> t(time.begin(), time.begin() + n), v(value.begin(), value.begin() + n);
    QVector<double> lo(n), hi(n);
    for (qsizetype k = 0; k < n; ++k) {
        lo[k] = v[k] - kBandSigmas * sigma[k];
        hi[k] = v[k] + kBandSigmas * sigma[k];
    }
    m_value->addData(t, v, true);
    m_lower->addData(t, lo, true);
    m_upper->addData(t, hi, true);
    updateTrueLine();
}

void ParameterPlot::clearData() {
    for (QCPGraph* g : {m_value, m_lower, m_upper, m_true})
        g->data()->clear();
}

void ParameterPlot::setOverlay(const QString& name, const QVector<double>& time,
                               const QVector<double>& values) {
    auto* g = const_cast<QCPGraph*>(overlayGraph(name));
    if (!g) {
        g = addGraph(xAxis, yAxis);
        QPen pen = PlotStyle::seriesPen(int(m_overlays.size()) + 2); // not the estimate's, not red
        pen.setStyle(Qt::DashLine);
        g->setPen(pen);
        g->setName(name);
        g->removeFromLegend(); // named by the owner's note (LivePlotsPanel): no third legend row
        m_overlays.push_back(g);
    }
    g->setData(time, values, true);
}

const QCPGraph* ParameterPlot::overlayGraph(const QString& name) const {
    for (QCPGraph* g : m_overlays)
        if (g->name() == name)
            return g;
    return nullptr;
}

void ParameterPlot::refresh() {
    PlotStyle::rescaleWithMargin(*this);
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace hsmu::gui
