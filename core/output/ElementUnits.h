#pragma once
// ElementUnits: the units of an element's deformation and force, from its configuration type
// (the presets' unit system: kN, m, s, rad, kN m):
//   rotationalBaseSpring   deformation rad, force kN m (a moment)
//   lateralSpring, truss   deformation m,   force kN
// Unknown types are assumed translational (m, kN).
// Thread rules: pure functions, any thread.

#include <string>

namespace hsmu {

struct ElementUnits {
    std::string deformation; ///< e.g. "rad" or "m"
    std::string force;       ///< e.g. "kN m" or "kN"
};

ElementUnits elementUnits(const std::string& typeName);

/// The unit without blanks, for column names: "kN m" -> "kNm".
std::string compactUnit(const std::string& unit);

} // namespace hsmu
