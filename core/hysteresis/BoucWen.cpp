#include "core/hysteresis/BoucWen.h"

#include "core/hysteresis/BoucWenNewton.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

namespace hsmu {

namespace {

using namespace boucwen;

using Field = double BoucWenParameters::*;
constexpr std::array<std::pair<const char*, Field>, 11> kFields{{
    {"k0", &BoucWenParameters::k0},
    {"alpha", &BoucWenParameters::alpha},
    {"n", &BoucWenParameters::n},
    {"beta", &BoucWenParameters::beta},
    {"gamma", &BoucWenParameters::gamma},
    {"A0", &BoucWenParameters::A0},
    {"deltaA", &BoucWenParameters::deltaA},
    {"deltaNu", &BoucWenParameters::deltaNu},
    {"deltaEta", &BoucWenParameters::deltaEta},
    {"uRef", &BoucWenParameters::uRef},
    {"fRef", &BoucWenParameters::fRef},
}};

// The backward-Euler residual of BackwardEuler (BoucWenNewton.h) at z, for the safeguarded
// solve below.
double residualAt(const BoucWenParameters& p, const BoucWenState& from, double dx, double z) {
    const double e = from.e + (1.0 - p.alpha) * p.k0 * z * dx;
    const Degradation d = degradationAt(p, e);
    const double psi = p.gamma + p.beta * signOf(dx * z);
    const double phi = d.a - absPow(std::abs(z), p.n) * psi * d.nu;
    return z - from.z - dx * phi / d.eta;
}

// The safeguarded solve of one backward-Euler step, for an increment on which Newton failed
// even after every halving (a cusp of |z|^n with n < 1 at z = 0, where Newton cycles, or a
// wild iterate): the root nearest z0 in the direction r(z0) points to is bracketed by steps
// |r(z0)|, 2 |r(z0)|, 4 |r(z0)|, ... from z0 (inside the iterates' bound), then bisected to the
// Newton tolerance. False when no bracket is found or a residual is not finite. Only ever
// reached where the law failed before (issue 29), so every step that succeeded is unchanged.
bool bracketedStep(const BoucWenParameters& p, BoucWenState& state, double dx,
                   StepLimits& limits) {
    const double z0 = state.z;
    const double r0 = residualAt(p, state, dx, z0);
    if (!std::isfinite(r0))
        return false;
    const double c = (1.0 - p.alpha) * p.k0;
    const auto finish = [&](double z) {
        const BoucWenState next{z, state.e + c * z * dx};
        if (!std::isfinite(next.z) || !std::isfinite(next.e))
            return false;
        state = next;
        return true;
    };
    if (r0 == 0.0)
        return finish(z0);
    const bool positive = r0 > 0.0;
    const double dir = positive ? -1.0 : 1.0;
    double lo = z0, hi = z0;
    double step = std::max(std::abs(r0), std::numeric_limits<double>::min());
    for (int k = 0;; ++k) {
        hi = z0 + dir * step;
        const double r = residualAt(p, state, dx, hi);
        if (k > 1100 || !std::isfinite(r) || !limits.withinZBound(std::abs(hi)))
            return false;
        if (r == 0.0)
            return finish(hi);
        if ((r > 0.0) != positive)
            break;
        lo = hi; // r(lo) keeps r0's sign, r(hi) the other
        step *= 2.0;
    }
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        if (mid == lo || mid == hi ||
            std::abs(hi - lo) <= kRelativeTolerance * std::max(std::abs(lo), std::abs(hi)))
            break;
        const double r = residualAt(p, state, dx, mid);
        if (!std::isfinite(r))
            return false;
        if (r == 0.0)
            return finish(mid);
        ((r > 0.0) == positive ? lo : hi) = mid;
    }
    return finish(0.5 * (lo + hi));
}

// Integrates dx from state (updated in place). Increments longer than the maximum step, or
// unloading ones too stiff for a single root (withinUnloadingStep(), judged from the sub-step's
// own start), and those where Newton fails, are halved while levelsLeft > 0; the halves run
// sequentially. At the last level a failed Newton solve is retried by bracketedStep().
bool integrateSplit(const BoucWenParameters& p, BoucWenState& state, double dx, int levelsLeft,
                    StepLimits& limits, int& subSteps) {
    if (levelsLeft <= 0 ||
        (limits.withinMaxStep(std::abs(dx)) && withinUnloadingStep(p, state, dx))) {
        BackwardEuler newton(p, state, dx);
        auto progress = BackwardEuler::Progress::Iterating;
        while (progress == BackwardEuler::Progress::Iterating) {
            progress = newton.iterate(limits);
        }
        if (progress == BackwardEuler::Progress::Converged) {
            state = newton.state();
            ++subSteps;
            return true;
        }
        if (levelsLeft <= 0) {
            if (bracketedStep(p, state, dx, limits)) {
                ++subSteps;
                return true;
            }
            return false;
        }
    }
    const double half = 0.5 * dx;
    return integrateSplit(p, state, half, levelsLeft - 1, limits, subSteps) &&
           integrateSplit(p, state, half, levelsLeft - 1, limits, subSteps);
}

// The unloading branch's bound (issue 29): on an unloading increment (dx z0 < 0) with
// gamma > beta, Eq. 2 moves z towards 0 only while |z|^n (gamma - beta) nu(e) < A(e), i.e.
// |z| < z1(e) = (A(e) / (nu(e) (gamma - beta)))^(1/n). From beyond z1(e0) the continuous law
// runs away as the deformation reverses (|z| grows, e falls, up to a blow-up in finite
// deformation); where that leaves the iterates' bound no step exists, for Newton or the
// bracketed solve. Such a state is never reached by the law's own trajectory with beta > 0
// (loading stops at the ultimate z(e) < z1(e)); it is reached when the parameters change
// under a state (a UKF sigma point with a larger deltaNu or gamma - beta than the state was
// integrated with) or with beta < 0 (where the ultimate z exceeds z1). z1 itself is an
// equilibrium of the unloading branch (dz/dx = 0 there, z would stay), so the state is
// returned to zr(e0) = (A(e0) / (2 nu(e0) (gamma - beta)))^(1/n) = 2^(-1/n) z1(e0), where the
// unloading rate dz/dx is half the elastic one A / eta; e0 is kept (the return is not a
// motion of x and dissipates nothing). False when the state is not beyond z1 or zr is
// undefined (A(e0) or nu(e0) not positive).
bool returnedToUnloadingBound(const BoucWenParameters& p, const BoucWenState& from, double dx,
                              BoucWenState& returned) {
    const double psi = p.gamma - p.beta; // gamma + beta sgn(dx z0) on unloading
    if (!(dx * from.z < 0.0) || !(psi > 0.0))
        return false;
    const Degradation d = degradationAt(p, from.e);
    if (!(d.a > 0.0) || !(d.nu > 0.0))
        return false;
    const double z1 = std::pow(d.a / (d.nu * psi), 1.0 / p.n);
    const double zr = std::pow(0.5 * d.a / (d.nu * psi), 1.0 / p.n);
    if (!std::isfinite(zr) || !(std::abs(from.z) > z1))
        return false;
    returned = {std::copysign(zr, from.z), from.e};
    return true;
}

// integrateState() for parameters known to be admissible.
BoucWenIncrement integrateAdmissible(const BoucWenParameters& p, const BoucWenState& from,
                                     double dx, int maxSubdivisions) {
    if (!std::isfinite(dx) || !std::isfinite(from.z) || !std::isfinite(from.e)) {
        return {LawStatus::InvalidInput, from, 0.0, 0};
    }
    if (dx == 0.0) {
        // At rest (most storeys of a tall building early in a run): Newton's first iterate
        // has r = 0 and converges on z0 whenever Phi / eta is finite, so its result is taken
        // without the iteration.
        const Degradation d = degradationAt(p, from.e);
        const double psi = p.gamma + p.beta * signOf(dx * from.z);
        if (std::isfinite((d.a - absPow(std::abs(from.z), p.n) * psi * d.nu) / d.eta)) {
            const double c = (1.0 - p.alpha) * p.k0;
            return {LawStatus::Ok, {from.z, from.e + c * from.z * dx}, 0.0, 1};
        }
    }
    StepLimits limits(p, from);
    BoucWenState end = from;
    int subSteps = 0;
    if (integrateSplit(p, end, dx, std::max(maxSubdivisions, 0), limits, subSteps)) {
        return {LawStatus::Ok, end, 0.0, subSteps};
    }
    // Only where the plain integration failed (so every step that succeeded is unchanged):
    // an unloading from beyond the unloading branch's bound starts from that bound.
    BoucWenState returned;
    if (returnedToUnloadingBound(p, from, dx, returned)) {
        StepLimits returnedLimits(p, returned);
        end = returned;
        subSteps = 0;
        if (integrateSplit(p, end, dx, std::max(maxSubdivisions, 0), returnedLimits, subSteps)) {
            return {LawStatus::Ok, end, 0.0, subSteps};
        }
    }
    return {LawStatus::NoConvergence, from, 0.0, 0};
}

} // namespace

