#include "comms/controller/ActuatorLoop.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace hsmu::comms {

ActuatorLoop::ActuatorLoop(const ActuatorModel& model, double rate, std::string quantity)
    : m_actuator(model, rate), m_quantity(std::move(quantity)) {}

void ActuatorLoop::setTiming(int ticksPerStep, int predictTicks, int holdRampTicks) {
    m_pc.setTiming(ticksPerStep, predictTicks);
    m_pc.setHoldRamp(holdRampTicks);
}

void ActuatorLoop::setLimits(double bound, double increment) {
    m_bound = std::isfinite(bound) && bound > 0.0 ? bound : 0.0;
    m_pc.setDeformationLimit(bound);
    m_pc.setIncrementLimit(increment);
}

void ActuatorLoop::beginStep() {
    m_pc.beginStep(m_pc.command(), m_h0, m_h1, m_h2);
}

std::optional<std::string> ActuatorLoop::tick() {
    const double c = m_pc.tick();
    m_peak =
        std::isfinite(c) ? std::max(m_peak, std::abs(c)) : std::numeric_limits<double>::infinity();
    const double a = m_actuator.tick(c);
    if (std::isfinite(a) && !(m_bound > 0.0 && std::abs(a) > m_bound))
        return std::nullopt;
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s = %.6g exceeds the limit %.6g", m_quantity.c_str(),
                  std::abs(a), m_bound > 0.0 ? m_bound : std::numeric_limits<double>::infinity());
    return std::string(buf);
}

void ActuatorLoop::commit(double target) {
    m_h2 = m_h1;
    m_h1 = m_h0;
    m_h0 = target;
    beginStep();
}

void ActuatorLoop::restore(double position, double h0, double h1, double h2) {
    m_h0 = h0;
    m_h1 = h1;
    m_h2 = h2;
    m_actuator.reset(position);
    m_pc.beginStep(h0, h0, h1, h2);
}

} // namespace hsmu::comms
