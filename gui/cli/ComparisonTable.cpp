#include "gui/cli/ComparisonTable.h"

#include <QStringList>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hsmu::gui {

namespace {

QString num(double x, int digits) {
    return QString::number(x, 'g', digits);
}

QString percent(double x) {
    return std::isfinite(x) ? QString::number(100.0 * x, 'f', 2) + QStringLiteral(" %")
                            : QStringLiteral("-");
}

/// Rows of cells, the first the header: columns padded to their widest cell, text left,
/// numbers right.
QString aligned(const std::vector<QStringList>& rows) {
    std::vector<int> width;
    for (const QStringList& r : rows)
        for (int c = 0; c < r.size(); ++c) {
            if (std::size_t(c) >= width.size())
                width.resize(std::size_t(c) + 1, 0);
            width[std::size_t(c)] = std::max(width[std::size_t(c)], int(r[c].size()));
        }
    QString out;
    for (const QStringList& r : rows) {
        QString line = QStringLiteral("  ");
        for (int c = 0; c < r.size(); ++c) {
            const int w = width[std::size_t(c)];
            line += c == 0 ? r[c].leftJustified(w) : QStringLiteral("  ") + r[c].rightJustified(w);
        }
        out += line + QLatin1Char('\n');
    }
    return out;
}

QString withUnit(double x, const std::string& unit) {
    return num(x, 4) + QLatin1Char(' ') + QString::fromStdString(unit);
}

} // namespace

QString ComparisonTable::channelTables(const ComparisonResult& r) {
    QString out;
    const std::pair<QString, const ComparisonRun*> runs[] = {
        {tr("reference"), &r.reference}, {tr("initial"), &r.initial}, {tr("updated"), &r.updated}};
    std::vector<QStringList> dofs;
    dofs.push_back({tr("run"), tr("element"), tr("basic DOF"), tr("deformation NRMSE"),
                    tr("deformation peak error"), tr("force NRMSE"), tr("force peak error")});
    for (const auto& [name, run] : runs)
        for (const BasicDofComparison& b : run->basicDofs)
            dofs.push_back({name, QString::fromStdString(b.element),
                            QString::fromStdString(b.dof), percent(b.deformationNrmse),
                            withUnit(b.deformationPeakError, b.deformationUnit),
                            percent(b.forceNrmse), withUnit(b.forcePeakError, b.forceUnit)});
    if (dofs.size() > 1)
        out += tr("Per basic DOF against the reference run:") + QLatin1Char('\n') +
               aligned(dofs);
    std::vector<QStringList> acts;
    acts.push_back({tr("run"), tr("element"), tr("actuator"), tr("control"),
                    QStringLiteral("J1 [ms]"), QStringLiteral("J2"), QStringLiteral("J3"),
                    tr("force NRMSE"), tr("force peak error")});
    for (const auto& [name, run] : runs)
        for (const ActuatorComparison& a : run->actuators)
            acts.push_back({name, QString::fromStdString(a.element),
                            QString::fromStdString(a.actuator),
                            a.control == "force" ? tr("force") : tr("displacement"),
                            num(a.tracking.j1, 3), percent(a.tracking.j2 / 100.0),
                            percent(a.tracking.j3 / 100.0),
                            a.compared ? percent(a.forceNrmse) : QStringLiteral("-"),
                            a.compared ? withUnit(a.forcePeakError, a.forceUnit)
                                       : QStringLiteral("-")});
    if (acts.size() > 1)
        out += tr("Per actuator: tracking against its command, force against the reference "
                  "run:") +
               QLatin1Char('\n') + aligned(acts);
    return out;
}

QString ComparisonTable::format(const ComparisonResult& r, const ParameterValues& truth) {
    const QString element = QString::fromStdString(r.element);
    const QString dof = QString::fromStdString(r.dof);
    const QString unit = QString::fromStdString(r.forceUnit);
    QString out = tr("Comparison against the reference run: %1 force [%2], %3 displacement [m]")
                      .arg(element, unit, dof) +
                  QLatin1Char('\n');
    std::vector<QStringList> rows;
    rows.push_back({tr("run"), tr("force NRMSE"), tr("force peak error [%1]").arg(unit),
                    tr("displ. NRMSE"), tr("displ. peak error [m]"), tr("steps")});
    auto row = [&](const QString& name, const ComparisonMetric& m, const ComparisonRun& run) {
        rows.push_back({name, percent(m.forceNrmse), num(m.forcePeakError, 4),
                        percent(m.displacementNrmse), num(m.displacementPeakError, 4),
                        QString::number(run.steps)});
    };
    row(tr("initial"), r.initialMetric, r.initial);
    row(tr("updated"), r.updatedMetric, r.updated);
    out += aligned(rows);
    const double fRatio = r.initialMetric.forceNrmse / r.updatedMetric.forceNrmse;
    const double dRatio = r.initialMetric.displacementNrmse / r.updatedMetric.displacementNrmse;
    if (std::isfinite(fRatio) && std::isfinite(dRatio))
        out += tr("  initial / updated NRMSE: force %1x, displacement %2x")
                   .arg(num(fRatio, 3), num(dRatio, 3)) +
               QLatin1Char('\n');

    out += channelTables(r);

    const ComparisonRun& u = r.updated;
    if (!u.parameterNames.empty() && !u.parameters.empty()) {
        out +=
            tr("Final parameters of the updated run (%1 updates applied):").arg(u.appliedUpdates) +
            QLatin1Char('\n');
        std::vector<QStringList> p;
        p.push_back({tr("parameter"), tr("value"), tr("std"), tr("true")});
        for (std::size_t i = 0; i < u.parameterNames.size(); ++i) {
            const auto at = [i](const std::vector<std::vector<double>>& h) {
                return h.empty() || i >= h.back().size() ? qQNaN() : h.back()[i];
            };
            const auto t = truth.find(u.parameterNames[i]);
            p.push_back({QString::fromStdString(u.parameterNames[i]), num(at(u.parameters), 5),
                         num(at(u.stddev), 2),
                         t == truth.end() ? QStringLiteral("-") : num(t->second, 5)});
        }
        out += aligned(p);
    }
    return out;
}

} // namespace hsmu::gui
