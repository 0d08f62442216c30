#include "core/integration/AlphaOS.h"

#include "core/structure/Structure.h"

#include <limits>
#include <stdexcept>

namespace hsmu {

AlphaOS::AlphaOS(double alpha) : m_alpha(alpha)
{
    if (!(alpha >= -1.0 / 3.0 - 1e-12 && alpha <= 0.0))
        throw std::invalid_argument("alphaOS: alpha must lie in [-1/3, 0]");
    m_beta = (1.0 - alpha) * (1.0 - alpha) / 4.0;
    m_gamma = (1.0 - 2.0 * alpha) / 2.0;
}

double AlphaOS::stabilityLimit() const { return std::numeric_limits<double>::infinity(); }

void AlphaOS::initialize(const Structure& s, double dt, const Eigen::VectorXd& u0,
                         const Eigen::VectorXd& v0, double ag0, const Eigen::VectorXd& r0)
{
    Integrator::initialize(s, dt, u0, v0, ag0, r0);
    m_c.set(s.damping());
    m_k.set(s.initialStiffness());
    const double c = 1.0 + m_alpha;
    m_lhs.compute(Eigen::SparseMatrix<double>(
        s.mass() + c * (m_gamma * dt * s.damping() + m_beta * dt * dt * s.initialStiffness())));
    m_fPrev = -s.influence() * ag0 - m_c * v0 - r0;
}

Eigen::VectorXd AlphaOS::predict() const
{
    return m_u + m_dt * m_v + m_dt * m_dt * (0.5 - m_beta) * m_a;
}

bool AlphaOS::correct(const Eigen::VectorXd& rTrial, double agNext)
{
    const Eigen::VectorXd uTilde = predict();
    const Eigen::VectorXd vTilde = m_v + m_dt * (1.0 - m_gamma) * m_a;
    const Eigen::VectorXd fTilde = -m_s->influence() * agNext - m_c * vTilde - rTrial;
    const Eigen::VectorXd rhs = (1.0 + m_alpha) * fTilde - m_alpha * m_fPrev;
    const Eigen::VectorXd aNext = m_lhs.solve(rhs);
    if (!aNext.allFinite())
        return false;
    m_u = uTilde + m_beta * m_dt * m_dt * aNext;
    m_v = vTilde + m_gamma * m_dt * aNext;
    m_a = aNext;
    // Corrected restoring force of step n+1: R~ + K_I (u - u~).
    const Eigen::VectorXd rNext = rTrial + m_k * (m_u - uTilde);
    m_fPrev = -m_s->influence() * agNext - m_c * m_v - rNext;
    return true;
}

} // namespace hsmu
