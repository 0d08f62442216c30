#include "core/hysteresis/BoucWenPinching.h"

#include "core/hysteresis/BoucWenNewton.h"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <stdexcept>

namespace hsmu {

namespace {

using namespace boucwen;

constexpr std::array<const char*, 17> kNames{"k0",      "alpha",   "n",        "beta",   "gamma",
                                             "A0",      "deltaA",  "deltaNu",  "deltaEta", "uRef",
                                             "fRef",    "zetaS",   "p",        "q",      "psi",
                                             "deltaPsi", "lambda"};

// The field at position i of parameterNames(); nullptr for an index out of range.
double* fieldAt(BoucWenPinchingParameters& p, int i) {
    BoucWenParameters& b = p.boucWen;
    PinchingParameters& c = p.pinching;
    double* fields[] = {&b.k0,       &b.alpha,    &b.n,     &b.beta,  &b.gamma, &b.A0,
                        &b.deltaA,   &b.deltaNu,  &b.deltaEta, &b.uRef, &b.fRef, &c.zetaS,
                        &c.p,        &c.q,        &c.psi,   &c.deltaPsi, &c.lambda};
    return i >= 0 && i < static_cast<int>(kNames.size()) ? fields[i] : nullptr;
}

// zeta1, zeta2 and q zu of P2-P4 at energy e (negative e counts as 0).
struct Pinch {
    double zeta1 = 0.0, zeta2 = 1.0, qzu = 0.0;
};

// The last (A / (nu (beta + gamma)))^(1/n) of an integration (P4): without nu or A degrading
// (deltaNu = deltaA = 0, as the calibration's optima often are) every sub-step has the same
// ratio, and the std::pow is taken once per increment instead of once per sub-step.
struct RootCache {
    double ratio = std::numeric_limits<double>::quiet_NaN();
    double root = 0.0;
};

Pinch pinchAt(const BoucWenPinchingParameters& p, double e, RootCache* cache = nullptr) {
    const PinchingParameters& c = p.pinching;
    Pinch pinch;
    if (c.zetaS == 0.0 || c.p == 0.0 || !(e > 0.0)) {
        return pinch; // zeta1 = 0: no pinching
    }
    pinch.zeta1 = -c.zetaS * std::expm1(-c.p * e);
    pinch.zeta2 = (c.psi + c.deltaPsi * e) * (c.lambda + pinch.zeta1);
    const Degradation d = degradationAt(p.boucWen, e);
    const double ratio = d.a / (d.nu * (p.boucWen.beta + p.boucWen.gamma));
    if (!(ratio > 0.0)) {
        pinch.qzu = 0.0;
    } else if (cache && ratio == cache->ratio) {
        pinch.qzu = c.q * cache->root;
    } else {
        const double root = std::pow(ratio, 1.0 / p.boucWen.n);
        if (cache) {
            *cache = {ratio, root};
        }
        pinch.qzu = c.q * root;
    }
    return pinch;
}

// h of P2 and dh/dz at z for motion in direction s (+1 / -1).
struct PinchValue {
    double h, dhdz;
};

PinchValue pinchValue(const Pinch& pinch, double z, double s) {
    const double w = z * s - pinch.qzu;
    const double g = std::exp(-(w * w) / (pinch.zeta2 * pinch.zeta2));
    return {1.0 - pinch.zeta1 * g, pinch.zeta1 * g * 2.0 * w * s / (pinch.zeta2 * pinch.zeta2)};
}

// One backward-Euler step of P1 with Eqs 3-6 from (z0, e0), the pinching frozen at e0:
//   r(z) = z - z0 - dx h(z) Phi(z, e(z)) / eta(e(z)),  e(z) = e0 + (1 - alpha) k0 z dx,
// Newton from z0 with BoucWen's tolerances and divergence test (BoucWenNewton.h).
// absZ0n: |z0|^n, computed by the caller (the first iterate is z0).
bool pinchedStep(const BoucWenParameters& p, const Pinch& pinch, BoucWenState& state, double dx,
                 StepLimits& limits, double absZ0n) {
    const double c = (1.0 - p.alpha) * p.k0;
    const double z0 = state.z, e0 = state.e;
    const double s = dx < 0.0 ? -1.0 : 1.0;
    const double dedz = c * dx;
    double z = z0;
    for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
        const double e = e0 + c * z * dx;
        const Degradation d = degradationAt(p, e);
        const double absZ = std::abs(z);
        const double psi = p.gamma + p.beta * signOf(dx * z);
        const double absZn = iteration == 0 ? absZ0n : std::pow(absZ, p.n);
        const double phi = d.a - absZn * psi * d.nu;
        const double dAbsZn = absZ > 0.0 ? p.n * absZn / absZ * signOf(z) : 0.0;
        const double dPhi = -p.deltaA * dedz - dAbsZn * psi * d.nu - absZn * psi * p.deltaNu * dedz;
        const PinchValue hv = pinchValue(pinch, z, s);
        const double g = hv.h * phi;
        const double dg = hv.h * dPhi + hv.dhdz * phi;
        const double r = z - z0 - dx * g / d.eta;
        const double dEta = p.deltaEta * dedz;
        const double dr = 1.0 - dx * (dg * d.eta - g * dEta) / (d.eta * d.eta);
        const double delta = r / dr;
        z -= delta;
        if (!std::isfinite(z) || !limits.withinZBound(std::abs(z))) {
            return false;
        }
        if (std::abs(delta) <= kRelativeTolerance * std::max(std::abs(z), std::abs(z0))) {
            const BoucWenState end{z, e0 + c * z * dx};
            if (!std::isfinite(end.e)) {
                return false;
            }
            state = end;
            return true;
        }
    }
    return false;
}

// What the step limits of integrateSplit need at a state: the pinching quantities at its
// energy and, when pinched, |z0|^n, the largest rate max(|A|, |Phi(z0)|) and the unloading
// stiffness n |z0|^(n-1) max(Psi, 0) nu. The same for every halving of an increment from that
// state (Psi depends on dx only through its sign), so the first half of a split increment
// takes them from its parent instead of recomputing them (the pinched law's sub-stepping
// spends most of its time in these std::pow and std::expm1 calls).
struct AtState {
    Pinch pinch;
    Degradation d{0.0, 0.0, 0.0};
    double absZn = 0.0, rate = 0.0, stiffness = 0.0;
};

AtState atState(const BoucWenPinchingParameters& p, const BoucWenState& state, double dx,
                RootCache& cache) {
    AtState q;
    q.pinch = pinchAt(p, state.e, &cache);
    if (q.pinch.zeta1 > 0.0) {
        q.d = degradationAt(p.boucWen, state.e);
        const double psi = p.boucWen.gamma + p.boucWen.beta * signOf(dx * state.z);
        const double absZ = std::abs(state.z);
        q.absZn = std::pow(absZ, p.boucWen.n);
        const double phi0 = q.d.a - q.absZn * psi * q.d.nu;
        q.rate = std::max(std::abs(q.d.a), std::abs(phi0));
        q.stiffness =
            absZ > 0.0 ? p.boucWen.n * q.absZn / absZ * std::max(psi, 0.0) * q.d.nu : 0.0;
    }
    return q;
}

// BoucWen.cpp's integrateSplit with the pinched step: a sub-step with zeta1 = 0 is BoucWen's
// step (halved by the same rules, withinUnloadingStep included); with zeta1 > 0 it is also
// halved while |dx| A / eta > zeta2. `known`: atState() at this state, when the caller has it.
bool integrateSplit(const BoucWenPinchingParameters& p, BoucWenState& state, double dx,
                    int levelsLeft, StepLimits& limits, RootCache& cache, int& subSteps,
                    const AtState* known = nullptr) {
    const AtState q = known ? *known : atState(p, state, dx, cache);
    const Pinch& pinch = q.pinch;
    bool withinPinchStep = true;
    if (pinch.zeta1 > 0.0) {
        // The backward-Euler equation r(z) = 0 has one root near z0 only while its derivative
        // dr/dz = 1 - dx (h Phi' + h' Phi) / eta stays positive there. Two limits keep it so:
        //  - the law's own stiffness: on unloading with gamma > beta (Psi = gamma - beta > 0),
        //    dx Phi' / eta = |dx| n |z0|^(n-1) Psi nu / eta, which at a reversal near the
        //    ultimate z is about n (gamma - beta) / (gamma + beta) / 2 for the 0.5 yield
        //    deformations of withinMaxStep: above 1 for n > 2, and Newton from z0 then goes
        //    the wrong way to a second root beyond -zu (z moving against dx), from which the
        //    law runs away and fails a few increments later (the anchored sets that failed on
        //    new larger cycles; TestBoucWenPinching::reversalNearTheUltimateZWithLargeN). So
        //    |dx| n |z0|^(n-1) max(Psi, 0) nu / eta <= 0.5;
        //  - the pinching term: z moves at most |dx| max(|A|, |Phi(z0)|) / eta <= zeta2, one
        //    width of the pinched zone (|h'| <= 0.86 zeta1 / zeta2).
        withinPinchStep = std::abs(dx) * q.rate <= pinch.zeta2 * q.d.eta &&
                          std::abs(dx) * q.stiffness <= 0.5 * q.d.eta;
    } else {
        withinPinchStep = withinUnloadingStep(p.boucWen, state, dx); // as BoucWen.cpp's step
    }
    if (levelsLeft <= 0 || (limits.withinMaxStep(std::abs(dx)) && withinPinchStep)) {
        bool converged = false;
        if (pinch.zeta1 > 0.0) {
            converged = pinchedStep(p.boucWen, pinch, state, dx, limits, q.absZn);
        } else {
            BackwardEuler newton(p.boucWen, state, dx);
            auto progress = BackwardEuler::Progress::Iterating;
            while (progress == BackwardEuler::Progress::Iterating) {
                progress = newton.iterate(limits);
            }
            converged = progress == BackwardEuler::Progress::Converged;
            if (converged) {
                state = newton.state();
            }
        }
        if (converged) {
            ++subSteps;
            return true;
        }
        if (levelsLeft <= 0) {
            return false;
        }
    }
    // The first half starts from this (unchanged) state: it reuses q.
    const double half = 0.5 * dx;
    return integrateSplit(p, state, half, levelsLeft - 1, limits, cache, subSteps, &q) &&
           integrateSplit(p, state, half, levelsLeft - 1, limits, cache, subSteps);
}

BoucWenIncrement integrateAdmissible(const BoucWenPinchingParameters& p, const BoucWenState& from,
                                     double dx, int maxSubdivisions) {
    if (!std::isfinite(dx) || !std::isfinite(from.z) || !std::isfinite(from.e)) {
        return {LawStatus::InvalidInput, from, 0.0, 0};
    }
    StepLimits limits(p.boucWen, from);
    BoucWenState end = from;
    int subSteps = 0;
    RootCache cache;
    if (!integrateSplit(p, end, dx, std::max(maxSubdivisions, 0), limits, cache, subSteps)) {
        return {LawStatus::NoConvergence, from, 0.0, 0};
    }
    return {LawStatus::Ok, end, 0.0, subSteps};
}

double slopeWithPinching(const BoucWenPinchingParameters& p, const BoucWenState& s, double dir) {
    const double slope = slopeAt(p.boucWen, s, dir);
    const Pinch pinch = pinchAt(p, s.e);
    return pinch.zeta1 > 0.0 ? pinchValue(pinch, s.z, dir).h * slope : slope;
}

} // namespace

