#pragma once
// ParameterSet: a parameter's bounds, and named values and bounds where parameters are named
// rather than positioned: as a configuration gives them and as reports write them (the edges;
// identifiers, laws, the Inspector and the Reporter take vectors in a ParameterLayout's order).
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

/// Values by name, for reports and outputs (summaries, tables, plots).
using ParameterValues = std::map<std::string, double>;
/// Bounds by name, as configured (resolved to an identifier's layout once, when it is built).
using ParameterBoundsMap = std::map<std::string, ParameterBounds>;

/// The paper's Table III bounds for normalized Bouc-Wen parameters (A0 = 1 and deltaA = 0 are
/// held fixed and not listed).
ParameterBoundsMap tableIIIBounds();

} // namespace hsmu
