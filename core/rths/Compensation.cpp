#include "core/rths/Compensation.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsmu::rths {

const char* compensationTypeName(CompensationSettings::Type t)
{
    switch (t) {
    case CompensationSettings::Type::None: return "none";
    case CompensationSettings::Type::Polynomial: return "polynomial";
    case CompensationSettings::Type::Feedforward: return "feedforward";
    case CompensationSettings::Type::Ats: return "ats";
    }
    return "none";
}

bool parseCompensationType(const std::string& s, CompensationSettings::Type& out)
{
    for (auto t : {CompensationSettings::Type::None, CompensationSettings::Type::Polynomial,
                   CompensationSettings::Type::Feedforward, CompensationSettings::Type::Ats})
        if (s == compensationTypeName(t)) {
            out = t;
            return true;
        }
    return false;
}

namespace {
constexpr int kStride = 8; // ATS: finite differences over 8 loop periods
} // namespace

Compensator::Compensator(const CompensationSettings& s, double h)
    : m_s(s), m_h(h), m_c{s.c0, s.c1, s.c2}
{
    if (!(h > 0.0))
        throw std::invalid_argument("compensation: the loop period must be positive");
    if (s.type == CompensationSettings::Type::Polynomial && (s.order < 1 || s.order > 5))
        throw std::invalid_argument("compensation: the polynomial order must be 1 to 5");
    if (s.lead.enabled)
        m_lead = FirstOrderSection::lead(s.lead.gain, s.lead.zero, s.lead.pole, h);
    m_alpha = 1.0 - std::exp(-2.0 * M_PI * s.filterFrequency * h);
    m_tauEstimate = s.delay;
}

void Compensator::reset(double x)
{
    m_past.clear();
    m_lead.reset(x, x * m_lead.dcGain());
    m_fu = {x, x};
    m_fx = {x, x};
    m_u.clear();
    m_xm.clear();
    m_ticks = 0;
    m_lastPrimary = x;
}

double Compensator::primary(const TargetState& t)
{
    using T = CompensationSettings::Type;
    switch (m_s.type) {
    case T::None:
        return t.x;
    case T::Feedforward:
    case T::Ats:
        return m_c[0] * t.x + m_c[1] * t.v + m_c[2] * t.a;
    case T::Polynomial: {
        m_past.push_front(t.x);
        while (int(m_past.size()) > m_s.order + 1)
            m_past.pop_back();
        const int n = int(m_past.size());
        // Lagrange polynomial through (0, x0), (-h, x1), ...; evaluated at tau.
        const double tau = m_s.estimateDelay ? m_tauEstimate : m_s.delay;
        double out = 0.0;
        for (int i = 0; i < n; ++i) {
            double w = 1.0;
            for (int j = 0; j < n; ++j)
                if (j != i)
                    w *= (tau + j * m_h) / ((j - i) * m_h);
            out += w * m_past[std::size_t(i)];
        }
        return out;
    }
    }
    return t.x;
}

double Compensator::command(const TargetState& target)
{
    m_lastPrimary = primary(target);
    return m_s.lead.enabled ? m_lead.step(m_lastPrimary) : m_lastPrimary;
}

void Compensator::observe(double measured)
{
    if (m_s.type != CompensationSettings::Type::Ats)
        return;
    // The fit maps the primary output (before the lead): a0..a2 describe the inverse of
    // everything downstream of it (lead, servo-controller, plant, sensors).
    m_u.push_back(m_fu.step(m_lastPrimary, m_alpha));
    m_xm.push_back(m_fx.step(measured, m_alpha));
    while (int(m_u.size()) > 2 * kStride + 1) {
        m_u.pop_front();
        m_xm.pop_front();
    }
    if (++m_ticks % std::max<long>(1, long(m_s.updateInterval / m_h)) == 0)
        refit();
    if (int(m_xm.size()) < 2 * kStride + 1)
        return;
    const double dh = kStride * m_h;
    const double x0 = m_xm[0], x1 = m_xm[kStride], x2 = m_xm[2 * kStride];
    const Eigen::Vector3d phi(x1, (x2 - x0) / (2.0 * dh), (x2 - 2.0 * x1 + x0) / (dh * dh));
    const double lambda = 1.0 - m_h / m_s.window;
    m_r = lambda * m_r + phi * phi.transpose();
    m_q = lambda * m_q + phi * m_u[kStride];
}

void Compensator::refit()
{
    if (m_r.trace() <= 0.0)
        return;
    const Eigen::Vector3d a = m_r.ldlt().solve(m_q);
    if (!a.allFinite())
        return;
    const double lo[3] = {0.5, 0.0, -m_s.maxC2}, hi[3] = {2.0, m_s.maxC1, m_s.maxC2};
    const double scale[3] = {1.0, m_s.maxC1, m_s.maxC2};
    for (int i = 0; i < 3; ++i) {
        const double step = m_s.maxChange * scale[i];
        const double target = std::clamp(a(i), lo[i], hi[i]);
        m_c[i] = std::clamp(target, m_c[i] - step, m_c[i] + step);
    }
}

void fitFeedforward(const LoopResponse& t, double fLow, double fHigh, CompensationSettings& s)
{
    // Linear least squares in c: rows Re/Im of (c0 + c1 jw - c2 w^2) T - 1 = 0.
    const int points = 200;
    Eigen::MatrixXd a(2 * points, 3);
    Eigen::VectorXd b(2 * points);
    for (int i = 0; i < points; ++i) {
        const double f = fLow * std::pow(fHigh / fLow, double(i) / (points - 1));
        const double w = 2.0 * M_PI * f;
        const std::complex<double> tw = t(w);
        const std::complex<double> col[3] = {tw, std::complex<double>(0.0, w) * tw, -w * w * tw};
        for (int j = 0; j < 3; ++j) {
            a(2 * i, j) = col[j].real();
            a(2 * i + 1, j) = col[j].imag();
        }
        b(2 * i) = 1.0;
        b(2 * i + 1) = 0.0;
    }
    const Eigen::Vector3d c = a.colPivHouseholderQr().solve(b);
    s.c0 = c(0);
    s.c1 = c(1);
    s.c2 = c(2);
}

} // namespace hsmu::rths