BoucWenPinching::BoucWenPinching(const BoucWenPinchingParameters& p) : m_p(p) {
    if (!admissible(p)) {
        throw std::invalid_argument("BoucWenPinching: parameters are not admissible");
    }
    revertToStart();
}

BoucWenIncrement BoucWenPinching::integrate(const BoucWenPinchingParameters& p,
                                            const BoucWenState& from, double dx,
                                            int maxSubdivisions) {
    if (!admissible(p)) {
        return {LawStatus::InvalidInput, from, 0.0, 0};
    }
    BoucWenIncrement result = integrateAdmissible(p, from, dx, maxSubdivisions);
    if (result.status == LawStatus::Ok) {
        result.dzdx = slopeWithPinching(p, result.state, dx < 0.0 ? -1.0 : 1.0);
    }
    return result;
}

bool BoucWenPinching::admissible(const BoucWenPinchingParameters& p) {
    const PinchingParameters& c = p.pinching;
    const bool finite = std::isfinite(c.zetaS) && std::isfinite(c.p) && std::isfinite(c.q) &&
                        std::isfinite(c.psi) && std::isfinite(c.deltaPsi) &&
                        std::isfinite(c.lambda);
    return admissibleParameters(p.boucWen) && finite && c.zetaS >= 0.0 && c.zetaS < 1.0 &&
           c.p >= 0.0 && c.q >= 0.0 && c.q < 1.0 && c.psi > 0.0 && c.deltaPsi >= 0.0 &&
           c.lambda > 0.0;
}

