#include "core/updating/UkfIdentifier.h"

#include <stdexcept>

namespace hsmu {

namespace {
constexpr BoucWenUkfIndex kParams[] = {BoucWenUkfIndex::K0,    BoucWenUkfIndex::Alpha,
                                       BoucWenUkfIndex::Beta,  BoucWenUkfIndex::Gamma,
                                       BoucWenUkfIndex::N,     BoucWenUkfIndex::DeltaNu,
                                       BoucWenUkfIndex::DeltaEta};

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
        throw std::invalid_argument("updating.bounds: the bounds do not keep the Bouc-Wen law "
                                    "admissible (need lower <= upper, k0 > 0, 0 <= alpha <= 1, "
                                    "n > 0, deltas >= 0, beta + gamma > 0)");
    return a;
}
} // namespace

UkfIdentifier::UkfIdentifier(const BoucWenParameters& initial,
                             const BoucWenUkfSettings& settings, const ParameterBoundsMap& bounds)
    : m_ukf(initial, settings, toArray(bounds))
{
    for (BoucWenUkfIndex i : kParams) {
        const auto& b = m_ukf.bounds()[static_cast<int>(i)];
        m_bounds[boucWenUkfIndexName(i)] = {b.lower, b.upper};
    }
    publish(nullptr);
}

std::vector<std::string> UkfIdentifier::parameterNames() const
{
    std::vector<std::string> names;
    for (BoucWenUkfIndex i : kParams)
        names.emplace_back(boucWenUkfIndexName(i));
    return names;
}

void UkfIdentifier::publish(const BoucWenUkfStep* step)
{
    const BoucWenParameters p = step ? step->estimate : m_ukf.estimate();
    m_estimate = {{"k0", p.k0},     {"alpha", p.alpha},     {"beta", p.beta},
                  {"gamma", p.gamma}, {"n", p.n},             {"deltaNu", p.deltaNu},
                  {"deltaEta", p.deltaEta}};
    const Eigen::VectorXd sd = m_ukf.filter().initialized()
                                   ? m_ukf.filter().standardDeviations()
                                   : Eigen::VectorXd::Zero(kBoucWenUkfSize);
    for (BoucWenUkfIndex i : kParams)
        m_stddev[boucWenUkfIndexName(i)] =
            step ? step->standardDeviation[static_cast<int>(i)] : sd[static_cast<int>(i)];
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

bool UkfIdentifier::setBounds(const std::string& name, const ParameterBounds& b)
{
    auto i = indexOf(name);
    if (!i || !m_ukf.setBounds(*i, b.lower, b.upper))
        return false;
    m_bounds[name] = b;
    return true;
}

bool UkfIdentifier::setLocked(const std::string& name, bool locked)
{
    auto i = indexOf(name);
    return i && m_ukf.setLocked(*i, locked);
}

bool UkfIdentifier::locked(const std::string& name) const
{
    auto i = indexOf(name);
    return i && m_ukf.locked(*i);
}

} // namespace hsmu
