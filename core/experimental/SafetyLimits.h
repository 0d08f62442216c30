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
    /// The reason a measured force must stop the test, if any.
    std::optional<std::string> violationOfForce(double f) const;
};

} // namespace hsmu
