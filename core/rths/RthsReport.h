#pragma once
// RthsReport: what an RTHS run leaves on disk (docs/rths.md, "Outputs"): steps.csv (one row per
// tick: time [s], desired, command, measured [m], force [N], the hybrid and the reference floors
// [m]) and summary.json (J1..J9, the frequency evaluation index, the tracking indicator, peaks,
// the pre-flight delays, deadline misses, the hold). Also the pre-flight's delay check.

#include "core/rths/RthsBenchmark.h"

#include <nlohmann/json.hpp>

#include <string>

namespace hsmu::rths {

/// The loop's delay left after compensation at f [Hz] [s] (the compensated design model:
/// closedLoopResponse times the compensator's own response), plus forceDelay ticks.
double effectiveDelay(const RthsSettings& s, double f);

struct Preflight {
    double criticalDelay = 0.0;  ///< [s] (Partition.h, S2)
    double loopDelay = 0.0;      ///< effectiveDelay at the first mode [s]
    double firstMode = 0.0;      ///< [Hz]
    bool refused = false;        ///< loopDelay >= criticalDelay
    bool flagged = false;        ///< loopDelay > half the critical delay
    std::string message;         ///< one sentence with both delays
};
Preflight preflight(const Partition& p, const RthsSettings& s);

/// Write steps.csv; throws std::runtime_error naming the file when it cannot be written.
void writeRthsSteps(const std::string& path, const RthsRun& run);
nlohmann::json rthsSummary(const RthsRun& run, const RthsSettings& s, const Preflight& pre);

} // namespace hsmu::rths
