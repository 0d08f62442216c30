#pragma once
// Bouc-Wen hysteresis with Baber-Noori degradation (docs/method.md, The Bouc-Wen law with
// degradation; paper Eqs 1-6), in the convention of OpenSees `uniaxialMaterial BoucWen`:
//
//   F     = alpha k0 x + (1 - alpha) k0 z                                   (Eq. 1)
//   dz/dx = [ A - |z|^n (beta sgn(dx z) + gamma) nu ] / eta                 (Eq. 2)
//   de/dx = (1 - alpha) k0 z                                                (Eq. 3)
//   A = A0 - deltaA e,  nu = 1 + deltaNu e,  eta = 1 + deltaEta e           (Eqs 4-6)
//
// The law runs on normalized variables x = u / uRef and f = F / fRef; k0 is then the
// normalized stiffness and the physical initial stiffness is k0 fRef / uRef. With the default
// uRef = fRef = 1 the law is in the caller's units (k0 in force per deformation).
//
// Integration over an increment dx from the committed (z0, e0): backward Euler, implicit in
// both z and e as in OpenSees,
//   e = e0 + (1 - alpha) k0 z dx,   r(z) = z - z0 - dx [A - |z|^n (beta s + gamma) nu] / eta = 0
// with A, nu, eta from that e and s = sgn(dx z), solved by Newton with the analytic dr/dz,
// started from the committed z (not 0.01 as OpenSees), converged when the Newton update is
// below 1e-12 max(|z|, |z0|), at most 30 iterations. An iterate that is not finite or leaves
// |z| <= 10 max(|z0|, ultimateZ) counts as a failure. An increment longer than half the
// current yield deformation (zu(e) eta / A, with zu(e) the ultimate z at energy e) is halved
// before Newton is tried, and so is an unloading one (dx z0 < 0) with gamma > beta while
// |dx| n |z0|^(n-1) (gamma - beta) nu / eta > 0.5 at its start (else dr/dz can be negative at
// z0 and Newton finds a second root beyond -zu; BoucWenNewton.h, withinUnloadingStep), and a
// failed one is halved too, recursively up to maxSubdivisions
// halvings (2^12 sub-steps by default); the sub-steps run sequentially. A sub-step of the
// last level whose Newton solve fails (with n < 1 Newton cycles at the cusp of |z|^n at z = 0)
// is solved bracketed: the root nearest z0 in the direction of -r(z0), bracketed by doubling
// steps from z0 within the iterates' bound, then bisected to the Newton tolerance (issue 29;
// only ever where the law failed before, so a step that succeeded is unchanged). An unloading
// increment (dx z0 < 0, gamma > beta) that still fails from beyond the unloading branch's bound
// z1(e0) = (A / (nu (gamma - beta)))^(1/n), where Eq. 2 itself runs away (a UKF sigma point's
// parameters under a state, or beta < 0), is integrated from |z| = 2^(-1/n) z1(e0) instead
// (e0 kept; docs/hysteresis-laws.md; BoucWen.cpp, returnedToUnloadingBound). Failure is
// reported as LawStatus::NoConvergence and leaves the committed state untouched.
// Accuracy: first order in the step (about 4e-4 of the peak force with 20000 points per
// +-8-yield cycle; 2e-2 with 400 points).
//
// Tangent (physical units): fRef / uRef * k0 [alpha + (1 - alpha) dz/dx] with the continuous
// dz/dx of Eq. 2 at the end state (not the consistent tangent of the discrete map); sgn uses
// the direction of the increment, or for a zero increment that of the last committed non-zero
// increment (+1 in the virgin state).
//
// Admissible parameters (admissible()): all finite, k0 > 0, 0 <= alpha <= 1, n > 0, A0 > 0,
// beta + gamma > 0 (bounded z; beta and gamma may each be negative), deltaA, deltaNu,
// deltaEta >= 0 (degradation only), uRef > 0, fRef > 0.

#include "core/hysteresis/HysteresisLaw.h"

#include <span>

