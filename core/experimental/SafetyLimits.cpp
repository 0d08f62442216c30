#include "core/experimental/SafetyLimits.h"

#include <cmath>
#include <cstdio>

namespace hsmu {

namespace {
bool active(double limit) { return limit > 0.0 && std::isfinite(limit); }

std::string describe(const char* what, double value, double limit)
{
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s %.6g exceeds the limit %.6g", what, value, limit);
    return buf;
}
} // namespace

std::optional<std::string> SafetyLimits::violationOfTarget(double d, double dLast) const
{
    if (!std::isfinite(d))
        return std::string("target deformation is not a finite number");
    if (active(maxDeformation) && std::abs(d) > maxDeformation)
        return describe("target deformation |d| =", std::abs(d), maxDeformation);
    if (active(maxIncrement) && std::abs(d - dLast) > maxIncrement)
        return describe("target increment |d - d_last| =", std::abs(d - dLast), maxIncrement);
    return std::nullopt;
}

std::optional<std::string> SafetyLimits::violationOfForce(double f) const
{
    if (!std::isfinite(f))
        return std::string("measured force is not a finite number");
    if (active(maxForce) && std::abs(f) > maxForce)
        return describe("measured force |F| =", std::abs(f), maxForce);
    return std::nullopt;
}

std::optional<std::string> SafetyLimits::violationOfMeasuredDeformation(double d) const
{
    if (!std::isfinite(d))
        return std::string("measured deformation is not a finite number");
    const double allowed = maxDeformation * (1.0 + kMeasuredDeformationTolerance);
    if (active(maxDeformation) && std::abs(d) > allowed) {
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "measured deformation |d| = %.6g exceeds the limit %.6g (+%.0f%% tolerance)",
                      std::abs(d), maxDeformation, 100.0 * kMeasuredDeformationTolerance);
        return std::string(buf);
    }
    return std::nullopt;
}

} // namespace hsmu
