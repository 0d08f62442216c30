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
    Eigen::VectorXd u;
    predictInto(u);
    return u;
}

void ExplicitNewmark::predictInto(Eigen::VectorXd& out) const
{
    out = m_u + m_dt * m_v + 0.5 * m_dt * m_dt * m_a;
}

bool ExplicitNewmark::correct(const Eigen::VectorXd& rTrial, double agNext)
{
    m_vHalf = m_v + (1.0 - kGamma) * m_dt * m_a;
    m_c.multiply(m_vHalf, m_cv);
    m_rhs = -m_s->influence() * agNext - rTrial - m_cv;
    m_lhs.solve(m_rhs, m_aNext);
    if (!m_aNext.allFinite())
        return false;
    m_u = m_u + m_dt * m_v + 0.5 * m_dt * m_dt * m_a; // predict(), in place
    m_v = m_vHalf + kGamma * m_dt * m_aNext;
    m_a.swap(m_aNext); // m_aNext's old storage is overwritten by the next solve
    return true;
}

} // namespace hsmu