namespace hsmu {

struct BoucWenParameters {
    double k0 = 1.0;       ///< initial stiffness (normalized when uRef/fRef are set)
    double alpha = 0.02;   ///< post-yield to initial stiffness ratio [-]
    double n = 2.0;        ///< smoothness of the transition, >= 1 recommended [-]
    double beta = 3.0;     ///< loop shape [-]
    double gamma = 1.0;    ///< loop shape [-]
    double A0 = 1.0;       ///< initial value of A [-]
    double deltaA = 0.0;   ///< degradation of A with e
    double deltaNu = 0.0;  ///< strength degradation with e
    double deltaEta = 0.0; ///< stiffness degradation with e
    double uRef = 1.0;     ///< deformation reference scale (physical units), > 0
    double fRef = 1.0;     ///< force reference scale (physical units), > 0
};

/// The law's internal state (normalized units).
struct BoucWenState {
    double z = 0.0; ///< hysteretic variable (normalized deformation units)
    double e = 0.0; ///< dissipated-energy measure (normalized)
};

/// Result of integrating z, e over one normalized increment.
struct BoucWenIncrement {
    LawStatus status = LawStatus::Ok;
    BoucWenState state; ///< state at the end of the increment
    double dzdx = 0.0;  ///< continuous dz/dx at the end state (for the tangent)
    int subSteps = 1;   ///< how many sub-steps were used
};

class BoucWen final : public HysteresisLaw {
public:
    /// Throws std::invalid_argument if p is not admissible (use LawFactory for a message that
    /// names the parameter).
    explicit BoucWen(const BoucWenParameters& p = {});

    /// Halvings of an increment allowed by default (2^12 sub-steps).
    static constexpr int kDefaultMaxSubdivisions = 12;

    /// Integrate the evolution equations over the normalized increment dx from `from`
    /// (pure function: no object state; also used by the UKF's sigma points).
    /// InvalidInput if dx or `from` is not finite or p is not admissible; NoConvergence if
    /// even maxSubdivisions halvings fail. On failure `state` is `from` and subSteps is 0.
    /// dzdx uses the direction of dx (+1 for dx == 0).
    static BoucWenIncrement integrate(const BoucWenParameters& p, const BoucWenState& from,
                                      double dx, int maxSubdivisions = kDefaultMaxSubdivisions);
    /// integrate() without dzdx (left 0), for callers that need only the end state (the UKF's
    /// sigma points): saves the std::pow of the slope, about a fifth of a typical step.
    static BoucWenIncrement integrateState(const BoucWenParameters& p, const BoucWenState& from,
                                           double dx,
                                           int maxSubdivisions = kDefaultMaxSubdivisions);
    /// How integrateStates() evaluates |z|^n.
    enum class BatchMath {
        Exact, ///< std::pow (exact forms for z = 0, n = 1, 2): the end states of integrateState(),
               ///< bit for bit
        Fast,  ///< a vector pow (glibc libmvec, AVX2) where the processor has AVX2, four
               ///< problems per call, within 1 ulp of std::pow (end states within a few ulps
               ///< of integrateState()'s); elsewhere Exact
    };
    /// Whether BatchMath::Fast uses the vector pow on this machine and build.
    static bool fastBatchMathAvailable();
    /// How BatchMath::Fast evaluates |z|^n here: "libmvec AVX2 vector pow" or "std::pow"
    /// (records name it, since it decides the last digits of an identification).
    static const char* fastBatchMathName();
    /// integrateState() for several problems with the same dx (the UKF's sigma points), out[i]
    /// for p[i] and from[i] (up to the shortest of the three). Same decisions and arithmetic
    /// as integrateState(), four problems per vector, their Newton iterations interleaved
    /// (each is a chain of dependent divisions and powers that the processor can overlap); a
    /// problem that is not a single plain step (inadmissible, non-finite, an increment to
    /// halve, a Newton failure) is left to integrateState(). With BatchMath::Exact the results
    /// are integrateState()'s bit for bit.
    static void integrateStates(std::span<const BoucWenParameters> p,
                                std::span<const BoucWenState> from, double dx,
                                std::span<BoucWenIncrement> out, BatchMath math = BatchMath::Exact);
    /// Ultimate |z| of the non-degraded law: (A0 / (nu (beta + gamma)))^(1/n) with nu = 1.
    static double ultimateZ(const BoucWenParameters& p);

