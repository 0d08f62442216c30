#pragma once
// SetupScript: OpenFresco's `expSetup` lines read as they are written in a lab's Tcl script,
// so that its numbers carry over unchanged (docs/setups.md, "Reading OpenFresco's lines").
//
// One command per line; blank lines and Tcl comments (#) are skipped; only literal numbers (no
// Tcl variables or expressions). Types and syntax: those of docs/setups.md (OpenFresco 2.8's),
// `-control $tag` / `-ctrl $tag` accepted and not used (HSMU's controls are configured apart).
// Unlike OpenFresco, every word must be understood: an unknown option (e.g. `-nlgeom` in lower
// case, or OpenFresco's scale factors `-trialDispFact` ...), a missing or malformed number, an
// unknown type, a repeated tag, or an Aggregator naming a setup not defined above it is refused
// with "line N: <type>: <what>". Setups an Aggregator takes are moved into it (OpenFresco's
// sub-setups are not used on their own either).

#include "core/experimental/setup/ExperimentalSetup.h"

#include <map>
#include <memory>
#include <string>

namespace hsmu {

using SetupsByTag = std::map<int, std::unique_ptr<ExperimentalSetup>>;

/// Parses `script`; on success fills `out` (tag -> setup) and returns true; otherwise returns
/// false with `error` set and `out` unchanged.
bool parseSetupScript(const std::string& script, SetupsByTag& out, std::string& error);

} // namespace hsmu