BoucWen::BoucWen(const BoucWenParameters& p) : m_p(p) {
    if (!admissible(p)) {
        throw std::invalid_argument("BoucWen: parameters are not admissible");
    }
    revertToStart();
}

bool BoucWen::projectBetaGamma(double& beta, double& gamma) {
    const double deficit = kBetaGammaMargin - (beta + gamma);
    if (!(deficit > 0.0))
        return false;
    beta += 0.5 * deficit;
    gamma += 0.5 * deficit;
    return true;
}

BoucWenIncrement BoucWen::integrate(const BoucWenParameters& p, const BoucWenState& from, double dx,
                                    int maxSubdivisions) {
    BoucWenIncrement result = integrateState(p, from, dx, maxSubdivisions);
    if (result.status == LawStatus::Ok) {
        result.dzdx = slopeAt(p, result.state, dx < 0.0 ? -1.0 : 1.0);
    }
    return result;
}

BoucWenIncrement BoucWen::integrateState(const BoucWenParameters& p, const BoucWenState& from,
                                         double dx, int maxSubdivisions) {
    if (!admissible(p)) {
        return {LawStatus::InvalidInput, from, 0.0, 0};
    }
    return integrateAdmissible(p, from, dx, maxSubdivisions);
}

double BoucWen::ultimateZ(const BoucWenParameters& p) {
    return std::pow(p.A0 / (p.beta + p.gamma), 1.0 / p.n);
}

