#include "core/experimental/ActuatorLimitCheck.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsmu {

namespace {

// The largest |F(t)| over [0, end] and its time (eq. F1 is linear between points).
void largestForce(const ActuatorChannelSpec& c, double end, double& force, double& time) {
    std::vector<double> times{0.0, end};
    for (const auto& p : c.forceSchedule)
        if (p[0] > 0.0 && p[0] < end)
            times.push_back(p[0]);
    std::sort(times.begin(), times.end()); // the earliest time of the largest force
    force = -1.0;
    time = 0.0;
    for (const double t : times) {
        const double f = std::abs(commandedForce(c, t));
        if (f > force) {
            force = f;
            time = t;
        }
    }
}

ActuatorLimitLine line(const ActuatorChannelSpec& c, LimitQuantity q, double limit) {
    ActuatorLimitLine l;
    l.actuator = c.name;
    l.mode = c.mode;
    l.quantity = q;
    l.limit = limit;
    l.reach = std::numeric_limits<double>::quiet_NaN();
    l.verdict = std::isfinite(limit) ? LimitVerdict::DuringRun : LimitVerdict::NoLimit;
    return l;
}

} // namespace

std::vector<ActuatorLimitLine> actuatorLimitLines(const std::vector<ActuatorChannelSpec>& channels,
                                                  double duration) {
    std::vector<ActuatorLimitLine> out;
    for (const ActuatorChannelSpec& c : channels) {
        out.push_back(line(c, LimitQuantity::Stroke, c.limits.maxDeformation));
        ActuatorLimitLine force = line(c, LimitQuantity::Force, c.limits.maxForce);
        if (c.mode == ActuatorMode::Force) {
            double end = duration;
            if (!(end > 0.0))
                end = c.forceSchedule.empty() ? 0.0 : c.forceSchedule.back()[0];
            largestForce(c, end, force.reach, force.reachTime);
            if (force.verdict != LimitVerdict::NoLimit)
                force.verdict =
                    force.reach > force.limit ? LimitVerdict::Exceeded : LimitVerdict::Pass;
        }
        out.push_back(force);
        out.push_back(line(c, LimitQuantity::Increment, c.limits.maxIncrement));
    }
    return out;
}

} // namespace hsmu
