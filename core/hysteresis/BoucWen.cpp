#include "core/hysteresis/BoucWen.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
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

struct Degradation {
    double a, nu, eta; // A, nu, eta of Eqs 4-6
};

Degradation degradationAt(const BoucWenParameters& p, double e) {
    return {p.A0 - p.deltaA * e, 1.0 + p.deltaNu * e, 1.0 + p.deltaEta * e};
}

// Continuous dz/dx of Eq. 2 at (z, e) when x moves in direction dir.
double slopeAt(const BoucWenParameters& p, const BoucWenState& s, double dir) {
    const Degradation d = degradationAt(p, s.e);
    const double psi = p.gamma + p.beta * signOf(dir * s.z);
    return (d.a - std::pow(std::abs(s.z), p.n) * psi * d.nu) / d.eta;
}

// True only if x <= scale q^(1/n), q = num / den, decided without std::pow (most of the cost of
// a step): q^r >= q / (q + r (1 - q)) for 0 < q <= 1, 0 < r <= 1 (Bernoulli's inequality) and
// q^r >= 1 for q >= 1, so x (n num + max(den - num, 0)) <= scale n num suffices. Its margin of
// 1e-9 is far above the roundings of both sides and of std::pow (the guards keep q and the
// terms in range). False (undecided) for n outside [1, 100].
bool surelyBelowScaledRoot(double x, double scale, double num, double den, double n) {
    if (!(n >= 1.0 && n <= 100.0 && num > 0.0 && den > 0.0 && num <= den * 1e300 &&
          den <= num * 1e300)) {
        return false;
    }
    const double rhs = scale * n * num * (1.0 - 1e-9);
    return std::isfinite(rhs) && x * (n * num + std::max(den - num, 0.0)) <= rhs;
}

// The two limits of one integration from `from`: the longest increment tried without halving
// and the largest |z| of an iterate. Each costs a std::pow and is computed only when a cheap
// test (surelyBelowScaledRoot, |z| <= kWildJumpFactor |z0|) cannot decide, which for ordinary
// increments is never. Every decision is the one the exact value gives.
class StepLimits {
public:
    StepLimits(const BoucWenParameters& p, const BoucWenState& from)
        : m_p(p), m_e0(from.e), m_absZ0(std::abs(from.z)) {}

    // |dx| <= kMaxStepInYieldDeformations yield deformations zu(e0) eta / a, where the elastic
    // branch reaches zu(e) = (a / (nu (beta + gamma)))^(1/n) (ultimateZ / A0 if undefined)?
    bool withinMaxStep(double absDx) {
        if (std::isnan(m_maxStep)) {
            const Degradation d = degradationAt(m_p, m_e0);
            const bool defined = d.a > 0.0 && d.nu > 0.0 && d.eta > 0.0;
            const double den = d.nu * (m_p.beta + m_p.gamma);
            const double scale = kMaxStepInYieldDeformations * d.eta;
            if (defined && surelyBelowScaledRoot(absDx * d.a, scale, d.a, den, m_p.n)) {
                return true;
            }
            const double zu = defined ? std::pow(d.a / den, 1.0 / m_p.n) : 0.0;
            m_maxStep = kMaxStepInYieldDeformations * (std::isfinite(zu) && zu > 0.0
                                                           ? zu * d.eta / d.a
                                                           : BoucWen::ultimateZ(m_p) / m_p.A0);
        }
        return absDx <= m_maxStep;
    }

    // |z| <= kWildJumpFactor max(|z0|, ultimateZ(p))?
    bool withinZBound(double absZ) {
        if (std::isnan(m_zBound)) {
            if (absZ <= kWildJumpFactor * m_absZ0 ||
                surelyBelowScaledRoot(absZ, kWildJumpFactor, m_p.A0, m_p.beta + m_p.gamma, m_p.n)) {
                return true;
            }
            m_zBound = kWildJumpFactor * std::max(m_absZ0, BoucWen::ultimateZ(m_p));
        }
        return absZ <= m_zBound;
    }

private:
    static constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
    const BoucWenParameters& m_p;
    double m_e0, m_absZ0;
    double m_maxStep = kUnknown, m_zBound = kUnknown;
};

// One backward-Euler step of Eqs 2-6 from (z0, e0) solved by Newton from z0, with the residual
//   r(z) = z - z0 - dx Phi(z, e(z)) / eta(e(z)),  e(z) = e0 + (1 - alpha) k0 z dx,
// one iteration per iterate(), so that several can run interleaved (integrateStates()).
class BackwardEuler {
public:
    enum class Progress { Iterating, Converged, Failed };

    BackwardEuler(const BoucWenParameters& p, const BoucWenState& from, double dx)
        : m_p(&p), m_dx(dx), m_c((1.0 - p.alpha) * p.k0), m_z0(from.z), m_e0(from.e), m_z(from.z) {}

