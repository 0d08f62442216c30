#include "gui/plots/RthsPlots.h"

#include "gui/plots/PlotStyle.h"
#include "gui/plots/PlotTools.h"

#include <QEvent>

namespace hsmu::gui {

SynchronizationPlot::SynchronizationPlot(QWidget* parent) : QCustomPlot(parent)
{
    PlotStyle::apply(*this);
    m_curve = new QCPCurve(xAxis, yAxis);
    m_curve->setPen(PlotStyle::seriesPen(0));
    QPen ideal(Qt::gray, 1, Qt::DashLine);
    m_ideal = new QCPItemStraightLine(this);
    m_ideal->setPen(ideal);
    m_ideal->point1->setCoords(0.0, 0.0);
    m_ideal->point2->setCoords(1.0, 1.0);
    m_ideal->setSelectable(false);
    setMinimumSize(260, 220);
    retranslate();
}

void SynchronizationPlot::retranslate()
{
    PlotStyle::setTitle(*this, tr("Synchronization: measured against desired"));
    xAxis->setLabel(tr("desired displacement y [mm]"));
    yAxis->setLabel(tr("measured displacement xm [mm]"));
    m_curve->setName(tr("measured"));
    replot(QCustomPlot::rpQueuedReplot);
}

void SynchronizationPlot::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QCustomPlot::changeEvent(event);
}

void SynchronizationPlot::append(double desired, double measured)
{
    m_curve->addData(desired * 1e3, measured * 1e3);
}

void SynchronizationPlot::clearData()
{
    m_curve->data()->clear();
}

int SynchronizationPlot::points() const
{
    return m_curve->dataCount();
}

void SynchronizationPlot::refresh()
{
    if (PlotTools::autoscale(*this)) {
        PlotStyle::rescaleWithMargin(*this);
        // One scale on both axes: the line xm = y at 45 degrees, the loop's shape undistorted.
        const QCPRange x = xAxis->range(), y = yAxis->range();
        const QCPRange both(std::min(x.lower, y.lower), std::max(x.upper, y.upper));
        xAxis->setRange(both);
        yAxis->setRange(both);
    }
    replot(QCustomPlot::rpQueuedReplot);
}

TrackingHistoryPlot::TrackingHistoryPlot(QWidget* parent) : QCustomPlot(parent)
{
    PlotStyle::apply(*this);
    yAxis2->setVisible(true);
    m_delay = addGraph(xAxis, yAxis);
    m_delay->setPen(PlotStyle::seriesPen(0));
    m_amplitude = addGraph(xAxis, yAxis2);
    m_amplitude->setPen(PlotStyle::seriesPen(1));
    m_warning = PlotStyle::addLine(*this, Qt::Horizontal, QPen(QColor(230, 150, 0), 1, Qt::DashLine));
    m_critical = PlotStyle::addLine(*this, Qt::Horizontal, QPen(QColor(200, 0, 0), 1, Qt::DashLine));
    setMinimumSize(260, 180);
    retranslate();
}

void TrackingHistoryPlot::retranslate()
{
    PlotStyle::setTitle(*this, tr("Delay and amplitude error (moving window)"));
    xAxis->setLabel(tr("time [s]"));
    yAxis->setLabel(tr("delay [ms]"));
    yAxis2->setLabel(tr("amplitude error [%]"));
    m_delay->setName(tr("delay [ms]"));
    m_amplitude->setName(tr("amplitude error [%]"));
    replot(QCustomPlot::rpQueuedReplot);
}

void TrackingHistoryPlot::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QCustomPlot::changeEvent(event);
}

void TrackingHistoryPlot::append(double time, double delay, double amplitudeError)
{
    m_delay->addData(time, delay);
    m_amplitude->addData(time, amplitudeError);
}

void TrackingHistoryPlot::setDelayThresholds(double warning, double critical)
{
    PlotStyle::placeLine(*m_warning, Qt::Horizontal, warning);
    PlotStyle::placeLine(*m_critical, Qt::Horizontal, critical);
    replot(QCustomPlot::rpQueuedReplot);
}

void TrackingHistoryPlot::clearData()
{
    m_delay->data()->clear();
    m_amplitude->data()->clear();
}

int TrackingHistoryPlot::points() const
{
    return m_delay->dataCount();
}

void TrackingHistoryPlot::refresh()
{
    if (PlotTools::autoscale(*this)) {
        PlotStyle::rescaleWithMargin(*this);
        m_amplitude->rescaleValueAxis();
        PlotStyle::includeInRange(*yAxis2, 0.0);
    }
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace hsmu::gui
