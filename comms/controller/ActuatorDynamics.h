#pragma once
// ActuatorDynamics: servo-actuator tracking between the command c and the achieved
// displacement a, advanced once per controller tick of h = 1 / rate seconds:
//   ideal: a = c
//   lag:   a += (c - a) (1 - exp(-h / tau))        (first-order lag, time constant tau [s])
//   delay: a[i] = c[i - D], D = round(delay / h)   (pure delay of D ticks)
//   servoHydraulic: one tick of rths::ServoActuator (servo-controller + plant, docs/rths.md)
// The model (type, tau, delay) is the specimen section's `actuator` (ActuatorModel), run
// here at the loop rate rather than once per integration step as in VirtualSpecimen.
// reset(x) puts the actuator at rest at x (the delay line filled with x).

#include "core/experimental/VirtualSpecimen.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace hsmu::comms {

class ActuatorDynamics {
public:
    ActuatorDynamics(const ActuatorModel& model, double rate);

    void reset(double position);
    /// One tick with command c; returns the achieved displacement.
    double tick(double command);
    double position() const { return m_position; }
    bool ideal() const { return m_model.type == ActuatorModel::Type::Ideal; }
    const ActuatorModel& model() const { return m_model; }

private:
    ActuatorModel m_model;
    double m_lagFactor = 1.0;
    std::vector<double> m_line; // ring buffer of the last D commands
    std::size_t m_head = 0;
    double m_position = 0.0;
    std::optional<rths::ServoActuator> m_servo;
};

} // namespace hsmu::comms
