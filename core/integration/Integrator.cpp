#include "core/integration/Integrator.h"

#include "core/integration/StepMatrix.h"
#include "core/structure/Structure.h"

namespace hsmu {

void Integrator::initialize(const Structure& s, double dt, const Eigen::VectorXd& u0,
                            const Eigen::VectorXd& v0, double ag0, const Eigen::VectorXd& r0)
{
    m_s = &s;
    m_dt = dt;
    m_u = u0;
    m_v = v0;
    StepMatrix c;
    c.set(s.damping());
    const Eigen::VectorXd f = -s.influence() * ag0 - c * v0 - r0;
    m_a = f.cwiseQuotient(s.massDiagonal()); // M is lumped (diagonal)
}

} // namespace hsmu
