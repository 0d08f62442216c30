#include "core/experimental/ActuatorChannel.h"

namespace hsmu {

double commandedForce(const ActuatorChannelSpec& c, double t) {
    return scheduledForce(c.forceSchedule, c.heldForce, t); // eq. F1
}

} // namespace hsmu
