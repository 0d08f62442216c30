#include "core/integration/ExplicitNewmark.h"

#include "core/structure/Structure.h"

namespace hsmu {

void ExplicitNewmark::initialize(const Structure& s, double dt, const Eigen::VectorXd& u0,
                                 const Eigen::VectorXd& v0, double ag0, const Eigen::VectorXd& r0)
{
    Integrator::initialize(s, dt, u0, v0, ag0, r0);
    m_c.set(s.damping());
    m_lhs.compute(Eigen::SparseMatrix<double>(s.mass() + kGamma * dt * s.damping()));
}

Eigen::VectorXd ExplicitNewmark::predict() const
{
    return m_u + m_dt * m_v + 0.5 * m_dt * m_dt * m_a;
}

bool ExplicitNewmark::correct(const Eigen::VectorXd& rTrial, double agNext)
{
    const Eigen::VectorXd vHalf = m_v + (1.0 - kGamma) * m_dt * m_a;
    const Eigen::VectorXd rhs = -m_s->influence() * agNext - rTrial - m_c * vHalf;
    const Eigen::VectorXd aNext = m_lhs.solve(rhs);
    if (!aNext.allFinite())
        return false;
    m_u = m_u + m_dt * m_v + 0.5 * m_dt * m_dt * m_a; // predict(), in place
    m_v = vHalf + kGamma * m_dt * aNext;
    m_a = aNext;
    return true;
}

} // namespace hsmu
