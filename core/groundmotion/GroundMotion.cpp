#include "core/groundmotion/GroundMotion.h"
#include "core/util/InputLimits.h"

#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace hsmu {

namespace {

std::size_t peakIndex(const std::vector<double>& a) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < a.size(); ++i) {
        if (std::abs(a[i]) > std::abs(a[best]))
            best = i;
    }
    return best;
}

// Interpolation with t clamped to [0, duration]: resampling may ask for a time a few ulps
// past the end, which must give the last sample and not the 0 that at() returns outside.
double interpolateClamped(const GroundMotion& g, double t) {
    const std::size_t n = g.acceleration.size();
    if (n == 0)
        return 0.0;
    if (n == 1 || t <= 0.0)
        return g.acceleration.front();
    const double position = t / g.dt;
    if (position >= static_cast<double>(n - 1))
        return g.acceleration.back();
    const auto i = static_cast<std::size_t>(std::floor(position));
    const double fraction = position - static_cast<double>(i);
    if (fraction == 0.0)
        return g.acceleration[i];
    return g.acceleration[i] + fraction * (g.acceleration[i + 1] - g.acceleration[i]);
}

} // namespace

double GroundMotion::duration() const {
    if (acceleration.size() < 2)
        return 0.0;
    return static_cast<double>(acceleration.size() - 1) * dt;
}

double GroundMotion::at(double t) const {
    if (acceleration.empty() || !std::isfinite(t) || t < 0.0 || t > duration())
        return 0.0;
    return interpolateClamped(*this, t);
}

double GroundMotion::pga() const {
    if (acceleration.empty())
        return 0.0;
    return std::abs(acceleration[peakIndex(acceleration)]);
}

double GroundMotion::pgaTime() const {
    if (acceleration.empty())
        return 0.0;
    return static_cast<double>(peakIndex(acceleration)) * dt;
}

GroundMotion GroundMotion::scaled(double factor) const {
    GroundMotion result = *this;
    for (double& value : result.acceleration)
        value *= factor;
    return result;
}

GroundMotion GroundMotion::resampled(double newDt) const {
    if (!std::isfinite(newDt) || newDt <= 0.0)
        throw std::invalid_argument("GroundMotion::resampled: the new time step must be > 0 s");
    if (acceleration.size() > 1 && !(dt > 0.0 && std::isfinite(dt)))
        throw std::invalid_argument("GroundMotion::resampled: the record's dt must be > 0 s");

    GroundMotion result;
    result.name = name;
    result.source = source;
    result.dt = newDt;
    if (acceleration.empty())
        return result;

    const double total = duration();
    const double samples = std::floor(total / newDt + 1e-9) + 1.0;
    if (!(samples <= double(limits::kMaxSteps) + 1.0)) // checked before allocating
        throw std::invalid_argument(
            "resampling '" + name + "' (" + std::to_string(total) + " s) at dt = " +
            std::to_string(newDt) + " s would make more than " +
            std::to_string(limits::kMaxSteps) + " samples");
    const auto count = static_cast<std::size_t>(samples);
    result.acceleration.resize(count);
    for (std::size_t k = 0; k < count; ++k)
        result.acceleration[k] = interpolateClamped(*this, static_cast<double>(k) * newDt);
    return result;
}

} // namespace hsmu
