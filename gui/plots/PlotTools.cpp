#include "gui/plots/PlotTools.h"

#include "gui/plots/PlotStyle.h"

#include <QFile>
#include <QFileDialog>
#include <QFontMetrics>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QTextStream>

#include <qcustomplot.h>

#include <algorithm>
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
    // A widget over the plot, not a plot item: an opaque box that is never clipped by the
    // axis rect and costs no replot when it moves.
    m_label = new QLabel(&m_plot);
    m_label->setObjectName(QStringLiteral("cursorReadout"));
    m_label->setStyleSheet(QStringLiteral("QLabel#cursorReadout { background: white; color: "
                                          "black; border: 1px solid #a0a0a0; padding: 1px 4px; }"));
    m_label->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_label->setTextFormat(Qt::PlainText);
    m_label->hide();
    m_plot.installEventFilter(this);
    connect(&m_plot, &QCustomPlot::mouseMove, this, &PlotTools::onMouseMove);
    connect(&m_plot, &QCustomPlot::mouseWheel, this, [this] { m_autoscale = false; });
    connect(&m_plot, &QCustomPlot::mouseDoubleClick, this, [this] { setAutoscale(true); });
    // The plot's one context menu (an owner adds its entries through menuRequested()).
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
    if (!m_subject.isEmpty())
        lines.prepend(m_subject);
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
    return m_label->isHidden() ? QString() : m_readout;
}

void PlotTools::hideReadout() {
    m_label->hide();
    m_readout.clear();
}

bool PlotTools::eventFilter(QObject* watched, QEvent* event) {
    if (watched == &m_plot &&
        (event->type() == QEvent::Leave || event->type() == QEvent::Hide))
        hideReadout();
    return QObject::eventFilter(watched, event);
}

void PlotTools::onMouseMove(QMouseEvent* event) {
    if (event->buttons() & Qt::LeftButton)
        m_autoscale = false; // a drag pans
    const QPointF p = event->position();
    if (!m_plot.axisRect()->rect().contains(p.toPoint())) {
        hideReadout();
        return;
    }
    m_readout = readout(m_plot.xAxis->pixelToCoord(p.x()), m_plot.yAxis->pixelToCoord(p.y()));
    placeReadout();
    m_label->show();
    m_label->raise();
}

void PlotTools::placeReadout() {
    // Lines too long for the plot lose their middle (a name), never their numbers' ends.
    const QFontMetrics fm(m_label->font());
    const int room = std::max(40, m_plot.width() - 16);
    QStringList lines = m_readout.split(QLatin1Char('\n'));
    for (QString& line : lines)
        line = fm.elidedText(line, Qt::ElideMiddle, room);
    m_label->setText(lines.join(QLatin1Char('\n')));
    m_label->adjustSize();
    const QRect area = m_plot.axisRect()->rect();
    const int x = std::clamp(area.right() - m_label->width() - 2, 2,
                             std::max(2, m_plot.width() - m_label->width() - 2));
    const int y = std::clamp(area.top() + 2, 0, std::max(0, m_plot.height() - m_label->height()));
    m_label->move(x, y);
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
    emit menuRequested(menu);
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
