#include "gui/plots/ComparisonPlotExporter.h"

#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"
#include "gui/plots/ParameterPlot.h"
#include "gui/plots/PlotExporter.h"

#include <QDir>

#include <memory>

namespace hsmu::gui {

namespace {

QVector<double> vec(const std::vector<double>& x) {
    return QVector<double>(x.begin(), x.end());
}

/// Column i of a [step][parameter] history.
QVector<double> column(const std::vector<std::vector<double>>& rows, std::size_t i) {
    QVector<double> out;
    out.reserve(qsizetype(rows.size()));
    for (const auto& r : rows)
        out.push_back(i < r.size() ? r[i] : qQNaN());
    return out;
}

QString runLabel(const ComparisonRun& run) {
    if (run.name == "reference")
        return ComparisonPlotExporter::tr("reference");
    if (run.name == "initial")
        return ComparisonPlotExporter::tr("initial (not updated)");
    return ComparisonPlotExporter::tr("updated");
}

} // namespace

QStringList ComparisonPlotExporter::write(const QString& dir, const ComparisonResult& r,
                                          const ParameterValues& truth, QStringList* errors) {
    QStringList written;
    auto record = [&](bool ok, const QString& path) {
        if (ok)
            written << path;
        else if (errors)
            *errors << path;
    };
    const QDir out(dir);
    const QString element = QString::fromStdString(r.element);
    const QString dof = QString::fromStdString(r.dof);
    const QString forceUnit = QString::fromStdString(r.forceUnit);
    const bool rotational = r.deformationUnit == "rad";
    const std::vector<const ComparisonRun*> runs{&r.reference, &r.initial, &r.updated};

    // Fig. 10: parameter histories of the updated run.
    const ComparisonRun& u = r.updated;
    if (!u.parameterNames.empty() && !u.parameters.empty()) {
        std::vector<std::unique_ptr<ParameterPlot>> plots;
        std::vector<QCustomPlot*> cells;
        const QVector<double> time = vec(u.time);
        for (std::size_t i = 0; i < u.parameterNames.size(); ++i) {
            auto plot = std::make_unique<ParameterPlot>();
            plot->showParameter(QString::fromStdString(u.parameterNames[i]), int(i));
            plot->appendSamples(time, column(u.parameters, i), column(u.stddev, i));
            const auto t = truth.find(u.parameterNames[i]);
            plot->setTrueValue(t == truth.end() ? qQNaN() : t->second);
            plot->legend->setVisible(i == 0); // one legend for the grid
            cells.push_back(plot.get());
            plots.push_back(std::move(plot));
        }
        const QString path = out.filePath(QStringLiteral("parameters.png"));
        record(PlotExporter::saveGridPng(cells, path, PlotExporter::kGridColumns,
                                         PlotExporter::kGridCellWidth,
                                         PlotExporter::kGridCellHeight),
               path);
    }

    // Fig. 12: hysteresis of the compared element, three runs.
    HysteresisPlot loops;
    loops.setAxes(tr("Hysteresis of %1: reference, initial and updated").arg(element),
                  QString::fromStdString(r.deformationUnit), forceUnit);
    for (const ComparisonRun* run : runs)
        loops.addCurve(runLabel(*run), vec(run->deformation), vec(run->force));
    QString path =
        out.filePath(QStringLiteral("hysteresis_%1.png").arg(PlotExporter::fileSafe(element)));
    record(PlotExporter::savePng(loops, path), path);

    // Fig. 13: force history of the compared element.
    HistoryPlot force;
    force.setChannels(
        rotational ? tr("Moment history of %1").arg(element)
                   : tr("Force history of %1").arg(element),
        rotational ? tr("Moment [%1]").arg(forceUnit) : tr("Force [%1]").arg(forceUnit), {});
    for (const ComparisonRun* run : runs)
        force.addSeries(runLabel(*run), vec(run->time), vec(run->force));
    path = out.filePath(QStringLiteral("force_%1.png").arg(PlotExporter::fileSafe(element)));
    record(PlotExporter::savePng(force, path), path);

    // Fig. 14: displacement history of the compared DOF.
    HistoryPlot displacement;
    displacement.setChannels(tr("Displacement of %1").arg(dof), tr("Displacement [m]"), {});
    for (const ComparisonRun* run : runs)
        displacement.addSeries(runLabel(*run), vec(run->time), vec(run->displacement));
    path = out.filePath(QStringLiteral("displacement_%1.png").arg(PlotExporter::fileSafe(dof)));
    record(PlotExporter::savePng(displacement, path), path);
    return written;
}

} // namespace hsmu::gui
