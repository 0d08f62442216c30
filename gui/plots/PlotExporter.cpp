#include "gui/plots/PlotExporter.h"

#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"
#include "gui/plots/ParameterPlot.h"
#include "gui/plots/PlotStyle.h"

#include <QDir>
#include <QImage>
#include <QPainter>

#include <algorithm>
#include <memory>

namespace hsmu::gui {

bool PlotExporter::savePng(QCustomPlot& plot, const QString& path, int width, int height) {
    plot.resize(width, height);
    PlotStyle::rescaleWithMargin(plot);
    plot.replot(QCustomPlot::rpImmediateRefresh);
    return plot.savePng(path, width, height);
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
                                        const std::vector<StepRecord>& records,
                                        QStringList* errors) {
    QStringList written;
    auto save = [&](QCustomPlot& plot, const QString& file) {
        const QString path = QDir(dir).filePath(file);
        if (savePng(plot, path))
            written << path;
        else if (errors)
            *errors << path;
    };
    for (std::size_t i = 0; i < layout.elements.size(); ++i) {
        if (!layout.elements[i].nonlinear)
            continue;
        HysteresisPlot plot;
        plot.showElements(layout, {int(i)});
        plot.appendRecords(records);
        save(plot, QStringLiteral("hysteresis_%1.png")
                       .arg(fileSafe(QString::fromStdString(layout.elements[i].name))));
    }
    HistoryPlot displacement;
    displacement.showDisplacements(layout);
    displacement.appendRecords(records);
    save(displacement, QStringLiteral("displacement.png"));

    HistoryPlot ground;
    ground.showGroundAcceleration();
    ground.appendRecords(records);
    save(ground, QStringLiteral("ground_motion.png"));

    if (layout.updating && !layout.updating->parameters.empty()) {
        std::vector<std::unique_ptr<ParameterPlot>> plots;
        std::vector<QCustomPlot*> cells;
        for (std::size_t i = 0; i < layout.updating->parameters.size(); ++i) {
            auto plot = std::make_unique<ParameterPlot>();
            plot->showParameter(QString::fromStdString(layout.updating->parameters[i]), int(i));
            plot->appendRecords(records);
            plot->legend->setVisible(i == 0); // one legend for the grid
            cells.push_back(plot.get());
            plots.push_back(std::move(plot));
        }
        const QString path = QDir(dir).filePath(QStringLiteral("parameters.png"));
        if (saveGridPng(cells, path, kGridColumns, kGridCellWidth, kGridCellHeight))
            written << path;
        else if (errors)
            *errors << path;
    }
    return written;
}

} // namespace hsmu::gui
