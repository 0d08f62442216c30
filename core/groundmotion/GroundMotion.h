#pragma once
// GroundMotion: a uniformly sampled ground acceleration record in m/s^2.
// Sample i is at t = i * dt (t = 0 for the first sample), as in the PEER files.

#include <string>
#include <vector>

namespace hsmu {

struct GroundMotion {
    std::string name;                 ///< e.g. file name or "synthetic (seed 1940)"
    std::string source;               ///< where it came from (path or "builtin")
    double dt = 0.0;                  ///< sample interval [s], > 0
    std::vector<double> acceleration; ///< ground acceleration [m/s^2]

    double duration() const; ///< (N - 1) dt [s]
    /// Linear interpolation at time t [s]; 0 outside the record.
    double at(double t) const;
    /// Peak absolute acceleration [m/s^2] and the time [s] of that sample (the first one
    /// if several share the peak); 0 for an empty record.
    double pga() const;
    double pgaTime() const;
    /// The same record multiplied by factor.
    GroundMotion scaled(double factor) const;
    /// Linear resampling to a new interval newDt [s] over the same duration:
    /// floor(duration / newDt + 1e-9) + 1 samples, sample k = at(k newDt) (the last one is
    /// clamped to the record's end). Throws std::invalid_argument if newDt <= 0 or is not
    /// finite, or if this record has dt <= 0 and more than one sample.
    GroundMotion resampled(double newDt) const;
};

/// Standard gravity [m/s^2] used for unit conversion.
inline constexpr double kStandardGravity = 9.80665;

} // namespace hsmu
