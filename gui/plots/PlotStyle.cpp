#include "gui/plots/PlotStyle.h"

#include <qcustomplot.h>

#include <array>

namespace hsmu::gui {

namespace {

void padRange(QCPAxis* axis) {
    QCPRange r = axis->range();
    double span = r.size();
    if (!(span > 0.0))
        span = std::max(1e-6, std::abs(r.center()));
    axis->setRange(r.lower - 0.05 * span, r.upper + 0.05 * span);
}

} // namespace

void PlotStyle::apply(QCustomPlot& plot) {
    plot.setBackground(Qt::white);
    plot.setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot.setNoAntialiasingOnDrag(true);
    plot.legend->setVisible(false);
    plot.legend->setBrush(QColor(255, 255, 255, 220));
    plot.legend->setBorderPen(QPen(QColor(180, 180, 180)));
    plot.axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    for (QCPAxis* axis : {plot.xAxis, plot.yAxis}) {
        axis->grid()->setSubGridVisible(false);
        axis->grid()->setPen(QPen(QColor(220, 220, 220), 0, Qt::DotLine));
        axis->grid()->setZeroLinePen(QPen(QColor(150, 150, 150), 0));
    }
    plot.setMinimumSize(240, 180);
}

QPen PlotStyle::seriesPen(int i) {
    static const std::array<QColor, 6> palette{QColor(31, 119, 180),  QColor(214, 39, 40),
                                               QColor(44, 160, 44),   QColor(255, 127, 14),
                                               QColor(148, 103, 189), QColor(140, 86, 75)};
    QPen pen(palette[std::size_t(i) % palette.size()]);
    pen.setWidthF(i == 0 ? 1.8 : 1.3);
    return pen;
}

void PlotStyle::setTitle(QCustomPlot& plot, const QString& title) {
    if (auto* existing = qobject_cast<QCPTextElement*>(plot.plotLayout()->element(0, 0))) {
        existing->setText(title);
        return;
    }
    plot.plotLayout()->insertRow(0);
    auto* element = new QCPTextElement(&plot, title, QFont(plot.font().family(), 11, QFont::Bold));
    plot.plotLayout()->addElement(0, 0, element);
}

void PlotStyle::rescaleWithMargin(QCustomPlot& plot) {
    plot.rescaleAxes();
    padRange(plot.xAxis);
    padRange(plot.yAxis);
}

} // namespace hsmu::gui
