#pragma once
// RthsCommand: `hsmu rths CONFIG --out DIR [--ground-motion FILE] [--scale S] [--duration T]
// [--pace fast|realtime] [--realtime-priority] [--compensation default|none|lead|polynomial|
// feedforward|ats] [--perturb SEED] [--seed N] [--no-noise]`: a real-time hybrid simulation on
// the servo-hydraulic plant of the virtual lab (docs/rths.md). CONFIG is a file with an "rths"
// object or a generated preset rths-benchmark-case-1 .. -4. Writes DIR/steps.csv and
// DIR/summary.json and prints the pre-flight and the tracking criteria.
// Exit codes as `hsmu run`: 0 finished, 1 error or refused in pre-flight, 2 held.
// Thread rules: main thread (the real-time pace runs the loop on a thread of its own).

#include <QCoreApplication>
#include <QStringList>

namespace hsmu::gui {

class RthsCommand {
    Q_DECLARE_TR_FUNCTIONS(RthsCommand)
public:
    static int exec(const QStringList& arguments);
};

} // namespace hsmu::gui
