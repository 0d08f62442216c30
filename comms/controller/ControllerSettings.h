#pragma once
// ControllerSettings: the optional "controller" section of a test configuration, read by
// hsmu-controller (the console ignores it). All fields optional:
//
//   "controller": {
//     "rate": 1024,            predictor-corrector and actuator loop rate [Hz], (0, 100000]
//     "stepDuration": 0.01,    time one integration step takes on the rig [s]; 0 or absent:
//                              the dt the console configures (real time)
//     "predictFraction": 0.5,  share of a step's ticks that may be extrapolated before the
//                              target is due, [0, 1); past it the actuator holds (late target)
//     "holdRamp": 0.005,       time over which the actuator slows to a hold when a target
//                              is late [s], >= 0 (0: it stops at once); see PredictorCorrector
//     "idleTimeout": 10        seconds of silence after which a console session is dropped
//   }
// plus the link fields both sides read (protocol, dataSize, ctrlSizes, daqSizes, initFile:
// core/config/LinkConfig.h, docs/openfresco.md).
//
// Ticks per step N = max(1, round(stepDuration * rate)); prediction ticks
// P = min(N - 1, floor(predictFraction * N)).

#include "core/config/TestConfig.h"

namespace hsmu::comms {

struct ControllerSettings {
    double rate = 1024.0;
    double stepDuration = 0.0;
    double predictFraction = 0.5;
    double holdRamp = 0.005;
    double idleTimeout = 10.0;

    /// Ticks of one integration step of dt seconds (>= 1).
    int ticksPerStep(double dt) const;
    /// Ticks that may be extrapolated before the target is due (0 .. ticksPerStep - 1).
    int predictTicks(double dt) const;
    /// Ticks over which a late command slows to a hold: round(holdRamp * rate).
    int holdRampTicks() const;
};

/// Read cfg.raw["controller"] (defaults when absent). Throws ConfigError naming the field.
ControllerSettings parseControllerSettings(const TestConfig& cfg);

} // namespace hsmu::comms
