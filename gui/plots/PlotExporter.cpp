#include "gui/plots/PlotExporter.h"

#include "gui/plots/ActuatorsPanel.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/plots/ParameterPlot.h"
#include "gui/plots/PlotSelection.h"
#include "gui/plots/PlotStyle.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QPainter>
#include <QSvgGenerator>

#include <algorithm>
#include <memory>

namespace hsmu::gui {

namespace {
void layOut(QCustomPlot& plot, int width, int height) {
    plot.resize(width, height);
    PlotStyle::rescaleWithMargin(plot);
    plot.replot(QCustomPlot::rpImmediateRefresh);
}
bool nonEmptyFile(const QString& path) {
    return QFileInfo(path).size() > 0;
}
} // namespace

bool PlotExporter::savePng(QCustomPlot& plot, const QString& path, int width, int height) {
    layOut(plot, width, height);
    return plot.savePng(path, width, height);
}

bool PlotExporter::saveSvg(QCustomPlot& plot, const QString& path, int width, int height) {
    layOut(plot, width, height);
    QSvgGenerator svg;
    svg.setFileName(path);
    svg.setSize(QSize(width, height));
    svg.setViewBox(QRect(0, 0, width, height));
    svg.setTitle(QStringLiteral("HSMU Console plot")); // file metadata: hsmu-ui-literal-ok
    QCPPainter painter;
    if (!painter.begin(&svg))
        return false;
    plot.toPainter(&painter, width, height);
    painter.end();
    return nonEmptyFile(path);
}

bool PlotExporter::savePdf(QCustomPlot& plot, const QString& path, int width, int height) {
    layOut(plot, width, height);
    return plot.savePdf(path, width, height, QCP::epNoCosmetic, QStringLiteral("HSMU Console"),
                        QStringLiteral("HSMU Console plot")) &&
           nonEmptyFile(path);
}

bool PlotExporter::saveAs(QCustomPlot& plot, const QString& path, int width, int height,
                          QString* why) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    bool ok = false;
    if (suffix == QLatin1String("png"))
        ok = savePng(plot, path, width, height);
    else if (suffix == QLatin1String("svg"))
        ok = saveSvg(plot, path, width, height);
    else if (suffix == QLatin1String("pdf"))
        ok = savePdf(plot, path, width, height);
    else {
        if (why)
            *why = tr("%1: unknown plot format '%2' (expected png, svg or pdf)").arg(path, suffix);
        return false;
    }
    if (!ok && why)
        *why = tr("%1: the plot could not be written").arg(path);
    return ok;
}

bool PlotExporter::saveGridPng(const std::vector<QCustomPlot*>& plots, const QString& path,
                               int columns, int cellWidth, int cellHeight) {
    if (plots.empty() || columns < 1)
        return false;
    const int n = int(plots.size());
    const int rows = (n + columns - 1) / columns;
    QImage image(std::min(n, columns) * cellWidth, rows * cellHeight, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter painter(&image);
    for (int i = 0; i < n; ++i) {
        QCustomPlot& plot = *plots[std::size_t(i)];
        plot.resize(cellWidth, cellHeight);
        PlotStyle::rescaleWithMargin(plot);
        plot.replot(QCustomPlot::rpImmediateRefresh);
        painter.drawPixmap((i % columns) * cellWidth, (i / columns) * cellHeight,
                           plot.toPixmap(cellWidth, cellHeight));
    }
    painter.end();
    return image.save(path, "PNG");
}

QString PlotExporter::fileSafe(const QString& name) {
    QString out;
    for (const QChar c : name)
        out += (c.isLetterOrNumber() || c == QLatin1Char('-')) ? c : QLatin1Char('_');
    return out;
}

QStringList PlotExporter::writeRunPlots(const QString& dir, const RunLayout& layout,
                                        const std::vector<StepRecord>& records, QStringList* errors,
                                        const PlotReferences& references) {
    QStringList written;
    auto record = [&](bool ok, const QString& path) {
        if (ok)
            written << path;
        else if (errors)
            *errors << path;
    };
    // The console's own panel, laid out offscreen at a screen-like size.
    LivePlotsPanel panel;
    panel.setAttribute(Qt::WA_DontShowOnScreen);
    panel.configure(layout, references);
    panel.appendRecords(records);
    panel.resize(kPanelWidth, kPanelHeight);
    panel.show();
    QApplication::processEvents(); // layouts settle before the grab
    panel.refreshNow();
    QString path = QDir(dir).filePath(QStringLiteral("plots.png"));
    record(panel.grab().save(path, "PNG"), path);
    panel.hide();

    for (const LivePlotsPanel::NamedPlot& p : panel.plots()) {
        path = QDir(dir).filePath(p.fileBase + QStringLiteral(".png"));
        record(savePng(*p.plot, path), path);
    }
    std::vector<int> nonlinear;
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        if (layout.elements[i].nonlinear)
            nonlinear.push_back(int(i));
    for (const int element : spreadSubset(nonlinear, kMaxPlottedElements)) {
        const auto i = std::size_t(element);
        HysteresisPlot plot;
        plot.showElements(layout, {int(i)});
        plot.appendRecords(records);
        path =
            QDir(dir).filePath(QStringLiteral("hysteresis_%1.png")
                                   .arg(fileSafe(QString::fromStdString(layout.elements[i].name))));
        record(savePng(plot, path), path);
    }
    // Every basic DOF and actuator of the multi-DOF elements, one plot per group.
    ActuatorsPanel& actuators = panel.actuators();
    for (int g = 0; g < int(actuators.groups().size()); ++g) {
        actuators.showGroup(g);
        path = QDir(dir).filePath(
            QStringLiteral("channels_%1.png")
                .arg(fileSafe(QString::fromStdString(channelGroupName(actuators.groups()[std::size_t(g)])))));
        record(savePng(actuators.plot(), path), path);
    }
    if (!panel.parameterPlots().empty()) {
        std::vector<QCustomPlot*> cells(panel.parameterPlots().begin(),
                                        panel.parameterPlots().end());
        path = QDir(dir).filePath(QStringLiteral("parameters.png"));
        record(saveGridPng(cells, path, kGridColumns, kGridCellWidth, kGridCellHeight), path);
    }
    return written;
}

} // namespace hsmu::gui
