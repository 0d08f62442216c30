#include "comms/controller/PredictorCorrector.h"

#include <algorithm>

namespace hsmu::comms {

void PredictorCorrector::setTiming(int ticksPerStep, int predictTicks) {
    m_n = std::max(1, ticksPerStep);
    m_p = std::clamp(predictTicks, 0, m_n - 1);
}

void PredictorCorrector::beginStep(double c, double h0, double h1, double h2) {
    m_command = c;
    m_h0 = h0;
    m_h1 = h1;
    m_h2 = h2;
    m_i = 0;
    m_j = 0;
    m_held = 0;
    m_phase = m_p > 0 ? Phase::Predicting : Phase::Late;
}

void PredictorCorrector::setTarget(double target) {
    m_target = target;
    m_from = m_command;
    m_remaining = std::max(1, m_n - std::min(m_i, m_p));
    m_j = 0;
    m_phase = Phase::Correcting;
}

void PredictorCorrector::stop() {
    m_phase = Phase::Stopped;
    m_i = std::max(m_i, m_p); // no prediction after a hold
    if (m_i >= m_n)
        m_i = m_p;
}

double PredictorCorrector::tick() {
    switch (m_phase) {
    case Phase::Predicting: {
        ++m_i;
        const double s = double(m_i) / double(m_n);
        m_command = m_h0 + s * (m_h0 - m_h1) + 0.5 * s * (s + 1.0) * (m_h0 - 2.0 * m_h1 + m_h2);
        if (m_i >= m_p)
            m_phase = Phase::Late;
        break;
    }
    case Phase::Late:
        ++m_held;
        break;
    case Phase::Correcting:
        ++m_j;
        ++m_i;
        if (m_j >= m_remaining) {
            m_command = m_target; // exactly: an ideal actuator ends the step on the target
            m_phase = Phase::Arrived;
            m_i = m_n;
        } else {
            m_command = m_from + (m_target - m_from) * double(m_j) / double(m_remaining);
        }
        break;
    case Phase::Arrived:
    case Phase::Stopped:
        break;
    }
    return m_command;
}

} // namespace hsmu::comms
