#include "core/hysteresis/MrDamper.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace hsmu {

namespace {

using Field = double MrDamperParameters::*;
constexpr std::array<std::pair<const char*, Field>, 12> kFields{{
    {"c0", &MrDamperParameters::c0},
    {"c1", &MrDamperParameters::c1},
    {"k0", &MrDamperParameters::k0},
    {"k1", &MrDamperParameters::k1},
    {"f0", &MrDamperParameters::f0},
    {"alpha", &MrDamperParameters::alpha},
    {"A", &MrDamperParameters::A},
    {"beta", &MrDamperParameters::beta},
    {"gamma", &MrDamperParameters::gamma},
    {"n", &MrDamperParameters::n},
    {"uRef", &MrDamperParameters::uRef},
    {"fRef", &MrDamperParameters::fRef},
}};

constexpr double kRelativeTolerance = 1e-12;
constexpr double kUnknownTangent = std::numeric_limits<double>::quiet_NaN();
constexpr int kMaxNewtonIterations = 30;
// A sub-step moves w by at most this many yield deformations zu / A (as boucWen's steps).
constexpr double kMaxStepInYieldDeformations = 0.5;
// Largest |dw| n |z0|^(n-1) (gamma - beta) of an unloading sub-step (boucWen's rule).
constexpr double kMaxUnloadingStiffness = 0.5;
// An iterate beyond this multiple of max(|z0|, zu) is a divergence.
constexpr double kWildJumpFactor = 10.0;
// Relaxation sub-steps of a quasi-static step (durations doubling from the relaxation time).
constexpr int kRelaxationSteps = 80;

double signOf(double v) {
    return static_cast<double>((v > 0.0) - (v < 0.0));
}

/// The derivatives of (w, z) with respect to the step's normalized increment dx.
struct Sensitivity {
    double w = 0.0, z = 0.0;
};

/// The step being integrated: its increment, duration and the limits of a sub-step.
class Step {
public:
    Step(const MrDamperParameters& p, double dx, double h)
        : m_p(p), m_c(p.c0 + p.c1), m_dx(dx), m_h(h),
          m_zu(MrDamper::ultimateZ(p)) {
        m_maxDw = kMaxStepInYieldDeformations * (std::isfinite(m_zu) ? m_zu / p.A : 1.0);
    }

    /// Integrates the fraction `theta` of the step (all of it: 1) from s (with its
    /// sensitivity d), halving while levels are left; false if even that fails.
    bool integrate(MrDamperState& s, Sensitivity& d, double theta, int levelsLeft,
                   int& subSteps) const {
        MrDamperState s1 = s;
        Sensitivity d1 = d;
        if (subStep(s1, d1, theta, levelsLeft > 0)) {
            s = s1;
            d = d1;
            ++subSteps;
            return true;
        }
        if (levelsLeft <= 0)
            return false;
        return integrate(s, d, 0.5 * theta, levelsLeft - 1, subSteps) &&
               integrate(s, d, 0.5 * theta, levelsLeft - 1, subSteps);
    }

