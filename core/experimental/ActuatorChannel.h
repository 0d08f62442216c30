#pragma once
// ActuatorChannelSpec: one actuator of a multi-actuator specimen (docs/setups.md, "Mixed
// control and channel limits"). Each channel is displacement-controlled (its command is the
// stroke the setup computes from the element's basic displacements) or force-controlled (its
// command is a held force, e.g. the vertical actuator's constant axial load; its stroke is
// whatever the specimen gives under it).
// Limits per channel (SafetyLimits, the channel's units: stroke [m], force [kN]):
//   maxDeformation: |stroke| (a commanded stroke past it is never sent; a measured one past it
//                   by SafetyLimits::kMeasuredDeformationTolerance holds the test, also on a
//                   force-controlled channel);
//   maxForce:       |force| (a commanded force past it is never sent; a measured one holds);
//   maxIncrement:   |stroke - last committed stroke| per step [m] (the rate limit times dt).
// A hold names the element and the channel.
// A force-controlled channel holds a constant force, or follows a schedule of (t [s], F [kN])
// points: F(t) linear between points (eq. F1: F = F_k + (t - t_k) (F_k+1 - F_k) / (t_k+1 -
// t_k) for t_k <= t <= t_k+1), F of the first point before it and of the last after it
// (docs/setups.md, "Scheduled forces"); its limits are checked on F(t) like a constant one.

#include "core/experimental/SafetyLimits.h"

#include <array>
#include <string>
#include <vector>

namespace hsmu {

enum class ActuatorMode { Displacement, Force };

struct ActuatorChannelSpec {
    std::string name;                          ///< e.g. "lateral", "vertical"
    ActuatorMode mode = ActuatorMode::Displacement;
    double heldForce = 0.0;                    ///< [kN] command of a force-controlled channel
    SafetyLimits limits;
    /// [kN/m] initial stiffness the channel sees (the specimen through this actuator), for K0;
    /// a force-controlled channel adds no stiffness.
    double initialStiffness = 0.0;
    /// Force control: (t [s], F [kN]) points, t strictly increasing; empty: heldForce. Last,
    /// so that brace initializers of the fields above keep their meaning.
    std::vector<std::array<double, 2>> forceSchedule;
};

const char* actuatorModeName(ActuatorMode m);

/// The force a force-controlled channel commands at test time t [s] (eq. F1; heldForce
/// without a schedule) [kN].
double commandedForce(const ActuatorChannelSpec& c, double t);

/// Why the schedule is not usable (empty string: it is): a point not finite, times not
/// strictly increasing.
std::string forceScheduleProblem(const std::vector<std::array<double, 2>>& schedule);

} // namespace hsmu
