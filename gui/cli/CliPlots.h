#pragma once
// CliPlots: how `hsmu run --plots` and `hsmu compare --plots` draw, without the command-line
// library linking Qt Widgets or QCustomPlot. The console executable (hsmu-console, gui/Launcher)
// installs the drawing functions at start; the light `hsmu` executable (gui/cli/CliLauncher)
// hands any --plots command to hsmu-console instead of running it itself, so the functions are
// always there when --plots reaches RunCommand / CompareCommand.
// Thread rules: set once on the main thread before any command runs.

#include "core/config/TestConfig.h"
#include "core/experiment/StepRecord.h"
#include "core/output/RunLayout.h"
#include "core/session/ComparisonProtocol.h"
#include "core/identification/ParameterSet.h"

#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

namespace hsmu::gui {

struct CliPlots {
    /// Draw a run's plots into dir; returns the files that could not be written.
    std::function<QStringList(const QString& dir, const RunLayout& layout,
                              const std::vector<StepRecord>& records, const TestConfig& cfg)>
        run;
    /// Draw a comparison's plots into dir; returns the files that could not be written.
    std::function<QStringList(const QString& dir, const ComparisonResult& result,
                              const ParameterValues& truth)>
        compare;

    /// The process's drawing functions (empty in the light `hsmu`).
    static CliPlots& installed();
};

} // namespace hsmu::gui
