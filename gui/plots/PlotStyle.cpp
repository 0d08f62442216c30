#include "gui/plots/PlotStyle.h"

#include "gui/plots/PlotTools.h"

#include <qcustomplot.h>

#include <algorithm>

#include <array>
#include <cmath>
#include <limits>

namespace hsmu::gui {

namespace {

void padRange(QCPAxis* axis) {
    QCPRange r = axis->range();
    double span = r.size();
    if (!(span > 0.0))
        span = std::max(1e-6, std::abs(r.center()));
    axis->setRange(r.lower - 0.05 * span, r.upper + 0.05 * span);
}

const char* fullLabelKey(const QCPAxis& axis) {
    switch (axis.axisType()) {
    case QCPAxis::atLeft: return "hsmuLabelLeft";
    case QCPAxis::atRight: return "hsmuLabelRight";
    case QCPAxis::atTop: return "hsmuLabelTop";
    case QCPAxis::atBottom: break;
    }
    return "hsmuLabelBottom";
}

// An axis label longer than its axis (a long translation along a short plot) is cut with
// "..." instead of being clipped at both ends; the full label is kept (PlotStyle::axisLabel)
// and goes to the plot's tool tip. A label set since the last replot is the new full label.
void elideAxisLabel(QCustomPlot& plot, QCPAxis& axis, QStringList& cut) {
    const char* fullKey = fullLabelKey(axis);
    const QByteArray shownKey = QByteArray(fullKey) + "Shown";
    const QString current = axis.label();
    if (current != plot.property(shownKey.constData()).toString())
        plot.setProperty(fullKey, current);
    const QString full = plot.property(fullKey).toString();
    const int length = PlotStyle::labelRoom(plot, axis);
    const QString shown = QFontMetrics(axis.labelFont())
                              .elidedText(full, Qt::ElideRight, std::max(30, length - 4));
    plot.setProperty(shownKey.constData(), shown);
    if (shown != current)
        axis.setLabel(shown);
    if (shown != full)
        cut << full;
}

// The plot's tool tip: the whole texts of a cut title and of cut axis labels.
void showCutTexts(QCustomPlot& plot) {
    QStringList tip = plot.property("hsmuCutLabels").toStringList();
    const QString title = plot.property("hsmuCutTitle").toString();
    if (!title.isEmpty())
        tip.prepend(title);
    plot.setToolTip(tip.join(QLatin1Char('\n')));
}

// As many ticks as the axis rect has room for without their labels running together (a
// small plot at 1280x720 over a short time: "0 0.0250.050.075 0.1"); never more than the plot
// asked for. Horizontal labels need their width, vertical ones their height, plus a gap.
void fitTickCount(QCPAxis& axis) {
    if (!axis.visible() || !axis.tickLabels() || !axis.axisRect())
        return;
    if (!axis.property("hsmuMaxTicks").isValid())
        axis.setProperty("hsmuMaxTicks", axis.ticker()->tickCount());
    const int most = axis.property("hsmuMaxTicks").toInt();
    const bool horizontal = axis.orientation() == Qt::Horizontal;
    const QRect r = axis.axisRect()->rect();
    const double room = horizontal ? r.width() : r.height();
    const double span = axis.range().size();
    if (!(room > 0.0) || !(span > 0.0))
        return;
    const QFontMetrics fm(axis.tickLabelFont());
    const QString format = axis.numberFormat();
    // The most ticks that fit, preferring two or more labels inside the range (one label
    // says nothing about the scale); at worst one tick.
    int chosen = 1, chosenInside = 0;
    for (int n = most; n >= 1; --n) {
        axis.ticker()->setTickCount(n);
        QVector<double> ticks;
        QVector<QString> labels;
        axis.ticker()->generate(axis.range(), axis.parentPlot()->locale(),
                                format.isEmpty() ? QLatin1Char('g') : format.at(0),
                                axis.numberPrecision(), ticks, nullptr, &labels);
        int needed = 0, inside = 0;
        for (qsizetype i = 0; i < ticks.size(); ++i) {
            if (!axis.range().contains(ticks[i]))
                continue;
            ++inside;
            needed = std::max(needed, horizontal ? fm.horizontalAdvance(labels[i]) : fm.ascent());
        }
        double gap = room;
        for (qsizetype i = 1; i < ticks.size(); ++i)
            gap = std::min(gap, room * std::abs(ticks[i] - ticks[i - 1]) / span);
        const bool fits = gap >= needed + (horizontal ? 8 : 2);
        if (fits && (inside >= 2 || chosenInside == 0) && inside > chosenInside) {
            chosen = n;
            chosenInside = inside;
            if (inside >= 2)
                break;
        }
    }
    axis.ticker()->setTickCount(chosen);
}

QCPTextElement* titleOf(const QCustomPlot& plot) {
    return qobject_cast<QCPTextElement*>(plot.property("hsmuTitleElement").value<QObject*>());
}

// As many legend columns as fit `width` (one row when they all fit): a legend wider than its
// plot would widen the layout past the widget and cut the traces' right edge.
void fitLegendColumns(QCPLegend& legend, int width) {
    const int items = legend.itemCount();
    for (int columns = items; columns >= 1; --columns) {
        legend.setWrap(columns);
        legend.setFillOrder(QCPLayoutGrid::foColumnsFirst, true); // rearranged
        if (legend.minimumOuterSizeHint().width() <= width)
            return;
    }
}

void takeLegend(QCPLegend& legend) {
    if (QCPLayout* from = legend.layout()) {
        from->take(&legend);
        from->simplify();
    }
}

// Where a legend goes: never over the traces. Shown: beside the title when both fit on its
// row (no height taken from the data), else in the plot layout's last row under the axis rect
// (its columns fitted to the width; it never asks for more width than the plot has). Hidden:
// back in the axis rect's inset layout, which reserves no room (a grid row would keep the
// hidden legend's height), so the plot still owns it. A legend of one entry under a title
// says what the title says: it is not shown.
void placeLegend(QCustomPlot& plot) {
    QCPLegend* legend = plot.legend;
    QCPLayoutGrid* grid = plot.plotLayout();
    QCPLayoutInset* inset = plot.axisRect()->insetLayout();
    QCPTextElement* title = titleOf(plot);
    const bool shown = legend->visible() && legend->itemCount() > 0 &&
                       (legend->itemCount() > 1 || !title);
    if (!shown) {
        if (legend->layout() != inset) {
            takeLegend(*legend);
            inset->addElement(legend, Qt::AlignTop | Qt::AlignRight);
        }
        legend->setVisible(false); // never drawn over the traces
        return;
    }
    auto* head = title ? qobject_cast<QCPLayoutGrid*>(title->layout()) : nullptr;
    bool beside = false;
    if (head) {
        legend->setMinimumSize(0, 0); // its own width, beside the title
        fitLegendColumns(*legend, QWIDGETSIZE_MAX); // one row
        const int titleWidth = QFontMetrics(title->font())
                                   .horizontalAdvance(plot.property("hsmuTitle").toString());
        beside = legend->minimumOuterSizeHint().width() + titleWidth + 24 <= plot.width();
    }
    if (beside) {
        if (legend->layout() != head) {
            takeLegend(*legend);
            head->addElement(0, 1, legend);
            head->setColumnStretchFactor(1, 0.001);
        }
        return;
    }
    legend->setMinimumSize(1, 0); // the plot's minimum width stays the axis rect's
    fitLegendColumns(*legend, plot.width() - 8);
    if (legend->layout() != grid) {
        takeLegend(*legend);
        const int row = grid->rowCount();
        grid->addElement(row, 0, legend);
        grid->setRowStretchFactor(row, 0.001);
    }
}

} // namespace

int PlotStyle::labelRoom(const QCustomPlot& plot, const QCPAxis& axis) {
    // A label is centred on its axis and may reach into the margins (title, tick labels)
    // but not past the plot's edges.
    const QRect r = plot.axisRect()->rect();
    if (axis.orientation() == Qt::Vertical) {
        // Up into the title row only beside the title's text (es: "Error de ajuste [-]" ran
        // over "Error de ajuste del inspector"), never down into a legend row.
        const QRect cell = plot.axisRect()->outerRect();
        int top = 0, bottom = plot.height();
        if (const QCPTextElement* title = titleOf(plot)) {
            const int half = QFontMetrics(title->font()).horizontalAdvance(title->text()) / 2;
            const int centre = title->outerRect().center().x();
            const bool beside = axis.axisType() == QCPAxis::atLeft ? centre - half > r.left()
                                                                   : centre + half < r.right();
            if (!beside)
                top = cell.top();
        }
        if (plot.legend->visible() && plot.legend->layout() == plot.plotLayout())
            bottom = cell.bottom();
        const int c = r.center().y();
        return 2 * std::min(c - top, bottom - c);
    }
    const int c = r.center().x();
    return 2 * std::min(c, plot.width() - c);
}

QString PlotStyle::axisLabel(const QCustomPlot& plot, const QCPAxis& axis) {
    const QByteArray shownKey = QByteArray(fullLabelKey(axis)) + "Shown";
    // Not yet drawn, or set again since: the label itself.
    if (axis.label() != plot.property(shownKey.constData()).toString())
        return axis.label();
    return plot.property(fullLabelKey(axis)).toString();
}

void PlotStyle::apply(QCustomPlot& plot) {
    plot.setBackground(Qt::white);
    plot.setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot.setNoAntialiasingOnDrag(true);
    plot.setPlottingHint(QCP::phFastPolylines, true); // thousands of points per live curve
    plot.setNotAntialiasedElements(QCP::aeFills);
    plot.legend->setVisible(false);
    // A visible legend is a row of its own under the axis rect, never over the traces (at
    // 1280x720 a see-through legend inside the axis rect still hid part of them).
    plot.legend->setBrush(Qt::NoBrush);
    plot.legend->setBorderPen(Qt::NoPen);
    QFont legendFont = plot.font();
    legendFont.setPointSizeF(std::max(6.0, legendFont.pointSizeF() - 2.0));
    plot.legend->setFont(legendFont);
    plot.legend->setIconSize(16, 8);
    plot.legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    plot.legend->setRowSpacing(0);
    plot.legend->setColumnSpacing(8);
    plot.legend->setMargins(QMargins(4, 0, 4, 0));
    QObject::connect(&plot, &QCustomPlot::beforeReplot, &plot, [&plot] { placeLegend(plot); });
    for (QCPAxis* axis : {plot.xAxis, plot.yAxis}) {
        axis->grid()->setSubGridVisible(false);
        axis->grid()->setPen(QPen(QColor(220, 220, 220), 0, Qt::DotLine));
        axis->grid()->setZeroLinePen(QPen(QColor(150, 150, 150), 0));
    }
    plot.setMinimumSize(240, 180);
    // A short cell (the replay's tracking plot, 110 px) still fits its title, axes and a
    // two-row legend: the data area may shrink to 30 px rather than push the legend out.
    plot.axisRect()->setMinimumSize(50, 30);
    // After the layout step of each replot (the axis rect as it will be drawn; a cut label
    // keeps its thickness, so the layout stays valid).
    QObject::connect(&plot, &QCustomPlot::afterLayout, &plot, [&plot] {
        for (QCPAxis* axis : {plot.xAxis, plot.yAxis, plot.yAxis2})
            fitTickCount(*axis);
        QStringList cut;
        for (QCPAxis* axis : {plot.xAxis, plot.yAxis, plot.yAxis2})
            if (axis->visible())
                elideAxisLabel(plot, *axis, cut);
        plot.setProperty("hsmuCutLabels", cut);
        showCutTexts(plot);
    });
    PlotTools::attach(plot); // cursor read-out, zoom / pan, autoscale, channels, CSV export
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
    plot.setProperty("hsmuTitle", title);
    if (auto* existing = titleOf(plot)) {
        existing->setText(title);
        return;
    }
    plot.plotLayout()->insertRow(0);
    // The title row: the title, and the legend beside it when both fit (placeLegend).
    auto* head = new QCPLayoutGrid;
    plot.plotLayout()->addElement(0, 0, head);
    head->setColumnSpacing(8);
    // 10 pt: the longest title fits a plot cell at 1280x720.
    auto* element = new QCPTextElement(&plot, title, QFont(plot.font().family(), 10, QFont::Bold));
    head->addElement(0, 0, element);
    plot.setProperty("hsmuTitleElement", QVariant::fromValue<QObject*>(element));
    // A title wider than its plot (a narrow cell, a long translation) is cut with "...", the
    // full title in the plot's tool tip.
    QObject::connect(&plot, &QCustomPlot::beforeReplot, element, [&plot, element] {
        const QString full = plot.property("hsmuTitle").toString();
        const QString shown = QFontMetrics(element->font())
                                  .elidedText(full, Qt::ElideRight, std::max(40, plot.width() - 12));
        if (element->text() != shown)
            element->setText(shown);
        plot.setProperty("hsmuCutTitle", shown == full ? QString() : full);
        showCutTexts(plot);
    });
}

bool PlotStyle::hasData(const QCustomPlot& plot) {
    for (int i = 0; i < plot.plottableCount(); ++i) {
        QCPAbstractPlottable* p = const_cast<QCustomPlot&>(plot).plottable(i); // no const getter
        if (p->visible() && p->interface1D() && p->interface1D()->dataCount() > 0)
            return true;
    }
    return false;
}

void PlotStyle::setEmptyXRange(QCustomPlot& plot, double lower, double upper) {
    plot.setProperty("hsmuEmptyX", upper > lower ? QVariant(QPointF(lower, upper)) : QVariant());
}

namespace {
// Before the first point: the references, not QCustomPlot's 0..5 (issue 25 item 16).
void showReferences(QCustomPlot& plot) {
    const QVariant x = plot.property("hsmuEmptyX");
    plot.xAxis->setRange(x.isValid() ? QCPRange(x.toPointF().x(), x.toPointF().y())
                                     : QCPRange(0.0, 1.0));
    plot.xAxis->setTickLabels(x.isValid());
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int i = 0; i < plot.itemCount(); ++i) {
        const auto* line = qobject_cast<QCPItemStraightLine*>(plot.item(i));
        if (line && line->visible() && line->point1->coords().y() == line->point2->coords().y()) {
            lo = std::min(lo, line->point1->coords().y());
            hi = std::max(hi, line->point1->coords().y());
        }
    }
    const bool known = std::isfinite(lo);
    if (known && lo == hi) { // a threshold alone: from 0 to it
        lo = std::min(lo, 0.0);
        hi = std::max(hi, 0.0);
    }
    const double span = known && hi > lo ? hi - lo : 1.0;
    plot.yAxis->setRange(known ? QCPRange(lo - 0.25 * span, hi + 0.25 * span) : QCPRange(-1, 1));
    plot.yAxis->setTickLabels(known);
    plot.yAxis2->setTickLabels(false);
}

// The span of the visible data along x (keys) or along a y axis (values: the left one unless
// `values` names another).
QCPRange dataSpan(QCustomPlot& plot, bool keys, bool& found, const QCPAxis* values = nullptr) {
    QCPRange out;
    found = false;
    const QCPAxis* axis = values ? values : plot.yAxis;
    for (int i = 0; i < plot.plottableCount(); ++i) {
        QCPAbstractPlottable* p = plot.plottable(i);
        if (!p->visible() || (!keys && p->valueAxis() != axis))
            continue;
        bool ok = false;
        const QCPRange r = keys ? p->getKeyRange(ok) : p->getValueRange(ok);
        if (!ok)
            continue;
        out = found ? QCPRange(std::min(out.lower, r.lower), std::max(out.upper, r.upper)) : r;
        found = true;
    }
    return out;
}

// The horizontal reference lines' y values (thresholds, bounds) widen [lo, hi].
void includeLines(const QCustomPlot& plot, double& lo, double& hi) {
    for (int i = 0; i < plot.itemCount(); ++i) {
        const auto* line = qobject_cast<QCPItemStraightLine*>(plot.item(i));
        if (line && line->visible() && line->point1->coords().y() == line->point2->coords().y()) {
            lo = std::min(lo, line->point1->coords().y());
            hi = std::max(hi, line->point1->coords().y());
        }
    }
}

// A single sample (the first row, a replay at step 0): QCustomPlot centres a span of its own
// on it (-3..3 s). Time goes over the test's span when it is known; a flat value over its
// reference lines, else +-1 (or +-50 %) around it.
void fitSingleSample(QCustomPlot& plot) {
    bool found = false;
    const QCPRange keys = dataSpan(plot, true, found);
    if (found && !(keys.size() > 0.0)) {
        const QVariant x = plot.property("hsmuEmptyX");
        const QCPRange span = x.isValid() ? QCPRange(x.toPointF().x(), x.toPointF().y())
                                          : QCPRange(keys.lower - 0.5, keys.lower + 0.5);
        plot.xAxis->setRange(span.contains(keys.lower) ? span
                                                       : QCPRange(keys.lower - 0.5, keys.lower + 0.5));
        plot.xAxis->setTickLabels(x.isValid()); // nothing to scale by: no made-up numbers
    }
    const QCPRange values = dataSpan(plot, false, found);
    if (found && !(values.size() > 0.0)) {
        double lo = values.lower, hi = values.upper;
        includeLines(plot, lo, hi);
        if (hi > lo) {
            const double pad = 0.25 * (hi - lo);
            plot.yAxis->setRange(lo - pad, hi + pad);
        } else {
            const double half = lo == 0.0 ? 1.0 : 0.5 * std::abs(lo);
            plot.yAxis->setRange(lo - half, lo + half);
            plot.yAxis->setTickLabels(false); // one value, no reference: nothing to scale by
        }
    }
    if (plot.yAxis2->visible()) { // e.g. the held ticks beside the tracking: one value, no scale
        const QCPRange right = dataSpan(plot, false, found, plot.yAxis2);
        if (!found) // no finite value yet (a control that reports no held ticks): no numbers
            plot.yAxis2->setTickLabels(false);
        else if (!(right.size() > 0.0)) {
            const double half = right.lower == 0.0 ? 1.0 : 0.5 * std::abs(right.lower);
            plot.yAxis2->setRange(right.lower - half, right.lower + half);
            plot.yAxis2->setTickLabels(false);
        }
    }
}
} // namespace

