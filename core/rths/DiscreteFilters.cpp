#include "core/rths/DiscreteFilters.h"

#include <stdexcept>

namespace hsmu::rths {

FirstOrderSection::FirstOrderSection(double n1, double n0, double d1, double d0, double h)
{
    const double c = 2.0 / h;
    const double a0 = d1 * c + d0;
    if (a0 == 0.0)
        throw std::invalid_argument("first-order section: the denominator vanishes");
    m_b0 = (n1 * c + n0) / a0;
    m_b1 = (n0 - n1 * c) / a0;
    m_a1 = (d0 - d1 * c) / a0;
}

FirstOrderSection FirstOrderSection::lead(double gain, double zero, double pole, double h)
{
    return {gain, gain * zero, 1.0, pole, h};
}

double FirstOrderSection::step(double x)
{
    const double y = m_b0 * x + m_b1 * m_x - m_a1 * m_y;
    m_x = x;
    m_y = y;
    return y;
}

void FirstOrderSection::reset(double x, double y)
{
    m_x = x;
    m_y = y;
}

double FirstOrderSection::dcGain() const { return (m_b0 + m_b1) / (1.0 + m_a1); }

Pid::Pid(const PidGains& gains, double h) : m_g(gains), m_h(h)
{
    if (!(h > 0.0))
        throw std::invalid_argument("PID: the loop period must be positive");
    if (gains.kd != 0.0 && !(gains.tauD > 0.0))
        throw std::invalid_argument("PID: a derivative gain needs a filter time constant tauD > 0");
}

double Pid::step(double e)
{
    m_integral += m_g.ki * 0.5 * m_h * (e + m_ePrev); // Tustin integral
    if (m_g.kd != 0.0) {
        // Kd s / (tauD s + 1) by Tustin: d = ((2 tauD - h) d + 2 Kd (e - e_prev)) / (2 tauD + h)
        m_d = ((2.0 * m_g.tauD - m_h) * m_d + 2.0 * m_g.kd * (e - m_ePrev)) /
              (2.0 * m_g.tauD + m_h);
    }
    m_ePrev = e;
    return m_g.kp * e + m_integral + m_d;
}

void Pid::reset(double u0)
{
    m_integral = u0;
    m_ePrev = 0.0;
    m_d = 0.0;
}

} // namespace hsmu::rths