    Progress iterate(StepLimits& limits) {
        const BoucWenParameters& p = *m_p;
        const double dx = m_dx, z0 = m_z0, z = m_z;
        const double dedz = m_c * dx;
        const double e = m_e0 + m_c * z * dx;
        const Degradation d = degradationAt(p, e);
        const double absZ = std::abs(z);
        const double psi = p.gamma + p.beta * signOf(dx * z);
        const double absZn = std::pow(absZ, p.n);
        const double phi = d.a - absZn * psi * d.nu;
        const double r = z - z0 - dx * phi / d.eta;

        // d|z|^n/dz = n |z|^(n-1) sgn z; taken as 0 at z = 0 (kink or cusp for n <= 1).
        const double dAbsZn = absZ > 0.0 ? p.n * absZn / absZ * signOf(z) : 0.0;
        const double dPhi = -p.deltaA * dedz - dAbsZn * psi * d.nu - absZn * psi * p.deltaNu * dedz;
        const double dEta = p.deltaEta * dedz;
        const double dr = 1.0 - dx * (dPhi * d.eta - phi * dEta) / (d.eta * d.eta);
        const double delta = r / dr;
        m_z = z - delta;
        if (!std::isfinite(m_z) || !limits.withinZBound(std::abs(m_z))) {
            return Progress::Failed;
        }
        if (std::abs(delta) <= kRelativeTolerance * std::max(std::abs(m_z), std::abs(z0))) {
            return std::isfinite(state().e) ? Progress::Converged : Progress::Failed;
        }
        return ++m_iterations < kMaxNewtonIterations ? Progress::Iterating : Progress::Failed;
    }

    BoucWenState state() const { return {m_z, m_e0 + m_c * m_z * m_dx}; }

private:
    const BoucWenParameters* m_p;
    double m_dx, m_c, m_z0, m_e0, m_z;
    int m_iterations = 0;
};

// Integrates dx from state (updated in place). Increments longer than the maximum step, and
// those where Newton fails, are halved while levelsLeft > 0; the halves run sequentially.
bool integrateSplit(const BoucWenParameters& p, BoucWenState& state, double dx, int levelsLeft,
                    StepLimits& limits, int& subSteps) {
    if (levelsLeft <= 0 || limits.withinMaxStep(std::abs(dx))) {
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
            return false;
        }
    }
    const double half = 0.5 * dx;
    return integrateSplit(p, state, half, levelsLeft - 1, limits, subSteps) &&
           integrateSplit(p, state, half, levelsLeft - 1, limits, subSteps);
}

// integrateState() for parameters known to be admissible.
BoucWenIncrement integrateAdmissible(const BoucWenParameters& p, const BoucWenState& from,
                                     double dx, int maxSubdivisions) {
    if (!std::isfinite(dx) || !std::isfinite(from.z) || !std::isfinite(from.e)) {
        return {LawStatus::InvalidInput, from, 0.0, 0};
    }
    StepLimits limits(p, from);
    BoucWenState end = from;
    int subSteps = 0;
    if (!integrateSplit(p, end, dx, std::max(maxSubdivisions, 0), limits, subSteps)) {
        return {LawStatus::NoConvergence, from, 0.0, 0};
    }
    return {LawStatus::Ok, end, 0.0, subSteps};
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

void BoucWen::integrateStates(std::span<const BoucWenParameters> p,
                              std::span<const BoucWenState> from, double dx,
                              std::span<BoucWenIncrement> out) {
    // Chunks of up to kInterleaved problems whose Newton iterations run round-robin. A problem
    // that is not a single plain step (invalid, an increment to halve, a Newton failure) is
    // left to integrateState(), which repeats the same decisions and iterations.
    constexpr std::size_t kInterleaved = 8;
    const std::size_t count = std::min({p.size(), from.size(), out.size()});
    for (std::size_t first = 0; first < count; first += kInterleaved) {
        std::array<std::optional<StepLimits>, kInterleaved> limits;
        std::array<std::optional<BackwardEuler>, kInterleaved> newton;
        const std::size_t size = std::min(kInterleaved, count - first);
        std::size_t running = 0;
        for (std::size_t k = 0; k < size; ++k) {
            const std::size_t i = first + k;
            if (admissible(p[i]) && std::isfinite(dx) && std::isfinite(from[i].z) &&
                std::isfinite(from[i].e) &&
                limits[k].emplace(p[i], from[i]).withinMaxStep(std::abs(dx))) {
                newton[k].emplace(p[i], from[i], dx);
                ++running;
            } else {
                out[i] = integrateState(p[i], from[i], dx);
            }
        }
        while (running > 0) {
            for (std::size_t k = 0; k < size; ++k) {
                using Progress = BackwardEuler::Progress;
                const Progress progress =
                    newton[k] ? newton[k]->iterate(*limits[k]) : Progress::Iterating;
                if (progress == Progress::Iterating) {
                    continue;
                }
                const std::size_t i = first + k;
                out[i] = progress == Progress::Converged
                             ? BoucWenIncrement{LawStatus::Ok, newton[k]->state(), 0.0, 1}
                             : integrateState(p[i], from[i], dx);
                newton[k].reset();
                --running;
            }
        }
    }
}

double BoucWen::ultimateZ(const BoucWenParameters& p) {
    return std::pow(p.A0 / (p.beta + p.gamma), 1.0 / p.n);
}

bool BoucWen::admissible(const BoucWenParameters& p) {
    // All finite: v - v is 0 for a finite v and NaN otherwise, so the sum is 0 exactly when
    // every field is finite (branch-free; called for every sigma point of every UKF step).
    double notFinite = 0.0;
    for (const auto& field : kFields) {
        notFinite += p.*field.second - p.*field.second;
    }
    return notFinite == 0.0 && p.k0 > 0.0 && p.alpha >= 0.0 &&
           p.alpha <= 1.0 && p.n > 0.0 && p.A0 > 0.0 && p.beta + p.gamma > 0.0 && p.deltaA >= 0.0 &&
           p.deltaNu >= 0.0 && p.deltaEta >= 0.0 && p.uRef > 0.0 && p.fRef > 0.0;
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

int BoucWen::setParameterValues(std::span<const int> indices, std::span<const double> values,
                                bool allOrNothing) {
    BoucWenParameters p = m_p;
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
            // setParameter-by-name restoring the old values leaves the parameters as they
            // were, with the force re-evaluated and a pending trial dropped.
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

} // namespace hsmu