void PlotStyle::rescaleWithMargin(QCustomPlot& plot) {
    if (!PlotTools::autoscale(plot))
        return; // the operator's zoom / pinned window stays
    if (!hasData(plot)) {
        showReferences(plot);
        return;
    }
    for (QCPAxis* axis : {plot.xAxis, plot.yAxis, plot.yAxis2})
        axis->setTickLabels(true);
    plot.rescaleAxes(true); // visible channels only
    padRange(plot.xAxis);
    padRange(plot.yAxis);
    // Visible horizontal reference lines (thresholds, bounds) stay in view.
    for (int i = 0; i < plot.itemCount(); ++i) {
        const auto* line = qobject_cast<QCPItemStraightLine*>(plot.item(i));
        if (line && line->visible() && line->point1->coords().y() == line->point2->coords().y())
            includeInRange(*plot.yAxis, line->point1->coords().y());
    }
    fitSingleSample(plot);
}

QCPItemStraightLine* PlotStyle::addLine(QCustomPlot& plot, Qt::Orientation orientation,
                                        const QPen& pen) {
    auto* line = new QCPItemStraightLine(&plot);
    line->setPen(pen);
    line->setClipToAxisRect(true);
    placeLine(*line, orientation, qQNaN());
    return line;
}

void PlotStyle::placeLine(QCPItemStraightLine& line, Qt::Orientation orientation, double value) {
    line.setVisible(std::isfinite(value));
    if (!std::isfinite(value))
        return;
    if (orientation == Qt::Horizontal) {
        line.point1->setCoords(0.0, value);
        line.point2->setCoords(1.0, value);
    } else {
        line.point1->setCoords(value, 0.0);
        line.point2->setCoords(value, 1.0);
    }
}

void PlotStyle::includeInRange(QCPAxis& axis, double value) {
    if (!std::isfinite(value))
        return;
    QCPRange r = axis.range();
    if (value >= r.lower && value <= r.upper)
        return;
    const double lower = std::min(r.lower, value), upper = std::max(r.upper, value);
    const double pad = 0.05 * (upper - lower);
    axis.setRange(value < r.lower ? lower - pad : lower, value > r.upper ? upper + pad : upper);
}

} // namespace hsmu::gui
