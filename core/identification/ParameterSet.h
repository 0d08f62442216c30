#pragma once
// ParameterSet: named law parameters with their bounds, as identified and reported.
// Values are in the law's own units (normalized for a Bouc-Wen law with uRef/fRef).

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace hsmu {

struct ParameterBounds {
    double lower = -std::numeric_limits<double>::infinity();
    double upper = std::numeric_limits<double>::infinity();
    bool contains(double v) const { return v >= lower && v <= upper; }
    double clamp(double v) const { return v < lower ? lower : (v > upper ? upper : v); }
};

using ParameterValues = std::map<std::string, double>;
using ParameterBoundsMap = std::map<std::string, ParameterBounds>;

/// The paper's Table III bounds for normalized Bouc-Wen parameters (A0 = 1 and deltaA = 0 are
/// held fixed and not listed).
ParameterBoundsMap tableIIIBounds();

} // namespace hsmu
