#include "core/experimental/SafetyLimits.h"

#include "core/util/ReasonText.h"

#include <cmath>
#include <cstdio>

namespace hsmu {

namespace {
bool active(double limit) { return limit > 0.0 && std::isfinite(limit); }

std::string number(const char* fmt, double v)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

// The texts are core's templates (core/util/ReasonText): the console translates them.
std::string describe(const char* code, double value, double limit)
{
    return reasonText(code, {number("%.6g", value), number("%.6g", limit)});
}
} // namespace

std::optional<std::string> SafetyLimits::violationOfTarget(double d, double dLast) const
{
    if (!std::isfinite(d))
        return reasonText("limit-target-not-finite");
    if (active(maxDeformation) && std::abs(d) > maxDeformation)
        return describe("limit-target", std::abs(d), maxDeformation);
    if (active(maxIncrement) && std::abs(d - dLast) > maxIncrement)
        return describe("limit-increment", std::abs(d - dLast), maxIncrement);
    return std::nullopt;
}

std::optional<std::string> SafetyLimits::violationOfForce(double f) const
{
    if (!std::isfinite(f))
        return reasonText("limit-force-not-finite");
    if (active(maxForce) && std::abs(f) > maxForce)
        return describe("limit-force", std::abs(f), maxForce);
    return std::nullopt;
}

std::optional<std::string> SafetyLimits::violationOfMeasuredDeformation(double d) const
{
    if (!std::isfinite(d))
        return reasonText("limit-measured-not-finite");
    const double allowed = maxDeformation * (1.0 + kMeasuredDeformationTolerance);
    if (active(maxDeformation) && std::abs(d) > allowed) {
        return reasonText("limit-measured",
                          {number("%.6g", std::abs(d)), number("%.6g", maxDeformation),
                           number("%.0f", 100.0 * kMeasuredDeformationTolerance)});
    }
    return std::nullopt;
}

} // namespace hsmu
