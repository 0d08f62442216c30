#pragma once
// RunReport: the human summary `hsmu run` prints on stdout once the test stopped: state,
// steps, times, peak displacement per DOF [m], peak force per element (its unit), with online
// model updating the final identified parameters ± one standard deviation (the law's own
// units: normalized for Bouc-Wen), the number of applied updates and pending proposals, and
// every alarm.
// Thread rules: main thread, after the test stopped stepping.

#include <QCoreApplication>
#include <QString>

class QTextStream;

namespace hsmu {
class HybridTest;
class RunStatistics;
struct RunInfo;
} // namespace hsmu

namespace hsmu::gui {

class RunReport {
    Q_DECLARE_TR_FUNCTIONS(RunReport)
public:
    static void print(QTextStream& out, const HybridTest& test, const RunStatistics& stats,
                      const RunInfo& info, const QString& outDir);
};

} // namespace hsmu::gui
