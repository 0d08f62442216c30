#pragma once
// The one path by which identified or operator values reach a law: the Reporter's targets
// (Reporter.h) and the RTHS loop's damper twin (core/rths/DamperTwin.h) alike.

#include "core/updating/Reporter.h"

namespace hsmu {

/// `values` (in `names` order) set at the law's positions `lawIndex`, all or nothing, keeping
/// the law's state. The event at `step`, `time`: Applied, or Refused with the reason (no law, a
/// value not finite, or the law refusing one). Nothing is counted (Reporter counts its own).
UpdateEvent applyParameterUpdate(HysteresisLaw* law, const std::string& element,
                                 const ParameterLayout& names, std::span<const int> lawIndex,
                                 std::span<const double> values, int step, double time);

} // namespace hsmu
