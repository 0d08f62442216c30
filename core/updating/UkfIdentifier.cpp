#include "core/updating/UkfIdentifier.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace hsmu {

namespace {
constexpr BoucWenUkfIndex kParams[] = {BoucWenUkfIndex::K0,    BoucWenUkfIndex::Alpha,
                                       BoucWenUkfIndex::Beta,  BoucWenUkfIndex::Gamma,
                                       BoucWenUkfIndex::N,     BoucWenUkfIndex::DeltaNu,
                                       BoucWenUkfIndex::DeltaEta};

constexpr int at(BoucWenUkfIndex i) { return static_cast<int>(i); }

std::vector<std::string> layoutNames()
{
    std::vector<std::string> names;
    for (BoucWenUkfIndex i : kParams)
        names.emplace_back(boucWenUkfIndexName(i));
    return names;
}

std::optional<BoucWenUkfIndex> indexOf(const std::string& name)
{
    for (BoucWenUkfIndex i : kParams)
        if (name == boucWenUkfIndexName(i))
            return i;
    return std::nullopt;
}

BoucWenUkf::BoundsArray toArray(const ParameterBoundsMap& bounds)
{
    BoucWenUkf::BoundsArray a = BoucWenUkf::tableIIIBounds();
    for (const auto& [name, b] : bounds) {
        auto i = indexOf(name);
        if (!i)
            throw std::invalid_argument("updating.bounds: '" + name +
                                        "' is not identified by the UKF (expected k0, alpha, "
                                        "beta, gamma, n, deltaNu, deltaEta)");
        a[static_cast<int>(*i)] = {b.lower, b.upper};
    }
    if (!BoucWenUkf::boundsAdmissible(a))
        throw std::invalid_argument("updating.bounds: the bounds leave no admissible Bouc-Wen "
                                    "law (need finite lower <= upper, k0 > 0, "
                                    "0 <= alpha <= 1, n > 0, deltas >= 0 and upper beta + "
                                    "upper gamma > 0.001)");
    return a;
}
} // namespace

UkfIdentifier::UkfIdentifier(const BoucWenParameters& initial,
                             const BoucWenUkfSettings& settings, const ParameterBoundsMap& bounds)
    : m_ukf(initial, settings, toArray(bounds)), m_layout(layoutNames())
{
    for (std::size_t k = 0; k < std::size(kParams); ++k) {
        const auto& b = m_ukf.bounds()[at(kParams[k])];
        m_bounds[k] = {b.lower, b.upper};
    }
    publish(nullptr);
}

void UkfIdentifier::publish(const BoucWenUkfStep* step)
{
    const BoucWenParameters p = step ? step->estimate : m_ukf.estimate();
    m_estimate = {p.k0, p.alpha, p.beta, p.gamma, p.n, p.deltaNu, p.deltaEta}; // kParams order
    if (step) {
        for (std::size_t k = 0; k < std::size(kParams); ++k)
            m_stddev[k] = step->standardDeviation[std::size_t(at(kParams[k]))];
        return;
    }
    const Eigen::VectorXd sd = m_ukf.filter().initialized()
                                   ? m_ukf.filter().standardDeviations()
                                   : Eigen::VectorXd::Zero(kBoucWenUkfSize);
    for (std::size_t k = 0; k < std::size(kParams); ++k)
        m_stddev[k] = sd[at(kParams[k])];
}

IdentificationStatus UkfIdentifier::observe(double deformation, double force, bool)
{
    const BoucWenUkfStep s = m_ukf.step(deformation, force);
    m_predicted = s.predictedForce;
    publish(&s);
    IdentificationStatus st;
    st.ok = s.status.ok;
    st.updated = s.status.ok;
    if (!s.status.ok)
        st.message = s.status.reason;
    return st;
}

bool UkfIdentifier::setBounds(std::size_t index, const ParameterBounds& b)
{
    if (index >= std::size(kParams) || !m_ukf.setBounds(kParams[index], b.lower, b.upper))
        return false;
    m_bounds[index] = b;
    return true;
}

bool UkfIdentifier::setLocked(std::size_t index, bool locked)
{
    return index < std::size(kParams) && m_ukf.setLocked(kParams[index], locked);
}

bool UkfIdentifier::locked(std::size_t index) const
{
    return index < std::size(kParams) && m_ukf.locked(kParams[index]);
}

} // namespace hsmu