    /// One backward-Euler sub-step of duration tau = theta h; `limited`: refuse one that
    /// breaks a sub-step limit (so that it is halved).
    bool subStep(MrDamperState& s, Sensitivity& d, double theta, bool limited) const {
        const MrDamperParameters& p = m_p;
        const double tau = theta * m_h;
        const double D = 1.0 + tau * p.k0 / m_c;
        const double P = tau / (m_c * D);
        const double drive = theta * m_dx * p.c1 / m_c; // tau c1 xd / c
        const double W = (s.w + drive) / D;
        const double w0 = s.w, z0 = s.z;
        const double a = W - w0;  // dw without the z1 term
        const double b = P * p.alpha; // dw = a - b z1
        if (!std::isfinite(a) || !std::isfinite(b))
            return false;
        if (limited) {
            const double predicted = a - b * z0;
            if (!withinLimits(predicted, z0))
                return false;
        }
        double z = z0;
        const double zBound = kWildJumpFactor * std::max(std::abs(z0), m_zu);
        bool converged = false;
        double dr = 1.0, phi = p.A;
        for (int it = 0; it < kMaxNewtonIterations; ++it) {
            const double dw = a - b * z;
            const double absZ = std::abs(z);
            const double psi = p.gamma + p.beta * signOf(dw * z);
            const double absZn = std::pow(absZ, p.n);
            phi = p.A - absZn * psi;
            const double dPhi = absZ > 0.0 ? -p.n * absZn / absZ * signOf(z) * psi : 0.0;
            const double r = z - z0 - dw * phi;
            dr = 1.0 + b * phi - dw * dPhi;
            const double delta = r / dr;
            const double next = z - delta;
            if (!std::isfinite(next) || std::abs(next) > zBound)
                return false;
            z = next;
            if (std::abs(delta) <= kRelativeTolerance * std::max(std::abs(z), std::abs(z0))) {
                converged = true;
                break;
            }
        }
        if (!converged)
            return false;
        const double dw = a - b * z;
        if (limited && !withinLimits(dw, z0))
            return false;
        // slope and residual derivative at the solution (for the sensitivities)
        const double absZ = std::abs(z);
        const double psi = p.gamma + p.beta * signOf(dw * z);
        const double absZn = std::pow(absZ, p.n);
        phi = p.A - absZn * psi;
        const double dPhi = absZ > 0.0 ? -p.n * absZn / absZ * signOf(z) * psi : 0.0;
        dr = 1.0 + b * phi - dw * dPhi;
        // W' = w0' / D + theta c1 / (c D), dw' = W' - w0' - b z1', z1' (dr/dz) = z0' + (W' - w0') Phi
        const double dW = d.w / D + theta * p.c1 / (m_c * D);
        const double dz = (d.z + (dW - d.w) * phi) / dr;
        const double dwNew = dW - b * dz;
        if (!std::isfinite(dz) || !std::isfinite(dwNew) || !std::isfinite(W - b * z))
            return false;
        s = {W - b * z, z};
        d = {dwNew, dz};
        return true;
    }

private:
    bool withinLimits(double dw, double z0) const {
        if (!(std::abs(dw) <= m_maxDw))
            return false;
        const double psi = m_p.gamma - m_p.beta; // on unloading
        if (dw * z0 < 0.0 && psi > 0.0) {
            const double absZ = std::abs(z0);
            return std::abs(dw) * m_p.n * std::pow(absZ, m_p.n - 1.0) * psi <=
                   kMaxUnloadingStiffness;
        }
        return true;
    }

    const MrDamperParameters& m_p;
    double m_c, m_dx, m_h, m_zu;
    double m_maxDw = 0.0;
};

/// The quasi-static step: the internal branch relaxes to rest (alpha z + k0 w = 0) by
/// backward-Euler sub-steps whose durations double from the relaxation time.
bool relax(const MrDamperParameters& p, MrDamperState& s, int& subSteps) {
    const double load0 = std::abs(p.alpha * s.z + p.k0 * s.w);
    if (load0 == 0.0)
        return true;
    const double stiffness = p.alpha * p.A + p.k0;
    double tau = (p.c0 + p.c1) / stiffness;
    for (int j = 0; j < kRelaxationSteps; ++j, tau *= 2.0) {
        const Step step(p, 0.0, tau);
        Sensitivity ignored;
        if (!step.integrate(s, ignored, 1.0, MrDamper::kMaxSubdivisions, subSteps))
            return false;
        if (std::abs(p.alpha * s.z + p.k0 * s.w) <= 1e-12 * load0)
            return true;
    }
    return true; // as close as the doubling got: the residual load is negligible or creeping
}

bool allFinite(const MrDamperParameters& p) {
    for (const auto& [name, field] : kFields)
        if (!std::isfinite(p.*field))
            return false;
    return true;
}

} // namespace

MrDamper::MrDamper(const MrDamperParameters& p) : m_p(p) {
    if (!admissible(p))
        throw std::invalid_argument("MrDamper: parameters are not admissible");
    revertToStart();
}

