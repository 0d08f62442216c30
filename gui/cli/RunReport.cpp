#include "gui/cli/RunReport.h"

#include "core/experiment/HybridTest.h"
#include "core/output/RunStatistics.h"
#include "core/output/RunSummary.h"
#include "core/rths/TrackingMetrics.h"
#include "gui/cli/CliText.h"
#include "gui/plots/PlotSelection.h"

#include <algorithm>
#include <limits>
#include <sstream>

namespace hsmu::gui {

namespace {

constexpr int kMaxListed = 20; // DOFs / elements listed before "... N more"

std::string num(double x, int digits = 4) {
    return number(x, 'g', digits);
}

void printUpdating(std::ostream& out, const HybridTest& test, const RunLayout& layout,
                   const StepRecord& last) {
    const ModelUpdater* updater = test.updater();
    if (!updater || !layout.updating)
        return;
    const UpdatingInfo& info = *layout.updating;
    const UpdatingSample& u = last.updating;
    out << Text(translate("RunReport", "  identified parameters of %1 (%2, final value ± std):"))
               .args({info.specimen, info.method})
               .str()
        << '\n';
    std::size_t width = 0;
    for (const auto& name : info.parameters)
        width = std::max(width, name.size());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < info.parameters.size(); ++i) {
        const double value = last.hasUpdating && i < u.parameters.size() ? u.parameters[i] : nan;
        const double sd = last.hasUpdating && i < u.stddev.size() ? u.stddev[i] : nan;
        std::string name = info.parameters[i];
        name.resize(std::max(width, name.size()), ' '); // QString::leftJustified
        out << "    " << name << " = " << num(value, 5) << " ± " << num(sd, 2) << '\n';
    }
    out << Text(translate("RunReport",
                          "  updates applied: %1, proposals pending: %2, final fit error: %3"))
               .arg(u.appliedUpdates)
               .arg(u.pendingProposals)
               .arg(num(u.fitError, 3))
               .str()
        << '\n';
}

} // namespace

std::string RunReport::text(const HybridTest& test, const RunStatistics& stats, const RunInfo& info,
                            const std::string& outDir) {
    std::ostringstream out;
    const RunLayout& layout = stats.layout();
    out << Text(translate("RunReport", "Test: %1")).arg(info.configName).str() << '\n';
    out << Text(translate("RunReport",
                          "  state: %1, steps: %2 of %3, test time: %4 s, wall time: %5 s"))
               .arg(testStateName(test.state()))
               .arg(test.currentStep())
               .arg(test.totalSteps())
               .args({num(test.time(), 6), num(info.wallTimeS, 3)})
               .str()
        << '\n';
    // A large model lists a spread few (docs/cli.md); summary.json has every one.
    const auto more = [&out](std::size_t shown, std::size_t all) {
        if (shown < all)
            out << "    "
                << Text(translate("RunReport", "... %1 more in summary.json"))
                       .arg(all - shown)
                       .str()
                << '\n';
    };
    out << translate("RunReport", "  peak displacement:") << '\n';
    const std::vector<int> dofs = spreadIndices(int(layout.dofNames.size()), kMaxListed);
    for (const int d : dofs) {
        const auto i = std::size_t(d);
        out << "    " << layout.dofNames[i] << ": " << num(stats.peakDisplacement()[i]) << " m\n";
    }
    more(dofs.size(), layout.dofNames.size());
    out << translate("RunReport", "  peak force:") << '\n';
    const std::vector<int> elements = spreadIndices(int(layout.elements.size()), kMaxListed);
    for (const int e : elements) {
        const auto i = std::size_t(e);
        out << "    " << layout.elements[i].name << ": " << num(stats.peakForce()[i]) << ' '
            << layout.elements[i].units.force << '\n';
    }
    more(elements.size(), layout.elements.size());
    for (std::size_t i = 0; i < layout.elements.size(); ++i) {
        const rths::TrackingReport* tracked = stats.tracking(i, test.dt());
        if (!tracked)
            continue;
        const rths::TrackingReport& t = *tracked;
        out << Text(
                   translate("RunReport",
                             "  tracking of %1 (commanded against measured): J1 %2 ms, J2 %3 %, J3 "
                             "%4 %"))
                   .args({layout.elements[i].name, num(t.j1, 3), num(t.j2, 3), num(t.j3, 3)})
                   .str()
            << '\n';
    }
    printUpdating(out, test, layout, stats.last());
    if (test.alarms().empty())
        out << translate("RunReport", "  alarms: none") << '\n';
    else
        out << translate("RunReport", "  alarms:") << '\n';
    for (const Alarm& a : test.alarms())
        out << "    t = " << num(a.time, 6) << " s (step " << a.step << ") "
            << alarmSeverityName(a.severity) << ", " << alarmKindName(a.kind) << ": " << a.message
            << '\n';
    if (const DofRecording& r = info.dofRecording; !r.full()) // the record's choice
        out << Text(translate("RunReport", "  record: DOFs %1 (%2 of %3), every %4 steps; "
                                           "elements, specimens and updating at every step"))
                   .arg(describeDofList(r.dofs))
                   .arg(int(r.dofs.empty() ? layout.dofNames.size() : r.dofs.size()))
                   .arg(int(layout.dofNames.size()))
                   .arg(r.every)
                   .str()
            << '\n';
    out << Text(translate("RunReport", "  outputs: %1")).arg(outDir).str() << '\n';
    return out.str();
}

} // namespace hsmu::gui