bool BoucWen::admissible(const BoucWenParameters& p) {
    return admissibleParameters(p);
}

bool BoucWen::setParameters(const BoucWenParameters& p) {
    if (!admissible(p)) {
        return false;
    }
    m_p = p;
    m_fCommitted = forceOf(m_uCommitted / m_p.uRef, m_committed);
    revert();
    return true;
}

void BoucWen::setCommittedState(const BoucWenState& s, double committedDeformation) {
    m_committed = s;
    m_uCommitted = committedDeformation;
    m_fCommitted = forceOf(m_uCommitted / m_p.uRef, m_committed);
    revert();
}

LawStatus BoucWen::setTrialDeformation(double u) {
    if (!std::isfinite(u)) {
        revert();
        return LawStatus::InvalidInput;
    }
    const double dx = (u - m_uCommitted) / m_p.uRef;
    // m_p is admissible (the constructor and setParameters check it).
    const BoucWenIncrement inc = integrateAdmissible(m_p, m_committed, dx, kDefaultMaxSubdivisions);
    if (inc.status != LawStatus::Ok) {
        revert();
        return inc.status;
    }
    m_trial = inc.state;
    m_uTrial = u;
    m_dirTrial = dx > 0.0 ? 1.0 : (dx < 0.0 ? -1.0 : m_dirCommitted);
    m_fTrial = forceOf(u / m_p.uRef, m_trial);
    return LawStatus::Ok;
}

double BoucWen::algorithmicTangent() const {
    const BoucWenParameters& p = m_p;
    const double scale = p.fRef / p.uRef;
    const double z = m_trial.z;
    if (z == 0.0)
        return scale * p.k0;
    const double dx = (m_uTrial - m_uCommitted) / p.uRef;
    const double c = (1.0 - p.alpha) * p.k0; // de = c z dx
    const double e = m_trial.e;
    const double a = p.A0 - p.deltaA * e, nu = 1.0 + p.deltaNu * e, eta = 1.0 + p.deltaEta * e;
    const double psi = p.gamma + p.beta * (dx * z > 0.0 ? 1.0 : -1.0);
    const double zn = absPow(std::abs(z), p.n);
    const double zn1 = p.n * absPow(std::abs(z), p.n - 1.0) * (z > 0.0 ? 1.0 : -1.0);
    const double phi = a - zn * psi * nu;
    // dPhi/de and deta/de (A, nu, eta are linear in e)
    const double phiE = -p.deltaA - zn * psi * p.deltaNu;
    const double etaE = p.deltaEta;
    const double q = phiE / eta - phi * etaE / (eta * eta); // d(Phi / eta)/de
    // r = z - z0 - dx Phi(z, e) / eta(e), e = e0 + c dx z
    const double drdz = 1.0 - dx * (-zn1 * psi * nu / eta + q * c * dx);
    const double drdx = -phi / eta - dx * q * c * z;
    const double dzdx = -drdx / drdz;
    return scale * p.k0 * (p.alpha + (1.0 - p.alpha) * dzdx);
}

double BoucWen::initialTangent() const {
    return m_p.k0 * (m_p.alpha + (1.0 - m_p.alpha) * m_p.A0) * m_p.fRef / m_p.uRef;
}

