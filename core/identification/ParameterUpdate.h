#pragma once
// The one path by which identified or operator values reach a law: the Reporter's targets
// (core/updating/Reporter.h) and the RTHS loop's damper twin (core/rths/DamperTwin.h) alike.
// Here, below both, so that neither folder depends on the other for it.

#include "core/identification/ParameterLayout.h"

#include <span>
#include <string>
#include <vector>

namespace hsmu {

class HysteresisLaw;

/// What became of an offer: applied to the target, refused by its law (or not finite), rejected
/// by the operator, or not queued (the approval queue was full). The record keeps the code
/// (updateDecisionName(), language-neutral).
/// Superseded: a newer proposal for the same target replaced it (OnApproval). Proposed: an offer
/// became a proposal waiting for the operator (the RTHS twin's, TwinProposals.h). New codes are
/// appended: the record stores the index into the list of names.
enum class UpdateDecision { Applied, Refused, Rejected, NotQueued, Superseded, Proposed };
const char* updateDecisionName(UpdateDecision d);

struct UpdateEvent {
    int step = 0;
    double time = 0.0;
    std::string element;
    ParameterLayout parameters;  ///< the target's parameters (name order), for display / record
    std::vector<double> applied; ///< the values applied (Applied) or offered, in that order
    bool ok = true;              ///< decision == Applied
    std::string message; ///< why, when !ok
    UpdateDecision decision = UpdateDecision::Applied;
    int proposal = 0; ///< the proposal's id under OnApproval (0: none)
};


/// `values` (in `names` order) set at the law's positions `lawIndex`, all or nothing, keeping
/// the law's state. The event at `step`, `time`: Applied, or Refused with the reason (no law, a
/// value not finite, or the law refusing one). Nothing is counted (Reporter counts its own).
UpdateEvent applyParameterUpdate(HysteresisLaw* law, const std::string& element,
                                 const ParameterLayout& names, std::span<const int> lawIndex,
                                 std::span<const double> values, int step, double time);

} // namespace hsmu
