#include "core/structure/FlexibleColumnSpring.h"

#include <cmath>

namespace hsmu {

FlexibleColumnSpring::FlexibleColumnSpring(std::string name, int dof, double height, double ei,
                                           std::unique_ptr<HysteresisLaw> law)
    : Element(std::move(name), {{dof, 1.0 / height}}), m_law(std::move(law)),
      m_flex(height / (3.0 * ei))
{
}

double FlexibleColumnSpring::initialGeneralizedStiffness() const
{
    return 1.0 / (1.0 / m_law->initialTangent() + m_flex);
}

ElementStatus FlexibleColumnSpring::setTrial(const Eigen::VectorXd& uFull)
{
    const double q = kinematicDeformation(uFull);
    auto residual = [&](double theta, double& slope) -> bool {
        if (m_law->setTrialDeformation(theta) != LawStatus::Ok)
            return false;
        slope = 1.0 + m_flex * m_law->trialTangent();
        return true;
    };
    // g(theta) = theta + flex M(theta) - q is increasing while the spring tangent exceeds
    // -1/flex; every evaluation narrows a bracket and Newton steps leaving it bisect.
    double theta = m_law->committedDeformation();
    double lo = -INFINITY;
    double hi = INFINITY;
    const double tol = 1e-13 * std::max(1.0, std::abs(q));
    for (int it = 0; it < 100; ++it) {
        double slope = 0.0;
        if (!residual(theta, slope))
            return ElementStatus::failure(name() + ": spring law did not converge");
        const double g = theta + m_flex * m_law->trialForce() - q;
        if (std::abs(g) <= tol)
            return ElementStatus::success();
        (g > 0 ? hi : lo) = theta;
        double next = theta - g / slope;
        if (!(slope > 0) || !(next > lo && next < hi)) {
            if (std::isfinite(lo) && std::isfinite(hi))
                next = 0.5 * (lo + hi);
            else // no bracket yet: step by the column-free estimate
                next = theta - g;
        }
        theta = next;
    }
    return ElementStatus::failure(name() + ": column-spring compatibility did not converge");
}

ElementStatus FlexibleColumnSpring::commit()
{
    m_law->commit();
    return ElementStatus::success();
}

} // namespace hsmu
