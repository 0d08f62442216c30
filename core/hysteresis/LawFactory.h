#pragma once
// LawFactory: builds a HysteresisLaw from a law name and named parameters, as given in a
// configuration file or on the `hsmu material` command line.
//
// Law names (case-insensitive): "boucWen" (also "bouc-wen"), "boucWenPinching" (also
// "bouc-wen-pinching"), "mrDamper" (also "mr-damper"), "bilinear", "elastic".
// Parameter names are those of each law's parameterNames():
//   boucWen   k0, alpha, n, beta, gamma, A0, deltaA, deltaNu, deltaEta, uRef, fRef
//             (defaults of BoucWenParameters; see BoucWen.h for the equations)
//   boucWenPinching  boucWen's names and zetaS, p, q, psi, deltaPsi, lambda (defaults of
//             BoucWenParameters and PinchingParameters; BoucWenPinching.h)
//   mrDamper  c0, c1, k0, k1, f0, alpha, A, beta, gamma, n, uRef, fRef (defaults of
//             MrDamperParameters; MrDamper.h; rate-dependent: the owner sets the time step)
//   bilinear  k0, fy, b   (defaults of BilinearParameters: 1, 1, 0.1)
//   elastic   k           (default 1)
// Unspecified parameters take the defaults.
// Every law also takes "deformationOffset" and "forceOffset" (OffsetLaw.h: F = F_law(u - u0) +
// F0, in the caller's units): when either is given the law is built inside an OffsetLaw, whose
// layout is the law's names followed by the two offsets (the other one 0).

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hsmu {

class HysteresisLaw;

/// Throws std::invalid_argument, with a sentence naming the law, the parameter and what was
/// expected, for an unknown law name, an unknown parameter name or an inadmissible value, e.g.
/// "bilinear: unknown parameter 'fyy' (expected one of k0, fy, b)".
std::unique_ptr<HysteresisLaw> makeLaw(const std::string& lawName,
                                       const std::map<std::string, double>& params);

/// The canonical law names: "boucWen", "boucWenPinching", "mrDamper", "bilinear", "elastic".
std::vector<std::string> knownLaws();

} // namespace hsmu
