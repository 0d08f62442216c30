#include "gui/plots/PlotTools.h"

#include "gui/plots/PlotStyle.h"

#include <QFile>
#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>
#include <QTextStream>

#include <qcustomplot.h>

#include <cmath>

namespace hsmu::gui {

namespace {
QString csvField(QString s) {
    if (s.contains(QLatin1Char(',')) || s.contains(QLatin1Char('"')))
        s = QLatin1Char('"') + s.replace(QLatin1String("\""), QLatin1String("\"\"")) +
            QLatin1Char('"');
    return s;
}
QString num(double v) {
    return QString::number(v, 'g', 6);
}
} // namespace

PlotTools::PlotTools(QCustomPlot& plot) : QObject(&plot), m_plot(plot) {
    setObjectName(QStringLiteral("plotTools"));
    m_plot.setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_plot.setContextMenuPolicy(Qt::CustomContextMenu);
    m_plot.setMouseTracking(true);
    m_label = new QCPItemText(&m_plot);
    m_label->setObjectName(QStringLiteral("cursorReadout"));
    m_label->setPositionAlignment(Qt::AlignTop | Qt::AlignRight);
    m_label->position->setType(QCPItemPosition::ptAxisRectRatio);
    m_label->position->setCoords(0.995, 0.01);
    m_label->setTextAlignment(Qt::AlignLeft);
    m_label->setBrush(QColor(255, 255, 255, 220));
    m_label->setPen(QPen(QColor(160, 160, 160)));
    m_label->setPadding(QMargins(4, 2, 4, 2));
    m_label->setClipToAxisRect(true);
    m_label->setVisible(false);
    connect(&m_plot, &QCustomPlot::mouseMove, this, &PlotTools::onMouseMove);
    connect(&m_plot, &QCustomPlot::mouseWheel, this, [this] { m_autoscale = false; });
    connect(&m_plot, &QCustomPlot::mouseDoubleClick, this, [this] { setAutoscale(true); });
    connect(&m_plot, &QWidget::customContextMenuRequested, this, [this](const QPoint& at) {
        QMenu* menu = buildMenu(&m_plot);
        menu->setAttribute(Qt::WA_DeleteOnClose);
        menu->popup(m_plot.mapToGlobal(at));
    });
}

PlotTools* PlotTools::attach(QCustomPlot& plot) {
    if (PlotTools* t = of(plot))
        return t;
    return new PlotTools(plot);
}

PlotTools* PlotTools::of(const QCustomPlot& plot) {
    return plot.findChild<PlotTools*>(QStringLiteral("plotTools"), Qt::FindDirectChildrenOnly);
}

bool PlotTools::autoscale(const QCustomPlot& plot) {
    const PlotTools* t = of(plot);
    return !t || t->autoscale();
}

void PlotTools::setAutoscale(bool on) {
    m_autoscale = on;
    if (on) {
        PlotStyle::rescaleWithMargin(m_plot);
        m_plot.replot(QCustomPlot::rpQueuedReplot);
    }
}

void PlotTools::setChannelVisible(int i, bool visible) {
    if (i < 0 || i >= m_plot.plottableCount())
        return;
    m_plot.plottable(i)->setVisible(visible);
    if (m_autoscale)
        PlotStyle::rescaleWithMargin(m_plot);
    m_plot.replot(QCustomPlot::rpQueuedReplot);
}

QString PlotTools::readout(double x, double y) const {
    QStringList lines{tr("x = %1, y = %2").arg(num(x), num(y))};
    for (int i = 0; i < m_plot.graphCount(); ++i) {
        const QCPGraph* g = m_plot.graph(i);
        if (!g->visible() || g->data()->isEmpty())
            continue;
        // the nearer of the samples either side of x (findBegin: the first key >= x)
        auto it = g->data()->findBegin(x, false);
        if (it == g->data()->constEnd() ||
            (it != g->data()->constBegin() && std::abs((it - 1)->key - x) < std::abs(it->key - x)))
            --it;
        lines << tr("%1: %2 at %3").arg(g->name(), num(it->value), num(it->key));
    }
    return lines.join(QLatin1Char('\n'));
}

QString PlotTools::cursorText() const {
    return m_label->visible() ? m_label->text() : QString();
}

void PlotTools::onMouseMove(QMouseEvent* event) {
    if (event->buttons() & Qt::LeftButton)
        m_autoscale = false; // a drag pans
    const QPointF p = event->position();
    const bool inside = m_plot.axisRect()->rect().contains(p.toPoint());
    m_label->setVisible(inside);
    if (inside)
        m_label->setText(readout(m_plot.xAxis->pixelToCoord(p.x()),
                                 m_plot.yAxis->pixelToCoord(p.y())));
    m_plot.replot(QCustomPlot::rpQueuedReplot);
}

bool PlotTools::exportVisibleCsv(const QString& path, QString* error, int* rows) const {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Text)) {
        if (error)
            *error = tr("%1: cannot be written (%2)").arg(path, file.errorString());
        return false;
    }
    QTextStream out(&file);
    const QCPRange xr = m_plot.xAxis->range();
    const QCPRange yr = m_plot.yAxis->range();
    out << "series," << csvField(m_plot.xAxis->label()) << ','
        << csvField(m_plot.yAxis->label()) << '\n';
    int n = 0;
    for (int i = 0; i < m_plot.plottableCount(); ++i) {
        QCPAbstractPlottable* p = m_plot.plottable(i);
        if (!p->visible())
            continue;
        const QString name = csvField(p->name());
        if (auto* g = qobject_cast<QCPGraph*>(p)) {
            for (auto it = g->data()->findBegin(xr.lower, false);
                 it != g->data()->constEnd() && it->key <= xr.upper; ++it) {
                if (it->key < xr.lower)
                    continue;
                out << name << ',' << num(it->key) << ',' << num(it->value) << '\n';
                ++n;
            }
        } else if (auto* c = qobject_cast<QCPCurve*>(p)) {
            for (auto it = c->data()->constBegin(); it != c->data()->constEnd(); ++it)
                if (xr.contains(it->key) && yr.contains(it->value)) {
                    out << name << ',' << num(it->key) << ',' << num(it->value) << '\n';
                    ++n;
                }
        }
    }
    out.flush();
    if (file.error() != QFileDevice::NoError) {
        if (error)
            *error = tr("%1: cannot be written (%2)").arg(path, file.errorString());
        return false;
    }
    if (rows)
        *rows = n;
    return true;
}

