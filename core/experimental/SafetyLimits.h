#pragma once
// SafetyLimits: what a target and a measurement may never exceed. Checked before anything is
// sent (deformation and increment) and on every measurement (force). A limit <= 0 or
// infinite disables that check. Units: the specimen's (deformation, force).

#include <limits>
#include <optional>
#include <string>

namespace hsmu {

struct SafetyLimits {
    double maxDeformation = std::numeric_limits<double>::infinity(); ///< |d| limit
    double maxForce = std::numeric_limits<double>::infinity();       ///< |F| limit
    double maxIncrement = std::numeric_limits<double>::infinity();   ///< |d - d_last| limit

    /// The reason a target d (after a last target dLast) must not be sent, if any.
    std::optional<std::string> violationOfTarget(double d, double dLast) const;
    /// The reason a measured force must stop the test, if any (no tolerance: the force
    /// limit is the specimen's, a measurement past it already loaded the specimen past it).
    std::optional<std::string> violationOfForce(double f) const;

    /// Relative tolerance on a *measured* deformation (sensor noise, actuator tracking):
    /// |d_measured| may exceed maxDeformation by this fraction of it (docs/configuration.md).
    static constexpr double kMeasuredDeformationTolerance = 0.05;
    /// The reason a measured deformation must stop the test, if any: not finite, or
    /// |d| > maxDeformation (1 + kMeasuredDeformationTolerance).
    std::optional<std::string> violationOfMeasuredDeformation(double d) const;
};

} // namespace hsmu