    const BoucWenParameters& parameters() const { return m_p; }
    /// Replace all parameters; the committed (z, e) (normalized) is kept, the committed force
    /// and tangent are re-evaluated with the new parameters and a pending trial is dropped
    /// (as by revert()). False, and nothing changes, if p is not admissible.
    bool setParameters(const BoucWenParameters& p);
    static bool admissible(const BoucWenParameters& p);
    /// The estimators keep beta + gamma at or above this margin (docs/method.md,
    /// "Admissibility").
    static constexpr double kBetaGammaMargin = 1e-3;
    /// Moves (beta, gamma) along (1, 1) onto beta + gamma = kBetaGammaMargin when the sum is
    /// below it (the nearest such point); true if it moved them.
    static bool projectBetaGamma(double& beta, double& gamma);

    BoucWenState committedState() const { return m_committed; }
    BoucWenState trialState() const { return m_trial; }
    /// Set the committed (and trial) state, e.g. to continue a saved specimen.
    void setCommittedState(const BoucWenState& s, double committedDeformation);

    // HysteresisLaw. setTrialDeformation: InvalidInput for a non-finite u, NoConvergence as
    // above; either way the trial is reset to the committed state.
    std::string lawName() const override { return "boucWen"; }
    LawStatus setTrialDeformation(double u) override;
    double trialDeformation() const override { return m_uTrial; }
    double trialForce() const override { return m_fTrial; }
    /// Computed on demand (a std::pow): explicit integrators never ask for it.
    double trialTangent() const override { return tangentOf(m_trial, m_dirTrial); }
    /// d(trial force)/d(trial deformation) through the backward-Euler map of one increment
    /// from the committed (z0, e0), implicit in z with e = e0 + (1 - alpha) k0 dx z:
    ///   r(z, dx) = z - z0 - dx Phi / eta,  Phi = A - |z|^n Psi nu,  Psi = gamma + beta s,
    ///   dz/dx = -(dr/ddx) / (dr/dz)  (both partials include e's dependence on z and dx),
    ///   tangent = fRef / uRef k0 [alpha + (1 - alpha) dz/dx];  z = 0: fRef / uRef k0,
    /// with s = +1 when dx z > 0, else -1 (so gamma - beta for dx = 0), as OpenSees'
    /// BoucWenMaterial::getTangent. An increment the law subdivided uses the same one-step
    /// formula from the committed state (then an approximation of the sub-stepped map).
    double algorithmicTangent() const override;
    double committedDeformation() const override { return m_uCommitted; }
    double committedForce() const override { return m_fCommitted; }
    double initialTangent() const override;
    void commit() override;
    void revert() override;
    void revertToStart() override;
    std::unique_ptr<HysteresisLaw> clone() const override;
    /// k0, alpha, n, beta, gamma, A0, deltaA, deltaNu, deltaEta, uRef, fRef.
    std::vector<std::string> parameterNames() const override;
    double parameterValue(int index) const override;
    /// As the base class says, deciding each value on a copy of the parameters with
    /// admissible() and setting them all with one setParameters().
    int setParameterValues(std::span<const int> indices, std::span<const double> values,
                           bool allOrNothing) override;

private:
    double forceOf(double x, const BoucWenState& s) const; // physical force
    /// Physical tangent at state s when moving in direction dir (+1 or -1).
    double tangentOf(const BoucWenState& s, double dir) const;
    BoucWenParameters m_p;
    BoucWenState m_committed, m_trial;
    double m_uCommitted = 0.0, m_uTrial = 0.0;
    double m_fCommitted = 0.0, m_fTrial = 0.0;
    /// Direction (+1 / -1) of the last non-zero increment; used for the tangent when the
    /// trial increment is zero (sgn(dx z) in Eq. 2 is otherwise undefined).
    double m_dirCommitted = 1.0, m_dirTrial = 1.0;
};

/// The same physical Bouc-Wen model in the scales (uRef, fRef) (both > 0): with s = p.uRef /
/// uRef and c = p.fRef / fRef, k0 c / s, beta and gamma s^-n, deltaA, deltaNu, deltaEta
/// 1 / (c s); alpha, n, A0 unchanged (the law's equations, docs/method.md). The state maps as
/// z s, e c s (rescaledState).
BoucWenParameters rescaled(const BoucWenParameters& p, double uRef, double fRef);
BoucWenState rescaledState(const BoucWenState& s, const BoucWenParameters& from,
                           const BoucWenParameters& to);

} // namespace hsmu
