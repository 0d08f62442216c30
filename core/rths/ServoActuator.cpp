#include "core/rths/ServoActuator.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hsmu::rths {

ServoActuator::ServoActuator(const ServoActuatorSettings& s)
    : m_s(s), m_plant(s.plant), m_pid(s.pid, 1.0 / s.rate), m_h(1.0 / s.rate)
{
    if (const std::string why = s.plant.validate(); !why.empty())
        throw std::invalid_argument("servo-hydraulic actuator: " + why);
    if (!(s.metresPerUnit > 0.0))
        throw std::invalid_argument("servo-hydraulic actuator: metresPerUnit must be positive");
    if (s.lead.enabled)
        m_lead = FirstOrderSection::lead(s.lead.gain, s.lead.zero, s.lead.pole, m_h);
    reset(0.0);
}

void ServoActuator::reset(double x)
{
    const double xm = x * m_s.metresPerUnit;
    m_plant.reset(xm);
    // At rest the valve needs g u = x + b2 Q / a1b0 with Q = a3 ke x (eqs. P1, P2).
    const auto& p = m_s.plant;
    m_pid.reset((xm + p.b2 * p.a3 * p.ke * xm / p.a1b0) / p.g);
    m_lead.reset(xm, xm * m_lead.dcGain());
}

double ServoActuator::tick(double command)
{
    double r = command * m_s.metresPerUnit;
    if (m_s.lead.enabled)
        r = m_lead.step(r);
    double x = m_plant.displacement();
    if (m_s.quantum > 0.0)
        x = m_s.quantum * std::round(x / m_s.quantum);
    m_plant.advance(m_pid.step(r - x), m_h);
    return position();
}

double ServoActuator::advance(double command, double dt)
{
    const long n = std::max(1L, std::lround(dt * m_s.rate));
    for (long i = 0; i < n; ++i)
        tick(command);
    return position();
}

std::string ServoActuator::limitBreach() const
{
    return plantLimitBreach(m_plant, m_s.limits);
}

} // namespace hsmu::rths
