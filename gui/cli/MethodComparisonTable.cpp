#include "gui/cli/MethodComparisonTable.h"

#include <QDir>
#include <QStringList>

namespace hsmu::gui {

QString MethodComparisonTable::format(const MethodComparison& c, const SpecimenHistory& history,
                                      const QString& dir) {
    QString text = tr("Method comparison on %1: %2 samples")
                       .arg(QString::fromStdString(history.source))
                       .arg(history.size()) +
                   QLatin1Char('\n');
    text += QStringLiteral("  %1 %2 %3 %4 %5  %6\n")
                .arg(tr("method"), -12)
                .arg(tr("NRMSE [%]"), 10)
                .arg(tr("CPU [s]"), 9)
                .arg(tr("on bounds"), -24)
                .arg(tr("rejected"), 8)
                .arg(tr("verdict"));
    for (const MethodComparisonRow& row : c.rows) {
        QStringList bounds;
        for (const std::string& name : row.onBounds)
            bounds << QString::fromStdString(name);
        text +=
            QStringLiteral("  %1 %2 %3 %4 %5  %6\n")
                .arg(QString::fromStdString(row.method), -12)
                .arg(row.ok ? QString::number(100.0 * row.nrmse, 'f', 2) : QStringLiteral("-"), 10)
                .arg(QString::number(row.cpuSeconds, 'f', 1), 9)
                .arg(bounds.isEmpty() ? tr("none") : bounds.join(QLatin1Char(' ')), -24)
                .arg(row.rejected, 8)
                .arg(QString::fromStdString(row.verdict));
    }
    if (!c.recommended.empty())
        text += tr("  recommended: %1 (the cheapest within 5 % of the best NRMSE)")
                    .arg(QString::fromStdString(c.recommended)) +
                QLatin1Char('\n');
    if (!c.lawVerdict.empty())
        text += tr("  verdict: %1").arg(QString::fromStdString(c.lawVerdict)) + QLatin1Char('\n');
    text += tr("  outputs: %1 (comparison.csv, summary.json; each method's own files in "
               "calibration/, ukf/, nelder-mead/)")
                .arg(QDir::toNativeSeparators(dir)) +
            QLatin1Char('\n');
    return text;
}

} // namespace hsmu::gui
