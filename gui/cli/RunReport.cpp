#include "gui/cli/RunReport.h"

#include "core/output/RunStatistics.h"
#include "core/output/RunSummary.h"
#include "core/test/HybridTest.h"

#include <QDir>
#include <QTextStream>

#include <algorithm>

namespace hsmu::gui {

namespace {

QString num(double x, int digits = 4) {
    return QString::number(x, 'g', digits);
}

void printUpdating(QTextStream& out, const HybridTest& test, const RunLayout& layout,
                   const StepRecord& last) {
    const ModelUpdater* updater = test.updater();
    if (!updater || !layout.updating)
        return;
    const UpdatingInfo& info = *layout.updating;
    const UpdatingSample& u = last.updating;
    out << RunReport::tr("  identified parameters of %1 (%2, final value ± std):")
               .arg(QString::fromStdString(info.specimen), QString::fromStdString(info.method))
        << '\n';
    int width = 0;
    for (const auto& name : info.parameters)
        width = std::max(width, int(name.size()));
    for (std::size_t i = 0; i < info.parameters.size(); ++i) {
        const double value =
            last.hasUpdating && i < u.parameters.size() ? u.parameters[i] : qQNaN();
        const double sd = last.hasUpdating && i < u.stddev.size() ? u.stddev[i] : qQNaN();
        out << "    " << QString::fromStdString(info.parameters[i]).leftJustified(width) << " = "
            << num(value, 5) << " ± " << num(sd, 2) << '\n';
    }
    out << RunReport::tr("  updates applied: %1, proposals pending: %2, final fit error: %3")
               .arg(u.appliedUpdates)
               .arg(u.pendingProposals)
               .arg(num(u.fitError, 3))
        << '\n';
}

} // namespace

void RunReport::print(QTextStream& out, const HybridTest& test, const RunStatistics& stats,
                      const RunInfo& info, const QString& outDir) {
    const RunLayout& layout = stats.layout();
    out << tr("Test: %1").arg(QString::fromStdString(info.configName)) << '\n';
    out << tr("  state: %1, steps: %2 of %3, test time: %4 s, wall time: %5 s")
               .arg(QString::fromLatin1(testStateName(test.state())))
               .arg(test.currentStep())
               .arg(test.totalSteps())
               .arg(num(test.time(), 6), num(info.wallTimeS, 3))
        << '\n';
    out << tr("  peak displacement:") << '\n';
    for (std::size_t i = 0; i < layout.dofNames.size(); ++i)
        out << "    " << QString::fromStdString(layout.dofNames[i]) << ": "
            << num(stats.peakDisplacement()[i]) << " m\n";
    out << tr("  peak force:") << '\n';
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        out << "    " << QString::fromStdString(layout.elements[i].name) << ": "
            << num(stats.peakForce()[i]) << ' '
            << QString::fromStdString(layout.elements[i].units.force) << '\n';
    printUpdating(out, test, layout, stats.last());
    if (test.alarms().empty())
        out << tr("  alarms: none") << '\n';
    else
        out << tr("  alarms:") << '\n';
    for (const Alarm& a : test.alarms())
        out << "    t = " << num(a.time, 6) << " s (step " << a.step << ") "
            << alarmSeverityName(a.severity) << ", " << alarmKindName(a.kind) << ": "
            << QString::fromStdString(a.message) << '\n';
    out << tr("  outputs: %1").arg(QDir::toNativeSeparators(outDir)) << Qt::endl;
}

} // namespace hsmu::gui