QMenu* PlotTools::buildMenu(QWidget* parent) {
    auto* menu = new QMenu(parent);
    menu->setObjectName(QStringLiteral("plotMenu"));
    QAction* autoscaleAction = menu->addAction(tr("Autoscale"));
    autoscaleAction->setCheckable(true);
    autoscaleAction->setChecked(m_autoscale);
    connect(autoscaleAction, &QAction::toggled, this, &PlotTools::setAutoscale);
    QMenu* channels = menu->addMenu(tr("Channels"));
    for (int i = 0; i < m_plot.plottableCount(); ++i) {
        QCPAbstractPlottable* p = m_plot.plottable(i);
        QAction* a = channels->addAction(p->name().isEmpty() ? tr("curve %1").arg(i + 1)
                                                             : p->name());
        a->setCheckable(true);
        a->setChecked(p->visible());
        connect(a, &QAction::toggled, this, [this, i](bool on) { setChannelVisible(i, on); });
    }
    menu->addSeparator();
    menu->addAction(tr("Export visible data as CSV..."), this, &PlotTools::exportWithDialog);
    return menu;
}

void PlotTools::exportWithDialog() {
    const QString path = QFileDialog::getSaveFileName(&m_plot, tr("Export visible data"),
                                                      QString(), tr("CSV files (*.csv)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!exportVisibleCsv(path, &error))
        QMessageBox::warning(&m_plot, tr("Export visible data"), error);
}

} // namespace hsmu::gui
