#include "core/experimental/ActuatorChannel.h"

#include <algorithm>
#include <cmath>

namespace hsmu {

double commandedForce(const ActuatorChannelSpec& c, double t) {
    const auto& p = c.forceSchedule;
    if (p.empty())
        return c.heldForce;
    if (t <= p.front()[0])
        return p.front()[1];
    if (t >= p.back()[0])
        return p.back()[1];
    const auto hi = std::upper_bound(
        p.begin(), p.end(), t, [](double x, const std::array<double, 2>& q) { return x < q[0]; });
    const auto lo = hi - 1;
    return (*lo)[1] + (t - (*lo)[0]) * ((*hi)[1] - (*lo)[1]) / ((*hi)[0] - (*lo)[0]); // eq. F1
}

std::string forceScheduleProblem(const std::vector<std::array<double, 2>>& schedule) {
    for (std::size_t k = 0; k < schedule.size(); ++k) {
        const auto& q = schedule[k];
        if (!std::isfinite(q[0]) || !std::isfinite(q[1]))
            return "point " + std::to_string(k + 1) + " is not finite";
        if (k > 0 && !(q[0] > schedule[k - 1][0]))
            return "point " + std::to_string(k + 1) + ": times must increase strictly";
    }
    return {};
}

} // namespace hsmu