double BoucWenPinching::pinchingFactor(const BoucWenPinchingParameters& p, const BoucWenState& s,
                                       double dir) {
    const Pinch pinch = pinchAt(p, s.e);
    return pinch.zeta1 > 0.0 ? pinchValue(pinch, s.z, dir < 0.0 ? -1.0 : 1.0).h : 1.0;
}

bool BoucWenPinching::setParameters(const BoucWenPinchingParameters& p) {
    if (!admissible(p)) {
        return false;
    }
    m_p = p;
    m_fCommitted = forceOf(m_uCommitted / m_p.boucWen.uRef, m_committed);
    revert();
    return true;
}

LawStatus BoucWenPinching::setTrialDeformation(double u) {
    if (!std::isfinite(u)) {
        revert();
        return LawStatus::InvalidInput;
    }
    const double dx = (u - m_uCommitted) / m_p.boucWen.uRef;
    const BoucWenIncrement inc =
        integrateAdmissible(m_p, m_committed, dx, BoucWen::kDefaultMaxSubdivisions);
    if (inc.status != LawStatus::Ok) {
        revert();
        return inc.status;
    }
    m_trial = inc.state;
    m_uTrial = u;
    m_dirTrial = dx > 0.0 ? 1.0 : (dx < 0.0 ? -1.0 : m_dirCommitted);
    m_fTrial = forceOf(u / m_p.boucWen.uRef, m_trial);
    return LawStatus::Ok;
}

