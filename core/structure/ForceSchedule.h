#pragma once
// A force held by an element or an actuator as a function of test time: a schedule of
// (t [s], F [kN] or [kN m]) points, F(t) linear between points (eq. F1 of docs/setups.md,
// "Scheduled forces": F = F_k + (t - t_k) (F_k+1 - F_k) / (t_k+1 - t_k) for t_k <= t <= t_k+1),
// F of the first point before it and of the last after it. One function for the specimen's
// force-controlled actuators (ActuatorChannel.h) and the numerical twin's held basic forces
// (Link2dElement.h).

#include <array>
#include <string>
#include <vector>

namespace hsmu {

using ForceSchedule = std::vector<std::array<double, 2>>;

/// F(t) of the schedule (eq. F1); `constant` when the schedule is empty.
double scheduledForce(const ForceSchedule& schedule, double constant, double t);

/// Why the schedule is not usable (empty string: it is): a point not finite, times not
/// strictly increasing.
std::string forceScheduleProblem(const ForceSchedule& schedule);

} // namespace hsmu