bool MrDamper::admissible(const MrDamperParameters& p) {
    return allFinite(p) && p.c0 >= 0.0 && p.c1 > 0.0 && p.k0 >= 0.0 && p.k1 >= 0.0 &&
           p.alpha >= 0.0 && p.A > 0.0 && p.n > 0.0 && p.beta + p.gamma > 0.0 && p.uRef > 0.0 &&
           p.fRef > 0.0;
}

double MrDamper::ultimateZ(const MrDamperParameters& p) {
    return std::pow(p.A / (p.beta + p.gamma), 1.0 / p.n);
}

MrDamperParameters MrDamper::rescaled(const MrDamperParameters& p, double uRef, double fRef) {
    const double s = p.uRef / uRef, c = p.fRef / fRef;
    MrDamperParameters q = p;
    for (double MrDamperParameters::*f : {&MrDamperParameters::c0, &MrDamperParameters::c1,
                                          &MrDamperParameters::k0, &MrDamperParameters::k1,
                                          &MrDamperParameters::alpha})
        q.*f = p.*f * c / s;
    q.f0 = p.f0 * c;
    const double shape = std::pow(s, -p.n);
    q.beta = p.beta * shape;
    q.gamma = p.gamma * shape;
    q.uRef = uRef;
    q.fRef = fRef;
    return q;
}

void MrDamper::setCommittedState(const MrDamperState& s, double deformation, double velocity) {
    m_committed = s;
    m_uCommitted = deformation;
    m_vCommitted = velocity;
    m_fCommitted = forceOf(deformation / m_p.uRef, velocity / m_p.uRef, s);
    revert();
}

bool MrDamper::setParameters(const MrDamperParameters& p) {
    if (!admissible(p))
        return false;
    m_p = p;
    m_fCommitted = forceOf(m_uCommitted / m_p.uRef, m_vCommitted / m_p.uRef, m_committed);
    revert();
    return true;
}

double MrDamper::forceOf(double x, double xd, const MrDamperState& s) const {
    const double c = m_p.c0 + m_p.c1;
    return m_p.fRef * (m_p.c0 * m_p.c1 / c * xd + m_p.c1 / c * (m_p.alpha * s.z + m_p.k0 * s.w) +
                       m_p.k1 * x + m_p.f0);
}

LawStatus MrDamper::integrateTrial(double u, MrDamperState& s, double& tangent,
                                   int& subSteps) const {
    if (!std::isfinite(u))
        return LawStatus::InvalidInput;
    if (!(m_dt > 0.0))
        return LawStatus::InvalidInput;
    const MrDamperParameters& p = m_p;
    const double dx = (u - m_uCommitted) / p.uRef;
    s = m_committed;
    Sensitivity d;
    subSteps = 0;
    const bool quasiStatic = !std::isfinite(m_dt);
    const bool ok = quasiStatic
                        ? relax(p, s, subSteps)
                        : Step(p, dx, m_dt).integrate(s, d, 1.0, kMaxSubdivisions, subSteps);
    if (!ok || !std::isfinite(s.w) || !std::isfinite(s.z)) {
        s = m_committed;
        return LawStatus::NoConvergence;
    }
    const double c = p.c0 + p.c1;
    tangent = p.fRef / p.uRef * p.k1;
    if (!quasiStatic)
        tangent += p.fRef / p.uRef *
                   (p.c0 * p.c1 / (c * m_dt) + p.c1 / c * (p.alpha * d.z + p.k0 * d.w));
    return LawStatus::Ok;
}

LawStatus MrDamper::setTrialDeformation(double u) {
    MrDamperState s;
    double tangent = 0.0;
    int subSteps = 0;
    const LawStatus status = integrateTrial(u, s, tangent, subSteps);
    if (status != LawStatus::Ok) {
        revert();
        if (!std::isfinite(u))
            m_failure = "mrDamper: the deformation is not finite";
        else if (!(m_dt > 0.0))
            m_failure = "mrDamper: no time increment (a rate-dependent law needs the time from "
                        "the committed state to the trial, HysteresisLaw::setTimeIncrement; it "
                        "is " + std::to_string(m_dt) + " s)";
        else
            m_failure = "mrDamper: the internal state could not be integrated over the step";
        return status;
    }
    m_failure.clear();
    m_trial = s;
    m_subSteps = subSteps;
    m_uTrial = u;
    m_vTrial = std::isfinite(m_dt) ? (u - m_uCommitted) / m_dt : 0.0;
    m_fTrial = forceOf(u / m_p.uRef, m_vTrial / m_p.uRef, s);
    m_tangentTrial = tangent;
    return LawStatus::Ok;
}

