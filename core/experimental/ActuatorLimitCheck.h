#pragma once
// ActuatorLimitCheck: the pre-flight lines of a multi-actuator specimen's per-channel limits
// (docs/console.md, "Running a test", and docs/setups.md, "Mixed control and channel limits"):
// for each actuator channel and each of its limits (stroke [m], force [kN], stroke increment
// per step [m]) the configured limit against what the run is known to reach before it starts:
//   - a force-controlled channel's force: its constant force, or the largest |F(t)| of its
//     schedule over [0, duration] (F is linear between points, eq. F1 of ActuatorChannel.h,
//     so the largest |F| is at a point inside the run or at t = 0 or t = duration);
//   - everything else (a displacement channel's stroke, force and increment, a force
//     channel's stroke and increment) depends on the specimen's response: not known before
//     the run, checked at every step while it runs.
// Verdicts: Pass (reach <= limit), Exceeded (reach > limit: the run would be held when it gets
// there), DuringRun (not known before the run), NoLimit (no limit configured).
// Thread rules: plain functions.

#include "core/experimental/ActuatorChannel.h"

#include <string>
#include <vector>

namespace hsmu {

enum class LimitQuantity { Stroke, Force, Increment };
enum class LimitVerdict { Pass, Exceeded, DuringRun, NoLimit };

struct ActuatorLimitLine {
    std::string actuator; ///< the channel's name
    ActuatorMode mode = ActuatorMode::Displacement;
    LimitQuantity quantity = LimitQuantity::Stroke;
    double limit = 0.0;     ///< [m] stroke and increment, [kN] force; +inf: none
    double reach = 0.0;     ///< what the run commands (verdict Pass / Exceeded), else NaN
    double reachTime = 0.0; ///< [s] when it first commands reach (Pass / Exceeded)
    LimitVerdict verdict = LimitVerdict::DuringRun;
};

/// Three lines per channel (stroke, force, increment), channels in order, for a run of
/// `duration` seconds (<= 0: the schedule's last point).
std::vector<ActuatorLimitLine> actuatorLimitLines(const std::vector<ActuatorChannelSpec>& channels,
                                                  double duration);

} // namespace hsmu
