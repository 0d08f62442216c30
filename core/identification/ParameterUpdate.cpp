#include "core/identification/ParameterUpdate.h"

#include "core/hysteresis/HysteresisLaw.h"

#include <cmath>

namespace hsmu {

const char* updateDecisionName(UpdateDecision d)
{
    switch (d) {
    case UpdateDecision::Applied: return "applied";
    case UpdateDecision::Refused: return "refused";
    case UpdateDecision::Rejected: return "rejected";
    case UpdateDecision::NotQueued: return "notQueued";
    case UpdateDecision::Superseded: return "superseded";
    case UpdateDecision::Proposed: return "proposed";
    }
    return "?";
}

UpdateEvent applyParameterUpdate(HysteresisLaw* law, const std::string& element,
                                 const ParameterLayout& names, std::span<const int> lawIndex,
                                 std::span<const double> values, int step, double time)
{
    UpdateEvent ev{step,  time, element, names, std::vector<double>(values.begin(), values.end()),
                   true, {}};
    const auto refuse = [&](std::string message) {
        ev.ok = false;
        ev.decision = UpdateDecision::Refused;
        ev.message = std::move(message);
        return ev;
    };
    if (!law)
        return refuse("no numerical element '" + element + "' with a law to update");
    for (std::size_t k = 0; k < values.size(); ++k)
        if (!std::isfinite(values[k]))
            return refuse(element + ": identified " + names.name(k) +
                          " is not finite; nothing applied");
    // All or nothing, judged as one parameter set (the law restores itself if it refuses).
    const int refused = law->setParameterValues(lawIndex, values, true);
    if (refused >= 0) {
        const auto k = static_cast<std::size_t>(refused);
        return refuse(element + ": the law refused " + names.name(k) + " = " +
                      std::to_string(values[k]));
    }
    return ev;
}

} // namespace hsmu