double MrDamper::trialTangent() const {
    if (std::isfinite(m_tangentTrial))
        return m_tangentTrial;
    // no trial since the last commit / revert / parameter change: the tangent of a trial at
    // the trial deformation with the current time increment
    MrDamperState s;
    double tangent = 0.0;
    int subSteps = 0;
    return integrateTrial(m_uTrial, s, tangent, subSteps) == LawStatus::Ok ? tangent
                                                                           : initialTangent();
}

double MrDamper::initialTangent() const {
    return m_p.fRef / m_p.uRef * (m_p.k1 + m_p.k0 + m_p.alpha * m_p.A);
}

void MrDamper::commit() {
    m_committed = m_trial;
    m_uCommitted = m_uTrial;
    m_vCommitted = m_vTrial;
    m_fCommitted = m_fTrial;
    m_tangentTrial = kUnknownTangent; // of the next trial (the committed state moved)
}

void MrDamper::revert() {
    m_trial = m_committed;
    m_uTrial = m_uCommitted;
    m_vTrial = m_vCommitted;
    m_fTrial = m_fCommitted;
    m_tangentTrial = kUnknownTangent;
    m_subSteps = 0;
}

void MrDamper::revertToStart() {
    m_committed = MrDamperState{};
    m_uCommitted = 0.0;
    m_vCommitted = 0.0;
    m_fCommitted = forceOf(0.0, 0.0, m_committed);
    revert();
}

std::unique_ptr<HysteresisLaw> MrDamper::clone() const {
    return std::make_unique<MrDamper>(*this);
}

std::vector<std::string> MrDamper::parameterNames() const {
    std::vector<std::string> names;
    names.reserve(kFields.size());
    for (const auto& [name, field] : kFields)
        names.emplace_back(name);
    return names;
}

double MrDamper::parameterValue(int index) const {
    if (index < 0 || static_cast<std::size_t>(index) >= kFields.size())
        return std::numeric_limits<double>::quiet_NaN();
    return m_p.*(kFields[static_cast<std::size_t>(index)].second);
}

int MrDamper::setParameterValues(std::span<const int> indices, std::span<const double> values,
                                 bool allOrNothing) {
    const auto valid = [](int i) { return i >= 0 && static_cast<std::size_t>(i) < kFields.size(); };
    MrDamperParameters p = m_p;
    if (allOrNothing) { // judged together (beta and gamma may change sign together)
        for (std::size_t k = 0; k < indices.size(); ++k) {
            if (!valid(indices[k])) {
                setParameters(m_p); // as a refused set: force re-evaluated, trial dropped
                return static_cast<int>(k);
            }
            p.*(kFields[static_cast<std::size_t>(indices[k])].second) = values[k];
        }
        if (!admissible(p)) {
            int refused = 0; // the first value inadmissible on its own, else the first
            for (std::size_t k = 0; k < indices.size(); ++k) {
                MrDamperParameters alone = m_p;
                alone.*(kFields[static_cast<std::size_t>(indices[k])].second) = values[k];
                if (!admissible(alone)) {
                    refused = static_cast<int>(k);
                    break;
                }
            }
            setParameters(m_p);
            return refused;
        }
        setParameters(p);
        return -1;
    }
    bool changed = false;
    int firstRefused = -1;
    for (std::size_t k = 0; k < indices.size(); ++k) {
        if (valid(indices[k])) {
            const Field field = kFields[static_cast<std::size_t>(indices[k])].second;
            const double previous = p.*field;
            p.*field = values[k];
            if (admissible(p)) {
                changed = true;
                continue;
            }
            p.*field = previous;
        }
        if (firstRefused < 0)
            firstRefused = static_cast<int>(k);
    }
    if (changed)
        setParameters(p);
    return firstRefused;
}

} // namespace hsmu