void BoucWen::commit() {
    m_committed = m_trial;
    m_uCommitted = m_uTrial;
    m_fCommitted = m_fTrial;
    m_dirCommitted = m_dirTrial;
}

void BoucWen::revert() {
    m_trial = m_committed;
    m_uTrial = m_uCommitted;
    m_fTrial = m_fCommitted;
    m_dirTrial = m_dirCommitted;
}

void BoucWen::revertToStart() {
    m_committed = BoucWenState{};
    m_uCommitted = 0.0;
    m_fCommitted = 0.0;
    m_dirCommitted = 1.0;
    revert();
}

std::unique_ptr<HysteresisLaw> BoucWen::clone() const {
    return std::make_unique<BoucWen>(*this);
}

std::vector<std::string> BoucWen::parameterNames() const {
    std::vector<std::string> names;
    names.reserve(kFields.size());
    for (const auto& [name, field] : kFields) {
        names.emplace_back(name);
    }
    return names;
}

double BoucWen::parameterValue(int index) const {
    if (index < 0 || static_cast<std::size_t>(index) >= kFields.size()) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return m_p.*(kFields[static_cast<std::size_t>(index)].second);
}

int BoucWen::setParameterValues(std::span<const int> indices, std::span<const double> values,
                                bool allOrNothing) {
    BoucWenParameters p = m_p;
    if (allOrNothing) { // judged together: a vector may cross an inadmissible intermediate
        for (std::size_t k = 0; k < indices.size(); ++k) {
            const int i = indices[k];
            if (i < 0 || static_cast<std::size_t>(i) >= kFields.size()) {
                setParameters(m_p); // as a refused set: force re-evaluated, trial dropped
                return static_cast<int>(k);
            }
            p.*(kFields[static_cast<std::size_t>(i)].second) = values[k];
        }
        if (!admissible(p)) {
            // Refused: name the first value that is inadmissible on its own, else the first.
            int refused = 0;
            for (std::size_t k = 0; k < indices.size(); ++k) {
                BoucWenParameters alone = m_p;
                alone.*(kFields[static_cast<std::size_t>(indices[k])].second) = values[k];
                if (!admissible(alone)) {
                    refused = static_cast<int>(k);
                    break;
                }
            }
            setParameters(m_p); // as a refused set: force re-evaluated, trial dropped
            return refused;
        }
        setParameters(p);
        return -1;
    }
    bool changed = false;
    int firstRefused = -1;
    for (std::size_t k = 0; k < indices.size(); ++k) {
        const int i = indices[k];
        if (i >= 0 && static_cast<std::size_t>(i) < kFields.size()) {
            const Field field = kFields[static_cast<std::size_t>(i)].second;
            const double previous = p.*field;
            p.*field = values[k];
            if (admissible(p)) {
                changed = true;
                continue;
            }
            p.*field = previous;
        }
        if (firstRefused < 0) {
            firstRefused = static_cast<int>(k);
        }
        if (allOrNothing) {
            setParameters(m_p);
            return firstRefused;
        }
    }
    if (changed) {
        setParameters(p);
    }
    return firstRefused;
}

double BoucWen::forceOf(double x, const BoucWenState& s) const {
    return m_p.fRef * m_p.k0 * (m_p.alpha * x + (1.0 - m_p.alpha) * s.z);
}

double BoucWen::tangentOf(const BoucWenState& s, double dir) const {
    const double dzdx = slopeAt(m_p, s, dir);
    return m_p.k0 * (m_p.alpha + (1.0 - m_p.alpha) * dzdx) * m_p.fRef / m_p.uRef;
}

BoucWenParameters rescaled(const BoucWenParameters& p, double uRef, double fRef) {
    const double s = p.uRef / uRef, c = p.fRef / fRef;
    BoucWenParameters q = p;
    q.k0 = p.k0 * c / s;
    const double sn = std::pow(s, -p.n);
    q.beta = p.beta * sn;
    q.gamma = p.gamma * sn;
    q.deltaA = p.deltaA / (c * s);
    q.deltaNu = p.deltaNu / (c * s);
    q.deltaEta = p.deltaEta / (c * s);
    q.uRef = uRef;
    q.fRef = fRef;
    return q;
}

BoucWenState rescaledState(const BoucWenState& st, const BoucWenParameters& from,
                           const BoucWenParameters& to) {
    const double s = from.uRef / to.uRef, c = from.fRef / to.fRef;
    BoucWenState out = st;
    out.z = st.z * s;
    out.e = st.e * c * s;
    return out;
}

} // namespace hsmu
