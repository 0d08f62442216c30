#pragma once
// RunReport: the human summary `hsmu run` prints on stdout once the test stopped: state,
// steps, times, peak displacement per DOF [m], peak force per element (its unit), with online
// model updating the final identified parameters ± one standard deviation (the law's own
// units: normalized for Bouc-Wen), the number of applied updates and pending proposals, and
// every alarm.
// Without Qt (the Qt-free `hsmu run`, gui/cli/FastRun.h); its strings are translated through
// CliText's translator in the context "RunReport" (translations/).
// Thread rules: main thread, after the test stopped stepping.

#include <string>

namespace hsmu {
class HybridTest;
class RunStatistics;
struct RunInfo;
} // namespace hsmu

namespace hsmu::gui {

class RunReport {
public:
    /// The summary's text (lines ending in '\n'); outDir as the user gave it (QDir's path()).
    static std::string text(const HybridTest& test, const RunStatistics& stats,
                            const RunInfo& info, const std::string& outDir);
};

} // namespace hsmu::gui
