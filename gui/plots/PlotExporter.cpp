#include "gui/plots/PlotExporter.h"

#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"
#include "gui/plots/PlotStyle.h"

#include <QDir>

namespace hsmu::gui {

bool PlotExporter::savePng(QCustomPlot& plot, const QString& path, int width, int height) {
    plot.resize(width, height);
    PlotStyle::rescaleWithMargin(plot);
    plot.replot(QCustomPlot::rpImmediateRefresh);
    return plot.savePng(path, width, height);
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
    return written;
}

} // namespace hsmu::gui
