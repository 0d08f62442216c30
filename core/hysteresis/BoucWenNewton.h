#pragma once
// Internal to core/hysteresis (not included outside it): the pieces of one backward-Euler step
// of the Bouc-Wen law (BoucWen.h, Eqs 2-6) shared by the one-problem integration (BoucWen.cpp)
// and the batched one of the UKF's sigma points (BoucWenBatch.cpp, which must reproduce it
// bit for bit): the step limits and the Newton iteration, one iteration per call.

#include "core/hysteresis/BoucWen.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsmu::boucwen {

inline constexpr double kRelativeTolerance = 1e-12;
inline constexpr int kMaxNewtonIterations = 30;
// Increments longer than this many yield deformations are split before Newton is tried:
// Newton converges for longer ones too, but backward Euler over a whole yield transition is
// a poor approximation of Eq. 2.
inline constexpr double kMaxStepInYieldDeformations = 0.5;
// An iterate beyond this multiple of max(|z_committed|, z_ultimate) is a divergence: the
// exact and the backward-Euler solutions never leave that range.
inline constexpr double kWildJumpFactor = 10.0;

// BoucWen::admissible(), inline for the batch (called for every sigma point of every UKF step).
// Branch-free: v - v is 0 for a finite v and NaN otherwise, so the sum is 0 exactly when every
// field is finite, and the conditions are combined without short-circuit.
inline bool admissibleParameters(const BoucWenParameters& p) {
    const double notFinite = (p.k0 - p.k0) + (p.alpha - p.alpha) + (p.n - p.n) + (p.beta - p.beta) +
                             (p.gamma - p.gamma) + (p.A0 - p.A0) + (p.deltaA - p.deltaA) +
                             (p.deltaNu - p.deltaNu) + (p.deltaEta - p.deltaEta) +
                             (p.uRef - p.uRef) + (p.fRef - p.fRef);
    return (notFinite == 0.0) & (p.k0 > 0.0) & (p.alpha >= 0.0) & (p.alpha <= 1.0) & (p.n > 0.0) &
           (p.A0 > 0.0) & (p.beta + p.gamma > 0.0) & (p.deltaA >= 0.0) & (p.deltaNu >= 0.0) &
           (p.deltaEta >= 0.0) & (p.uRef > 0.0) & (p.fRef > 0.0);
}

// |z|^n for n > 0 (admissible parameters): the value std::pow gives, without calling it where
// an exact form exists. z = 0 (a storey at rest: 91 % of the calls in a 1,000-step run of
// shear-building-10000, issue 27) gives +0 as std::pow does; n = 1 gives |z|; n = 2 gives the
// correctly rounded |z| |z| (std::pow is within 0.52 ulp of it, so at most its last bit
// differs). Every |z|^n of the law's step goes through here, so the batch (BatchMath::Exact)
// and the one-problem integration stay bit-identical.
inline double absPow(double absZ, double n) {
    if (absZ == 0.0) {
        return 0.0;
    }
    if (n == 2.0) {
        return absZ * absZ;
    }
    if (n == 1.0) {
        return absZ;
    }
    return std::pow(absZ, n);
}

inline double signOf(double v) {
    return static_cast<double>((v > 0.0) - (v < 0.0));
}

struct Degradation {
    double a, nu, eta; // A, nu, eta of Eqs 4-6
};

inline Degradation degradationAt(const BoucWenParameters& p, double e) {
    return {p.A0 - p.deltaA * e, 1.0 + p.deltaNu * e, 1.0 + p.deltaEta * e};
}

// Continuous dz/dx of Eq. 2 at (z, e) when x moves in direction dir.
inline double slopeAt(const BoucWenParameters& p, const BoucWenState& s, double dir) {
    const Degradation d = degradationAt(p, s.e);
    const double psi = p.gamma + p.beta * signOf(dir * s.z);
    return (d.a - absPow(std::abs(s.z), p.n) * psi * d.nu) / d.eta;
}

// True only if x <= scale q^(1/n), q = num / den, decided without std::pow (most of the cost of
// a step): q^r >= q / (q + r (1 - q)) for 0 < q <= 1, 0 < r <= 1 (Bernoulli's inequality) and
// q^r >= 1 for q >= 1, so x (n num + max(den - num, 0)) <= scale n num suffices. Its margin of
// 1e-9 is far above the roundings of both sides and of std::pow (the guards keep q and the
// terms in range). False (undecided) for n outside [1, 100].
inline bool surelyBelowScaledRoot(double x, double scale, double num, double den, double n) {
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

// Largest dx Phi'(z0) / eta of an unloading step tried without halving (see below).
inline constexpr double kMaxUnloadingStiffness = 0.5;

// Is an unloading increment short enough for the step's equation to have one root near z0?
// The backward-Euler residual r(z) has dr/dz = 1 - dx Phi'(z) / eta (plus terms in dx^2 from
// e's dependence on z). On loading (dx z0 > 0) and on unloading with gamma <= beta it is >= 1.
// On unloading with gamma > beta, -dx Phi'(z0) / eta = |dx| n |z0|^(n-1) (gamma - beta) nu / eta,
// which at a reversal near the ultimate z is about n (gamma - beta) / (gamma + beta) / 2 for the
// kMaxStepInYieldDeformations step: above 1 for n > 2, and Newton from z0 then goes the wrong
// way to a second root beyond -zu (z moving against dx), from which the law runs away an
// increment later (TestBoucWen::reversalNearTheUltimateZWithLargeN). So such a step is tried
// only while |dx| n |z0|^(n-1) (gamma - beta) nu(e0) / eta(e0) <= kMaxUnloadingStiffness
// (the pinching law's BoucWenPinching.cpp keeps the same limit). The std::pow is taken only for
// unloading with gamma > beta, and not when n >= 1 and |z0| <= 1 already decide it (then
// |z0|^(n-1) <= 1; the margin of 1e-9 is far above the roundings): the decision is always the
// one the exact value gives. True when the limit is undefined (nu or eta not positive).
inline bool withinUnloadingStep(const BoucWenParameters& p, const BoucWenState& from, double dx) {
    const double psi = p.gamma - p.beta; // gamma + beta sgn(dx z0) on unloading
    if (!(dx * from.z < 0.0) || !(psi > 0.0)) {
        return true;
    }
    const Degradation d = degradationAt(p, from.e);
    if (!(d.nu > 0.0 && d.eta > 0.0)) {
        return true;
    }
    const double absZ = std::abs(from.z);
    const double limit = kMaxUnloadingStiffness * d.eta;
    if (p.n >= 1.0 && absZ <= 1.0 && std::abs(dx) * (p.n * psi * d.nu) * (1.0 + 1e-9) <= limit) {
        return true;
    }
    const double absZn = absPow(absZ, p.n);
    return std::abs(dx) * (p.n * absZn / absZ * psi * d.nu) <= limit;
}

// One backward-Euler step of Eqs 2-6 from (z0, e0) solved by Newton from z0, with the residual
//   r(z) = z - z0 - dx Phi(z, e(z)) / eta(e(z)),  e(z) = e0 + (1 - alpha) k0 z dx,
// one iteration per iterate(). BoucWenBatch.cpp repeats iterate()'s arithmetic, four problems at a
// time.
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
        const double absZn = absPow(absZ, p.n);
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

} // namespace hsmu::boucwen
