#pragma once
// SetupConfig: a link2d specimen's experimental setup given in JSON as its type and
// OpenFresco's parameters (docs/configuration.md, "link2d"; docs/setups.md for each type's
// parameters, the same names and meanings as OpenFresco's expSetup), beside the expSetup line
// (`"setup": {"script": "expSetup ..."}`). The block is turned into the very expSetup line(s)
// that say the same (numbers written so that they read back to the same double) and read by
// parseSetupScript (SetupScript.h), so that both forms build identical setups with the same
// checks:
//   {"type": "TwoActuators2d", "La1": 1.5, "La2": 1.2, "L": 0.6, "nlGeom": true,
//    "posAct": "left", "phiLocX": 90}
//     -> expSetup TwoActuators2d 1 1.5 1.2 0.6 -nlGeom -posAct left -phiLocX 90
// Parameters per type (lengths in the script's units, m with the presets; phiLocX [deg]):
//   TwoActuators2d                      La1 La2 L, posAct
//   ThreeActuators2d, InvertedVBrace2d,
//   ChevronBrace2d                      La1 La2 La3 L1 L2, posAct1
//   ThreeActuatorsJntOff2d,
//   InvertedVBraceJntOff2d              La1 La2 La3 L1 L2 L3 L4 L5 L6, posAct1
//   FourActuators3d                     L1 L2 L3 L4 a1 a2 a3 a4 h h1 h2 arlN arlS LrodN LrodS Hbeam
//   (all of these also nlGeom (true/false, default false), phiLocX (default 0))
//   OneActuator                         dir (1-based), sizeTrial
//   NoTransformation                    dir (array, 1-based), sizeTrial
//   Aggregator                          setups (array of such blocks; sizeTrial their sum)
// Errors: ConfigError naming the field (e.g. "setup.La2: TwoActuators2d: La2 missing",
// "setup.L: TwoActuators2d: L = 0 puts both horizontal actuators ..."), an unknown key or type.

#include "core/config/JsonCursor.h"

#include <string>

namespace hsmu {

/// The expSetup script (one line, or an Aggregator's sub-setups then its own line) of the
/// JSON setup block c; checked by building it (ConfigError naming the field otherwise).
std::string setupScriptOf(const JsonCursor& c);

} // namespace hsmu
