#include "comms/controller/PredictorCorrector.h"

#include <algorithm>
#include <cmath>

namespace hsmu::comms {

void PredictorCorrector::setTiming(int ticksPerStep, int predictTicks) {
    m_n = std::max(1, ticksPerStep);
    m_p = std::clamp(predictTicks, 0, m_n - 1);
}

void PredictorCorrector::setHoldRamp(int ticks) { m_ramp = std::max(0, ticks); }

void PredictorCorrector::setIncrementLimit(double limit) {
    // 0 (no bound) also for a zero limit: it refuses every target, there is nothing to move.
    m_limit = std::isfinite(limit) && limit > 0.0 ? limit : 0.0;
}

void PredictorCorrector::setDeformationLimit(double limit) {
    m_bound = std::isfinite(limit) && limit > 0.0 ? limit : 0.0;
}

void PredictorCorrector::beginStep(double c, double h0, double h1, double h2) {
    m_command = c;
    m_h0 = h0;
    m_h1 = h1;
    m_h2 = h2;
    m_i = 0;
    m_j = 0;
    m_held = 0;
    m_lateVelocity = m_velocity;
    m_phase = m_p > 0 ? Phase::Predicting : Phase::Late;
}

void PredictorCorrector::setTarget(double target) {
    m_target = target;
    m_from = m_command;
    m_remaining = std::max(1, m_n - std::min(m_i, m_p));
    m_j = 0;
    m_smooth = m_phase == Phase::Late && m_held > 0;
    m_resumeVelocity = m_smooth ? m_velocity : 0.0;
    m_phase = Phase::Correcting;
}

void PredictorCorrector::stop() {
    m_phase = Phase::Stopped;
    m_velocity = 0.0;
    m_i = std::max(m_i, m_p); // no prediction after a hold
    if (m_i >= m_n)
        m_i = m_p;
}

void PredictorCorrector::moveTo(double c) {
    if (m_limit > 0.0)
        c = std::clamp(c, m_h0 - m_limit, m_h0 + m_limit);
    if (m_bound > 0.0)
        c = std::clamp(c, -m_bound, m_bound);
    m_velocity = c - m_command;
    m_command = c;
}

double PredictorCorrector::tick() {
    switch (m_phase) {
    case Phase::Predicting: {
        ++m_i;
        const double s = double(m_i) / double(m_n);
        moveTo(m_h0 + s * (m_h0 - m_h1) + 0.5 * s * (s + 1.0) * (m_h0 - 2.0 * m_h1 + m_h2));
        if (m_i >= m_p) {
            m_phase = Phase::Late;
            m_lateVelocity = m_velocity;
        }
        break;
    }
    case Phase::Late:
        ++m_held;
        if (m_held < m_ramp)
            moveTo(m_command + m_lateVelocity * double(m_ramp - m_held) / double(m_ramp));
        else
            m_velocity = 0.0;
        break;
    case Phase::Correcting:
        ++m_j;
        ++m_i;
        if (m_j >= m_remaining) {
            // Exactly: an ideal actuator ends the step on the target (checked by the interlock).
            m_velocity = m_target - m_command;
            m_command = m_target;
            m_phase = Phase::Arrived;
            m_i = m_n;
        } else if (m_smooth) {
            const double s = double(m_j) / double(m_remaining);
            const double s2 = s * s, s3 = s2 * s;
            moveTo(m_from + double(m_remaining) * m_resumeVelocity * (s3 - 2.0 * s2 + s) +
                   (m_target - m_from) * (2.0 * s2 - s3));
        } else {
            const double c = m_from + (m_target - m_from) * double(m_j) / double(m_remaining);
            m_velocity = c - m_command;
            m_command = c; // linear: between c0 and T, inside the limit if both are
        }
        break;
    case Phase::Arrived:
    case Phase::Stopped:
        m_velocity = 0.0;
        break;
    }
    return m_command;
}

} // namespace hsmu::comms