void BoucWenPinching::setCommittedState(const BoucWenState& s, double committedDeformation) {
    m_committed = s;
    m_uCommitted = committedDeformation;
    m_fCommitted = forceOf(m_uCommitted / m_p.boucWen.uRef, m_committed);
    revert();
}

double BoucWenPinching::initialTangent() const {
    const BoucWenParameters& b = m_p.boucWen;
    return b.k0 * (b.alpha + (1.0 - b.alpha) * b.A0) * b.fRef / b.uRef;
}

void BoucWenPinching::commit() {
    m_committed = m_trial;
    m_uCommitted = m_uTrial;
    m_fCommitted = m_fTrial;
    m_dirCommitted = m_dirTrial;
}

void BoucWenPinching::revert() {
    m_trial = m_committed;
    m_uTrial = m_uCommitted;
    m_fTrial = m_fCommitted;
    m_dirTrial = m_dirCommitted;
}

void BoucWenPinching::revertToStart() {
    m_committed = BoucWenState{};
    m_uCommitted = 0.0;
    m_fCommitted = 0.0;
    m_dirCommitted = 1.0;
    revert();
}

std::unique_ptr<HysteresisLaw> BoucWenPinching::clone() const {
    return std::make_unique<BoucWenPinching>(*this);
}

std::vector<std::string> BoucWenPinching::parameterNames() const {
    return {kNames.begin(), kNames.end()};
}

double BoucWenPinching::parameterValue(int index) const {
    BoucWenPinchingParameters p = m_p;
    const double* field = fieldAt(p, index);
    return field ? *field : std::numeric_limits<double>::quiet_NaN();
}

int BoucWenPinching::setParameterValues(std::span<const int> indices,
                                        std::span<const double> values, bool allOrNothing) {
    BoucWenPinchingParameters p = m_p;
    if (allOrNothing) { // judged together, as BoucWen does (BoucWen.h)
        for (std::size_t k = 0; k < indices.size(); ++k) {
            double* field = fieldAt(p, indices[k]);
            if (!field) {
                setParameters(m_p);
                return static_cast<int>(k);
            }
            *field = values[k];
        }
        if (!admissible(p)) {
            // Refused: name the first value that is inadmissible on its own, else the first.
            int refused = 0;
            for (std::size_t k = 0; k < indices.size(); ++k) {
                BoucWenPinchingParameters alone = m_p;
                *fieldAt(alone, indices[k]) = values[k];
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
        if (double* field = fieldAt(p, indices[k])) {
            const double previous = *field;
            *field = values[k];
            if (admissible(p)) {
                changed = true;
                continue;
            }
            *field = previous;
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

double BoucWenPinching::forceOf(double x, const BoucWenState& s) const {
    const BoucWenParameters& b = m_p.boucWen;
    return b.fRef * b.k0 * (b.alpha * x + (1.0 - b.alpha) * s.z);
}

double BoucWenPinching::tangentOf(const BoucWenState& s, double dir) const {
    const BoucWenParameters& b = m_p.boucWen;
    const double dzdx = slopeWithPinching(m_p, s, dir);
    return b.k0 * (b.alpha + (1.0 - b.alpha) * dzdx) * b.fRef / b.uRef;
}

BoucWenPinchingParameters rescaled(const BoucWenPinchingParameters& p, double uRef,
                                   double fRef) {
    const double s = p.boucWen.uRef / uRef, c = p.boucWen.fRef / fRef;
    BoucWenPinchingParameters q = p;
    q.boucWen = rescaled(p.boucWen, uRef, fRef);
    q.pinching.p = p.pinching.p / (c * s);
    q.pinching.psi = p.pinching.psi * s;
    q.pinching.deltaPsi = p.pinching.deltaPsi / c;
    return q;
}

} // namespace hsmu
