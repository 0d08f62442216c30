#include "core/hysteresis/BoucWen.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace hsmu {

namespace {

constexpr double kRelativeTolerance = 1e-12;
constexpr int kMaxNewtonIterations = 30;
// Increments longer than this many yield deformations are split before Newton is tried:
// Newton converges for longer ones too, but backward Euler over a whole yield transition is
// a poor approximation of Eq. 2.
constexpr double kMaxStepInYieldDeformations = 0.5;
// An iterate beyond this multiple of max(|z_committed|, z_ultimate) is a divergence: the
// exact and the backward-Euler solutions never leave that range.
constexpr double kWildJumpFactor = 10.0;

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

Field findField(const std::string& name) {
    for (const auto& [fieldName, field] : kFields) {
        if (name == fieldName) {
            return field;
        }
    }
    return nullptr;
}

double signOf(double v) {
    return static_cast<double>((v > 0.0) - (v < 0.0));
}

// Continuous dz/dx of Eq. 2 at (z, e) when x moves in direction dir.
double slopeAt(const BoucWenParameters& p, const BoucWenState& s, double dir) {
    const double a = p.A0 - p.deltaA * s.e;
    const double nu = 1.0 + p.deltaNu * s.e;
    const double eta = 1.0 + p.deltaEta * s.e;
    const double psi = p.gamma + p.beta * signOf(dir * s.z);
    return (a - std::pow(std::abs(s.z), p.n) * psi * nu) / eta;
}

// Deformation (normalized) at which the elastic branch of the law at energy e reaches the
// ultimate z; the scale that decides whether an increment is "large".
double yieldDeformation(const BoucWenParameters& p, double e) {
    const double a = p.A0 - p.deltaA * e;
    const double nu = 1.0 + p.deltaNu * e;
    const double eta = 1.0 + p.deltaEta * e;
    if (a > 0.0 && nu > 0.0 && eta > 0.0) {
        const double zu = std::pow(a / (nu * (p.beta + p.gamma)), 1.0 / p.n);
        if (std::isfinite(zu) && zu > 0.0) {
            return zu * eta / a;
        }
    }
    return BoucWen::ultimateZ(p) / p.A0;
}

// One backward-Euler step of Eqs 2-6 solved by Newton from the committed z.
// Residual r(z) = z - z0 - dx Phi(z, e(z)) / eta(e(z)),  e(z) = e0 + (1 - alpha) k0 z dx.
bool backwardEulerStep(const BoucWenParameters& p, BoucWenState& state, double dx, double zBound) {
    const double c = (1.0 - p.alpha) * p.k0;
    const double dedz = c * dx;
    const double z0 = state.z;
    const double e0 = state.e;
    double z = z0;
    for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
        const double e = e0 + c * z * dx;
        const double a = p.A0 - p.deltaA * e;
        const double nu = 1.0 + p.deltaNu * e;
        const double eta = 1.0 + p.deltaEta * e;
        const double absZ = std::abs(z);
        const double psi = p.gamma + p.beta * signOf(dx * z);
        const double absZn = std::pow(absZ, p.n);
        const double phi = a - absZn * psi * nu;
        const double r = z - z0 - dx * phi / eta;

        // d|z|^n/dz = n |z|^(n-1) sgn z; taken as 0 at z = 0 (kink or cusp for n <= 1).
        const double dAbsZn = absZ > 0.0 ? p.n * absZn / absZ * signOf(z) : 0.0;
        const double dPhi = -p.deltaA * dedz - dAbsZn * psi * nu - absZn * psi * p.deltaNu * dedz;
        const double dEta = p.deltaEta * dedz;
        const double dr = 1.0 - dx * (dPhi * eta - phi * dEta) / (eta * eta);
        const double delta = r / dr;
        z -= delta;
        if (!std::isfinite(z) || std::abs(z) > zBound) {
            return false;
        }
        if (std::abs(delta) <= kRelativeTolerance * std::max(std::abs(z), std::abs(z0))) {
            state.z = z;
            state.e = e0 + c * z * dx;
            return std::isfinite(state.e);
        }
    }
    return false;
}

// Integrates dx from state (updated in place). Increments longer than maxStep, and those where
// Newton fails, are halved while levelsLeft > 0; the halves run sequentially.
bool integrateSplit(const BoucWenParameters& p, BoucWenState& state, double dx, int levelsLeft,
                    double maxStep, double zBound, int& subSteps) {
    if (std::abs(dx) <= maxStep || levelsLeft <= 0) {
        BoucWenState trial = state;
        if (backwardEulerStep(p, trial, dx, zBound)) {
            state = trial;
            ++subSteps;
            return true;
        }
        if (levelsLeft <= 0) {
            return false;
        }
    }
    const double half = 0.5 * dx;
    return integrateSplit(p, state, half, levelsLeft - 1, maxStep, zBound, subSteps) &&
           integrateSplit(p, state, half, levelsLeft - 1, maxStep, zBound, subSteps);
}

} // namespace

BoucWen::BoucWen(const BoucWenParameters& p) : m_p(p) {
    if (!admissible(p)) {
        throw std::invalid_argument("BoucWen: parameters are not admissible");
    }
    revertToStart();
}

