#include "core/structure/Structure.h"

#include "core/structure/ModalAnalysis.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsmu {

RayleighDamping RayleighDamping::fromRatio(double zeta, double w1, double w2)
{
    if (std::abs(w1 - w2) < 1e-12 * std::max(w1, w2))
        return {zeta * w1, zeta / w1};
    return {2.0 * zeta * w1 * w2 / (w1 + w2), 2.0 * zeta / (w1 + w2)};
}

int Structure::addDof(std::string name, double mass, double influence)
{
    m_dofNames.push_back(std::move(name));
    m_masses.push_back(mass);
    m_iota.push_back(influence);
    return static_cast<int>(m_dofNames.size()) - 1;
}

void Structure::addElement(std::unique_ptr<Element> element)
{
    m_elements.push_back(std::move(element));
}

void Structure::addEqualDof(int master, int slave) { m_equalDofs.emplace_back(master, slave); }

void Structure::setModalDamping(double zeta, int modeI, int modeJ)
{
    m_modalZeta = zeta;
    m_modeI = modeI;
    m_modeJ = modeJ;
}

Element* Structure::element(const std::string& name) const
{
    for (const auto& e : m_elements)
        if (e->name() == name)
            return e.get();
    return nullptr;
}

void Structure::finalize()
{
    const int n = fullDofCount();
    if (n == 0)
        throw std::invalid_argument("structure has no DOFs");
    auto checkDof = [n](int d, const std::string& where) {
        if (d < 0 || d >= n)
            throw std::invalid_argument(where + ": DOF index " + std::to_string(d) +
                                        " is outside 0.." + std::to_string(n - 1));
    };
    std::vector<int> master(n);
    for (int i = 0; i < n; ++i)
        master[i] = i;
    for (const auto& [m, s] : m_equalDofs) {
        checkDof(m, "equalDof master");
        checkDof(s, "equalDof slave");
        if (m == s)
            throw std::invalid_argument("equalDof: master and slave are both DOF " +
                                        std::to_string(m));
        if (master[s] != s)
            throw std::invalid_argument("equalDof: DOF " + std::to_string(s) +
                                        " is constrained twice");
        master[s] = m;
    }
    // Resolve chains (a slave's master may itself be a slave), detecting cycles.
    for (int i = 0; i < n; ++i) {
        int r = i;
        for (int hops = 0; master[r] != r; ++hops) {
            if (hops > n)
                throw std::invalid_argument("equalDof constraints form a cycle through DOF " +
                                            std::to_string(i));
            r = master[r];
        }
        master[i] = r;
    }
    buildOrder();
    std::vector<int> freeIndex(n, -1);
    int nFree = 0;
    for (int i = 0; i < n; ++i)
        if (master[i] == i)
            freeIndex[i] = nFree++;
    m_freeOf.assign(n, 0);
    for (int i = 0; i < n; ++i)
        m_freeOf[i] = freeIndex[master[i]];
    using Triplet = Eigen::Triplet<double>;
    std::vector<Triplet> triplets;
    triplets.reserve(n);
    for (int i = 0; i < n; ++i)
        triplets.emplace_back(i, m_freeOf[i], 1.0);
    m_t.resize(n, nFree);
    m_t.setFromTriplets(triplets.begin(), triplets.end());

    Eigen::VectorXd mFull(n);
    for (int i = 0; i < n; ++i) {
        if (!(m_masses[i] >= 0.0) || !std::isfinite(m_masses[i]))
            throw std::invalid_argument("DOF '" + m_dofNames[i] + "': mass must be >= 0");
        mFull[i] = m_masses[i];
    }
    // M = T^T M_full T: each free DOF carries the masses merged into it (diagonal).
    m_mDiag = Eigen::VectorXd::Zero(nFree);
    for (int i = 0; i < n; ++i)
        m_mDiag[m_freeOf[i]] += mFull[i];
    for (int j = 0; j < nFree; ++j)
        if (!(m_mDiag[j] > 0.0))
            throw std::invalid_argument(
                "free DOF " + std::to_string(j) +
                " has no mass (an explicit integrator needs a positive mass on every DOF)");
    m_m.resize(nFree, nFree);
    m_m.reserve(Eigen::VectorXi::Constant(nFree, 1));
    for (int j = 0; j < nFree; ++j)
        m_m.insert(j, j) = m_mDiag[j];
    m_m.makeCompressed();
    m_influence = Eigen::VectorXd::Zero(nFree); // T^T M_full iota
    for (int i = 0; i < n; ++i) {
        if (!std::isfinite(m_iota[i]))
            throw std::invalid_argument("DOF '" + m_dofNames[i] + "': influence must be finite");
        m_influence[m_freeOf[i]] += mFull[i] * m_iota[i];
    }

    for (const auto& e : m_elements)
        for (const auto& t : e->terms())
            checkDof(t.dof, "element '" + e->name() + "'");
    m_k0 = assembleInitialStiffness();

    if (nFree <= kDenseModalLimit) {
        m_omega = denseFrequencies(m_k0, m_mDiag);
        m_omegaMax = m_omega.maxCoeff();
    } else {
        const int wanted = m_modalZeta >= 0.0 ? std::max({m_modeI, m_modeJ, 3}) : 3;
        m_omega = lowestFrequencies(m_k0, m_mDiag, std::min(wanted, nFree));
        m_omegaMax = largestFrequency(m_k0, m_mDiag);
    }

    if (m_modalZeta >= 0.0) {
        auto w = [&](int mode) {
            const int idx = std::clamp(mode, 1, nFree) - 1;
            return m_omega[idx];
        };
        const double w1 = w(m_modeI), w2 = w(m_modeJ);
        if (!(w1 > 0.0) || !(w2 > 0.0))
            throw std::invalid_argument("modal damping needs positive frequencies (is a DOF "
                                        "without stiffness?)");
        m_rayleigh = RayleighDamping::fromRatio(m_modalZeta, w1, w2);
    }
    m_c = m_rayleigh.a0 * m_m + m_rayleigh.a1 * m_k0;
    m_c.prune(0.0);
    m_cDiagonal = true;
    for (int j = 0; j < m_c.outerSize() && m_cDiagonal; ++j)
        for (SparseMatrix::InnerIterator it(m_c, j); it; ++it)
            if (it.row() != j) {
                m_cDiagonal = false;
                break;
            }
}

