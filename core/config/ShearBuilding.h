#pragma once
// ShearBuilding: the generated preset family "shear-building-<N>[-elastic][-mass-damped]",
// a uniform chain of N storeys for models of any size (docs/presets.md, issue 17):
//
//   storey i (1..N): mass 10 t on DOF "S<i>"; between floors i-1 and i (the ground for i = 1)
//   one spring of initial stiffness 4000 kN/m: a Bouc-Wen law (k0 = 1 normalized with
//   uRef = 0.02 m, fRef = 80 kN; alpha 0.05, n 2, beta 0.75, gamma 0.25) or, with "-elastic",
//   a linear elastic one. Damping 5 % Rayleigh at modes 1 and 2 (C = a0 M + a1 K0, so the
//   explicit step solves with a sparse LDL^T factor), or with "-mass-damped" C = a0 M with
//   a0 = 0.5 1/s (diagonal: no solve at all). Built-in synthetic record at scale 1,
//   explicit Newmark, dt = 0.001 s, 5 s. omega_max < 2 sqrt(k/m) = 40 rad/s, so
//   omega_max dt < 0.04 at any N.
// It is a numerical stress test (for large N not a realistic building): every element is
// numerical, DOFs are referenced by index so parsing stays O(N).
// Thread rules: pure functions.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace hsmu {

struct ShearBuildingSpec {
    int storeys = 10;          ///< N >= 1
    bool boucWen = true;       ///< false: linear elastic storeys
    bool massDamped = false;   ///< true: C = a0 M only
};

/// Largest N the generator accepts (a million DOFs would need gigabytes of records).
inline constexpr int kMaxShearBuildingStoreys = 200000;

/// The spec a name like "shear-building-1000-elastic" asks for; nullopt if the name is not
/// of the family (or N is outside 1..kMaxShearBuildingStoreys).
std::optional<ShearBuildingSpec> parseShearBuildingName(const std::string& name);
/// The configuration document (docs/configuration.md schema) of the spec.
nlohmann::json shearBuildingConfig(const ShearBuildingSpec& spec);

} // namespace hsmu
