#include "comms/controller/ControllerSettings.h"

#include "core/config/JsonCursor.h"

#include <algorithm>
#include <cmath>

namespace hsmu::comms {

int ControllerSettings::ticksPerStep(double dt) const {
    const double duration = stepDuration > 0.0 ? stepDuration : dt;
    const double n = std::round(duration * rate);
    if (!(n >= 1.0))
        return 1;
    return n > 1e6 ? 1000000 : static_cast<int>(n);
}

int ControllerSettings::predictTicks(double dt) const {
    const int n = ticksPerStep(dt);
    const int p = static_cast<int>(std::floor(predictFraction * n));
    return std::clamp(p, 0, n - 1);
}

int ControllerSettings::holdRampTicks() const {
    const double r = std::round(holdRamp * rate);
    return r > 1e6 ? 1000000 : (r >= 1.0 ? static_cast<int>(r) : 0);
}

ControllerSettings parseControllerSettings(const TestConfig& cfg) {
    ControllerSettings s;
    if (!cfg.raw.is_object() || !cfg.raw.contains("controller"))
        return s;
    const JsonCursor root(cfg.raw, cfg.sourcePath);
    const JsonCursor c = root.child("controller");
    // protocol, dataSize, ctrlSizes, daqSizes, initFile: the link (core/config/LinkConfig.h).
    c.allowOnly({"rate", "stepDuration", "predictFraction", "holdRamp", "idleTimeout", "protocol",
                 "dataSize", "ctrlSizes", "daqSizes", "initFile", "serverDofs",
                 "connectTimeout", "stepDeadline"}); // the last two: the console's (LinkSpec)
    s.rate = c.number("rate", s.rate);
    if (!(s.rate > 0.0 && s.rate <= 100000.0))
        c.fail("rate", "expected a loop rate in (0, 100000] Hz");
    s.stepDuration = c.number("stepDuration", s.stepDuration);
    if (!(s.stepDuration >= 0.0) || !std::isfinite(s.stepDuration))
        c.fail("stepDuration", "expected a duration >= 0 s (0: the test's dt)");
    s.predictFraction = c.number("predictFraction", s.predictFraction);
    if (!(s.predictFraction >= 0.0 && s.predictFraction < 1.0))
        c.fail("predictFraction", "expected a fraction in [0, 1)");
    s.holdRamp = c.number("holdRamp", s.holdRamp);
    if (!(s.holdRamp >= 0.0) || !std::isfinite(s.holdRamp))
        c.fail("holdRamp", "expected a duration >= 0 s (0: stop at once)");
    s.idleTimeout = c.number("idleTimeout", s.idleTimeout);
    if (!(s.idleTimeout > 0.0) || !std::isfinite(s.idleTimeout))
        c.fail("idleTimeout", "expected a timeout > 0 s");
    return s;
}

} // namespace hsmu::comms