BoucWenIncrement BoucWen::integrate(const BoucWenParameters& p, const BoucWenState& from, double dx,
                                    int maxSubdivisions) {
    BoucWenIncrement result;
    result.state = from;
    result.subSteps = 0;
    if (!std::isfinite(dx) || !std::isfinite(from.z) || !std::isfinite(from.e) || !admissible(p)) {
        result.status = LawStatus::InvalidInput;
        return result;
    }
    const double maxStep = kMaxStepInYieldDeformations * yieldDeformation(p, from.e);
    const double zBound = kWildJumpFactor * std::max(std::abs(from.z), ultimateZ(p));
    BoucWenState end = from;
    int subSteps = 0;
    if (!integrateSplit(p, end, dx, std::max(maxSubdivisions, 0), maxStep, zBound, subSteps)) {
        result.status = LawStatus::NoConvergence;
        return result;
    }
    result.state = end;
    result.subSteps = subSteps;
    result.dzdx = slopeAt(p, end, dx < 0.0 ? -1.0 : 1.0);
    return result;
}

double BoucWen::ultimateZ(const BoucWenParameters& p) {
    return std::pow(p.A0 / (p.beta + p.gamma), 1.0 / p.n);
}

bool BoucWen::admissible(const BoucWenParameters& p) {
    for (const auto& [name, field] : kFields) {
        if (!std::isfinite(p.*field)) {
            return false;
        }
    }
    return p.k0 > 0.0 && p.alpha >= 0.0 && p.alpha <= 1.0 && p.n > 0.0 && p.A0 > 0.0 &&
           p.beta + p.gamma > 0.0 && p.deltaA >= 0.0 && p.deltaNu >= 0.0 && p.deltaEta >= 0.0 &&
           p.uRef > 0.0 && p.fRef > 0.0;
}

bool BoucWen::setParameters(const BoucWenParameters& p) {
    if (!admissible(p)) {
        return false;
    }
    m_p = p;
    m_fCommitted = forceOf(m_uCommitted / m_p.uRef, m_committed);
    m_kCommitted = tangentOf(m_committed, m_dirCommitted);
    revert();
    return true;
}

void BoucWen::setCommittedState(const BoucWenState& s, double committedDeformation) {
    m_committed = s;
    m_uCommitted = committedDeformation;
    m_fCommitted = forceOf(m_uCommitted / m_p.uRef, m_committed);
    m_kCommitted = tangentOf(m_committed, m_dirCommitted);
    revert();
}

LawStatus BoucWen::setTrialDeformation(double u) {
    if (!std::isfinite(u)) {
        revert();
        return LawStatus::InvalidInput;
    }
    const double dx = (u - m_uCommitted) / m_p.uRef;
    const BoucWenIncrement inc = integrate(m_p, m_committed, dx);
    if (inc.status != LawStatus::Ok) {
        revert();
        return inc.status;
    }
    m_trial = inc.state;
    m_uTrial = u;
    m_dirTrial = dx > 0.0 ? 1.0 : (dx < 0.0 ? -1.0 : m_dirCommitted);
    m_fTrial = forceOf(u / m_p.uRef, m_trial);
    m_kTrial = tangentOf(m_trial, m_dirTrial);
    return LawStatus::Ok;
}

double BoucWen::initialTangent() const {
    return m_p.k0 * (m_p.alpha + (1.0 - m_p.alpha) * m_p.A0) * m_p.fRef / m_p.uRef;
}

void BoucWen::commit() {
    m_committed = m_trial;
    m_uCommitted = m_uTrial;
    m_fCommitted = m_fTrial;
    m_kCommitted = m_kTrial;
    m_dirCommitted = m_dirTrial;
}

void BoucWen::revert() {
    m_trial = m_committed;
    m_uTrial = m_uCommitted;
    m_fTrial = m_fCommitted;
    m_kTrial = m_kCommitted;
    m_dirTrial = m_dirCommitted;
}

void BoucWen::revertToStart() {
    m_committed = BoucWenState{};
    m_uCommitted = 0.0;
    m_fCommitted = 0.0;
    m_kCommitted = initialTangent();
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

std::optional<double> BoucWen::parameter(const std::string& name) const {
    const Field field = findField(name);
    if (field == nullptr) {
        return std::nullopt;
    }
    return m_p.*field;
}

bool BoucWen::setParameter(const std::string& name, double value) {
    const Field field = findField(name);
    if (field == nullptr) {
        return false;
    }
    BoucWenParameters p = m_p;
    p.*field = value;
    return setParameters(p);
}

double BoucWen::forceOf(double x, const BoucWenState& s) const {
    return m_p.fRef * m_p.k0 * (m_p.alpha * x + (1.0 - m_p.alpha) * s.z);
}

double BoucWen::tangentOf(const BoucWenState& s, double dir) const {
    const double dzdx = slopeAt(m_p, s, dir);
    return m_p.k0 * (m_p.alpha + (1.0 - m_p.alpha) * dzdx) * m_p.fRef / m_p.uRef;
}

} // namespace hsmu
