#pragma once
// ConfigUnits: the optional "units" block of a configuration file (docs/configuration.md),
//   "units": { "length": "mm", "force": "kN", "rotation": "rad", "moment": "kN m",
//              "time": "s", "mass": "t" }
// names the units the file's values are written in (each key optional; the console's units
// kN, m, s, rad, kN m, t are the defaults; "moment" defaults to force x length). On load the
// dimensional fields are converted to the console's units, field by field:
//   structure.dofs[].mass                                mass
//   structure.damping.a0 / a1                            1 / time, time
//   structure.elements[].height                          length
//   structure.elements[].ei                              force x length^2
//   elements' and specimens' material parameters, in the element's deformation D and force F
//   (lateralSpring, truss: length and force; rotationalBaseSpring: rotation and moment):
//     boucWen, boucWenPinching  uRef (D), fRef (F) (the defaults 1 D and 1 F are written out;
//                               k0 and the other parameters are normalized, unchanged)
//     mrDamper                  uRef (D), fRef (F) as boucWen; c0, c1 (normalized force x
//                               time) by the time unit
//     bilinear                  k0 (F / D), fy (F);   elastic  k (F / D)
//   specimen.forceNoiseStd (F), deformationNoiseStd (D), fracture.atCumulativeDeformation (D),
//   fracture.atTime, actuator.timeConstant, actuator.delay (time); limits and
//   specimen.interlock: deformation, increment (D), force (F)
//   groundMotion.dt, analysis.dt, analysis.duration     time
// Not converted: groundMotion's accelerations (their own groundMotion.units) and the
// "updating" section (its values stay in the console's units). Units: core/util/Units.h.
// Thread rules: none.

#include <nlohmann/json.hpp>

#include <string>

namespace hsmu {

/// A copy of `document` in the console's units (the document itself if it has no units block
/// or that block names the console's units). Throws ConfigError naming the file and the field,
/// e.g. "t.json: units.length: unknown length unit 'yd' (expected m, cm, mm, in, ft)".
nlohmann::json toConsoleUnits(const nlohmann::json& document, const std::string& sourceName);

} // namespace hsmu
