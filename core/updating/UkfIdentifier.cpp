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

// kParams sorted by name: the order of estimate()'s map, i.e. estimateNames().
const std::array<BoucWenUkfIndex, std::size(kParams)> kSorted = [] {
    std::array<BoucWenUkfIndex, std::size(kParams)> a{};
    std::copy(std::begin(kParams), std::end(kParams), a.begin());
    std::sort(a.begin(), a.end(), [](BoucWenUkfIndex x, BoucWenUkfIndex y) {
        return std::string(boucWenUkfIndexName(x)) < std::string(boucWenUkfIndexName(y));
    });
    return a;
}();

constexpr int at(BoucWenUkfIndex i) { return static_cast<int>(i); }

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
    m_estimate[at(BoucWenUkfIndex::K0)] = p.k0;
    m_estimate[at(BoucWenUkfIndex::Alpha)] = p.alpha;
    m_estimate[at(BoucWenUkfIndex::Beta)] = p.beta;
    m_estimate[at(BoucWenUkfIndex::Gamma)] = p.gamma;
    m_estimate[at(BoucWenUkfIndex::N)] = p.n;
    m_estimate[at(BoucWenUkfIndex::DeltaNu)] = p.deltaNu;
    m_estimate[at(BoucWenUkfIndex::DeltaEta)] = p.deltaEta;
    if (step) {
        m_stddev = step->standardDeviation;
        return;
    }
    const Eigen::VectorXd sd = m_ukf.filter().initialized()
                                   ? m_ukf.filter().standardDeviations()
                                   : Eigen::VectorXd::Zero(kBoucWenUkfSize);
    for (int i = 0; i < kBoucWenUkfSize; ++i)
        m_stddev[i] = sd[i];
}

ParameterValues UkfIdentifier::estimate() const
{
    ParameterValues out;
    for (BoucWenUkfIndex i : kParams)
        out[boucWenUkfIndexName(i)] = m_estimate[at(i)];
    return out;
}

ParameterValues UkfIdentifier::standardDeviation() const
{
    ParameterValues out;
    for (BoucWenUkfIndex i : kParams)
        out[boucWenUkfIndexName(i)] = m_stddev[at(i)];
    return out;
}

std::vector<std::string> UkfIdentifier::estimateNames() const
{
    std::vector<std::string> names;
    for (BoucWenUkfIndex i : kSorted)
        names.emplace_back(boucWenUkfIndexName(i));
    return names;
}

void UkfIdentifier::estimateValues(std::vector<double>& out) const
{
    out.resize(kSorted.size());
    for (std::size_t k = 0; k < kSorted.size(); ++k)
        out[k] = m_estimate[at(kSorted[k])];
}

void UkfIdentifier::standardDeviationValues(std::vector<double>& out) const
{
    out.resize(kSorted.size());
    for (std::size_t k = 0; k < kSorted.size(); ++k)
        out[k] = m_stddev[at(kSorted[k])];
}

void UkfIdentifier::boundsValues(std::vector<ParameterBounds>& out) const
{
    out.resize(kSorted.size());
    for (std::size_t k = 0; k < kSorted.size(); ++k) {
        const BoucWenUkf::Bounds& b = m_ukf.bounds()[at(kSorted[k])];
        out[k] = {b.lower, b.upper};
    }
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
