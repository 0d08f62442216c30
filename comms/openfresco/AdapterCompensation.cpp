#include "comms/openfresco/AdapterCompensation.h"

#include <algorithm>
#include <cmath>

namespace hsmu::comms::of {

namespace {

/// Whether a step of du continues a step of before in the same direction.
bool sameDirection(double before, double du) {
    return before * du > 0.0;
}

} // namespace

void AdapterCompensation::predict(double d, double& force, double& tangent) const {
    // m_d[2], m_f[2]: the last committed step; m_d[1], m_d[0] the two before it (the state at
    // rest, 0 and 0, counts as the step before the first).
    force = m_f[2];
    tangent = 0.0;
    if (m_steps < 1)
        return;
    const double h1 = m_d[2] - m_d[1];
    const double scale = std::max({std::abs(d), std::abs(m_d[2]), std::abs(m_d[1])});
    if (!(std::abs(h1) > 1e-8 * scale)) { // no usable last step: keep the last tangent
        tangent = m_k;
        force = m_f[2] + tangent * (d - m_d[2]);
        return;
    }
    const double s1 = (m_f[2] - m_f[1]) / h1;
    if (!sameDirection(h1, d - m_d[2])) {
        // The motion reverses: a hysteretic substructure unloads along a stiffer branch than
        // the secant of the loading step; the secant of the last reversal step estimates it.
        tangent = m_kReversal > 0.0 ? m_kReversal : s1;
        force = m_f[2] + tangent * (d - m_d[2]);
        return;
    }
    tangent = s1;
    force = m_f[2] + s1 * (d - m_d[2]);
    const double h0 = m_d[1] - m_d[0];
    if (m_steps >= 2 && sameDirection(h0, h1) && std::abs(h0) > 1e-8 * scale) {
        // Three steps on one branch: the parabola through them (Newton's divided differences).
        const double s0 = (m_f[1] - m_f[0]) / h0;
        const double c = (s1 - s0) / (m_d[2] - m_d[0]);
        force += c * (d - m_d[2]) * (d - m_d[1]);
        tangent += c * ((d - m_d[2]) + (d - m_d[1]));
    }
}

double AdapterCompensation::command(double d) {
    m_target = d;
    double predicted = 0.0;
    predict(d, predicted, m_kStep);
    if (!std::isfinite(predicted) || !std::isfinite(m_kStep)) {
        predicted = m_f[2];
        m_kStep = 0.0;
    }
    m_sent = d;
    if (m_opt.predictTarget && m_kb > 0.0)
        if (const double sent = d + predicted / m_kb; std::isfinite(sent))
            m_sent = sent;
    return m_sent;
}

AdapterCompensation::Corrected AdapterCompensation::correct(double daqDisp, double daqForce) {
    // q = KB (s - db) as the adapter computes it; s - db is exact (the two are close).
    if (const double gap = m_sent - daqDisp; gap != 0.0) {
        const double kb = daqForce / gap;
        if (std::isfinite(kb) && kb > 0.0)
            m_kb = kb;
    }
    m_now.deformation = daqDisp;
    m_now.force = daqForce;
    if (m_opt.correctForce) {
        m_now.deformation = m_target;
        m_now.force = daqForce + endTangent(daqDisp, daqForce) * (m_target - daqDisp);
    }
    return m_now;
}

double AdapterCompensation::endTangent(double db, double q) const {
    // The tangent at the point just measured, from that point and the committed history
    // (what the step did, not what was predicted: at a reversal the prediction is the weakest).
    const double h = db - m_d[2];
    const double scale = std::max(std::abs(db), std::abs(m_d[2]));
    if (!(std::abs(h) > 1e-8 * scale))
        return m_kStep;
    const double s = (q - m_f[2]) / h;
    if (m_steps < 1)
        return std::isfinite(s) ? s : m_kStep;
    const double h1 = m_d[2] - m_d[1];
    double t = s;
    if (sameDirection(h1, h) && std::abs(h1) > 1e-8 * scale) {
        // The parabola through the last two committed points and this one: its slope at db.
        const double s1 = (m_f[2] - m_f[1]) / h1;
        t = s + (s - s1) / (db - m_d[1]) * h;
    }
    return std::isfinite(t) ? t : m_kStep;
}

void AdapterCompensation::commit() {
    const double step = m_target - m_d[2];
    const double scale = std::max(std::abs(m_target), std::abs(m_d[2]));
    if (std::abs(step) > 1e-8 * scale) {
        const double secant = (m_now.force - m_f[2]) / step;
        if (std::isfinite(secant)) {
            const bool reversal = m_steps >= 1 && !sameDirection(m_d[2] - m_d[1], step);
            if (reversal || m_kReversal == 0.0)
                m_kReversal = secant;
            m_k = secant;
        }
    }
    m_d[0] = m_d[1];
    m_d[1] = m_d[2];
    m_d[2] = m_target;
    m_f[0] = m_f[1];
    m_f[1] = m_f[2];
    m_f[2] = m_now.force;
    ++m_steps;
}

} // namespace hsmu::comms::of