void Structure::buildOrder()
{
    // Experimental elements first (their targets go out before any numerical work; their
    // commits first), then the numerical ones, each in model order.
    m_order.clear();
    for (int pass = 0; pass < 2; ++pass)
        for (auto& e : m_elements)
            if (e->isExperimental() == (pass == 0))
                m_order.push_back(e.get());
}

Structure::SparseMatrix Structure::assembleInitialStiffness() const
{
    // K0 = T^T K_full T, assembled directly over the free DOFs (duplicates are summed).
    std::vector<Eigen::Triplet<double>> triplets;
    for (const auto& e : m_elements)
        e->addInitialStiffness(triplets, m_freeOf);
    const Eigen::Index nFree = m_mDiag.size();
    SparseMatrix k(nFree, nFree);
    k.setFromTriplets(triplets.begin(), triplets.end());
    k.prune(0.0); // terms that cancel (a truss between merged DOFs) leave no entry
    return k;
}

double Structure::updatedMaxFrequency() const
{
    const SparseMatrix k = assembleInitialStiffness();
    if (m_mDiag.size() <= kDenseModalLimit)
        return denseFrequencies(k, m_mDiag).maxCoeff();
    return largestFrequency(k, m_mDiag);
}

Eigen::VectorXd Structure::toFull(const Eigen::VectorXd& uFree) const
{
    Eigen::VectorXd u;
    toFull(uFree, u);
    return u;
}

void Structure::toFull(const Eigen::VectorXd& uFree, Eigen::VectorXd& out) const
{
    out.resize(Eigen::Index(m_freeOf.size()));
    for (std::size_t i = 0; i < m_freeOf.size(); ++i)
        out[Eigen::Index(i)] = uFree[m_freeOf[i]];
}

ElementStatus Structure::setTrial(const Eigen::VectorXd& uFree)
{
    if (m_order.size() != m_elements.size())
        buildOrder();
    toFull(uFree, m_trialFull);
    const Eigen::VectorXd& u = m_trialFull;
    // Send every specimen's target before any measurement is awaited (sites answer in
    // parallel: the step costs the slowest round trip, not the sum). Experimental elements
    // come first in m_order. A send that fails stops further sends; every target already
    // sent is still awaited, so no link is left with a reply in flight.
    std::size_t sent = 0;
    ElementStatus first = ElementStatus::success();
    for (; sent < m_order.size() && m_order[sent]->isExperimental(); ++sent) {
        if (ElementStatus s = m_order[sent]->sendTrial(u); !s.ok) {
            first = s;
            break;
        }
    }
    for (std::size_t i = 0; i < sent; ++i) {
        ElementStatus s = m_order[i]->setTrial(u);
        if (!s.ok && first.ok)
            first = s;
    }
    if (!first.ok)
        return first;
    for (std::size_t i = sent; i < m_order.size(); ++i) {
        ElementStatus s = m_order[i]->setTrial(u);
        if (!s.ok)
            return s;
    }
    return ElementStatus::success();
}

Eigen::VectorXd Structure::restoringForce() const
{
    Eigen::VectorXd r;
    restoringForce(r);
    return r;
}

void Structure::restoringForce(Eigen::VectorXd& r) const
{
    m_rFull.setZero(fullDofCount());
    for (const auto& e : m_elements)
        e->addNodalForces(m_rFull);
    r.setZero(freeDofCount());
    for (std::size_t i = 0; i < m_freeOf.size(); ++i) // T^T r_full
        r[m_freeOf[i]] += m_rFull[Eigen::Index(i)];
}

ElementStatus Structure::commit()
{
    // Specimens first: a failed specimen commit leaves every numerical element uncommitted,
    // so the step can be retried. Every specimen's commit is sent before any acknowledgement
    // is awaited (a failed send is settled by that element's commit(), e.g. a reconnect).
    if (m_order.size() != m_elements.size())
        buildOrder();
    for (Element* e : m_order) {
        if (!e->isExperimental())
            break;
        e->beginCommit(); // a failure here is reported (and recovered) by commit() below
    }
    // Every specimen's commit is completed even after one failed (no acknowledgement left
    // in flight on a link); numerical elements only when all specimens committed.
    ElementStatus first = ElementStatus::success();
    for (Element* e : m_order) {
        if (!e->isExperimental() && !first.ok)
            break;
        ElementStatus s = e->commit();
        if (!s.ok && !e->isExperimental())
            return s;
        if (!s.ok && first.ok)
            first = s;
    }
    return first;
}

void Structure::revert()
{
    for (auto& e : m_elements)
        e->revert();
}

} // namespace hsmu
