#include "core/structure/Element.h"

namespace hsmu {

Element::Element(std::string name, std::vector<DofTerm> terms)
    : m_name(std::move(name)), m_terms(std::move(terms))
{
}

double Element::kinematicDeformation(const Eigen::VectorXd& uFull) const
{
    double q = 0.0;
    for (const auto& t : m_terms)
        q += t.coefficient * uFull[t.dof];
    return q;
}

void Element::addNodalForces(Eigen::VectorXd& rFull) const
{
    const double p = generalizedForce();
    for (const auto& t : m_terms)
        rFull[t.dof] += t.coefficient * p;
}

void Element::addInitialStiffness(std::vector<Eigen::Triplet<double>>& k,
                                  const std::vector<int>& freeOf) const
{
    const double k0 = initialGeneralizedStiffness();
    for (const auto& a : m_terms)
        for (const auto& b : m_terms)
            k.emplace_back(freeOf[a.dof], freeOf[b.dof], a.coefficient * b.coefficient * k0);
}

} // namespace hsmu
