#pragma once
// MrDamper: a phenomenological, rate-dependent law of a magnetorheological (MR) damper at a
// constant command voltage: the "modified Bouc-Wen" model of Spencer, Dyke, Sain & Carlson
// (1997, "Phenomenological model for magnetorheological dampers", J. Eng. Mech. 123(3),
// 230-238, their Fig. 5 and Eqs 3-6; docs/hysteresis-laws.md, "mrDamper"). A Bouc-Wen element
// (force alpha z), a dashpot c0 and a spring k0 act in parallel between the damper's end x and
// an internal point y; a dashpot c1 ties y to the other end, and a spring k1 acts over the
// whole damper. On the normalized deformation x = u / uRef and force f = F / fRef (with the
// default uRef = fRef = 1, in the caller's units and seconds):
//
//   f     = c1 dy/dt + k1 x + f0
//   dy/dt = [ alpha z + c0 dx/dt + k0 (x - y) ] / (c0 + c1)
//   dz/dt = [ A - |z|^n (beta sgn(dw/dt z) + gamma) ] dw/dt,     w = x - y
//
// (equivalently f = alpha z + c0 dw/dt + k0 w + k1 x + f0: the internal branch plus k1).
// Spencer et al. write the outer spring k1 (x - x0) with x0 the accumulator's preload: here
// the constant f0 = -k1 x0, which stays identifiable when k1 is 0. Their z equation,
// dz/dt = -gamma |wd| z |z|^(n-1) - beta wd |z|^n + A wd, has gamma on the sign term: here, as
// in boucWen (BoucWen.h), beta multiplies sgn(dw z) (their gamma is our beta, their beta our
// gamma). The model's low-velocity roll-off comes from c1: at rest the internal branch relaxes
// (time constant about (c0 + c1) / (alpha A + k0)) and the force tends to k1 x + f0.
//
// Rate: a trial moves x at the constant velocity xd = (x - x_committed) / dt over the time
// dt = timeIncrement() (HysteresisLaw.h, rate-dependent laws). The internal state (w, z) is
// integrated over that time by backward Euler: a sub-step of duration tau solves
//   w1 = [ w0 + tau (c1 xd - alpha z1) / c ] / (1 + tau k0 / c),   c = c0 + c1
//   z1 = z0 + (w1 - w0) Phi(z1),   Phi(z) = A - |z|^n (beta sgn((w1 - w0) z) + gamma)
// for z1 by Newton (w1 is linear in z1), and the step is halved (up to 2^12 sub-steps) while a
// sub-step's |w1 - w0| exceeds half the yield deformation zu / A (zu = (A / (beta +
// gamma))^(1/n)), while an unloading sub-step with gamma > beta has |w1 - w0| n |z0|^(n-1)
// (gamma - beta) > 0.5 (boucWen's rule against a second root), or when Newton fails. The force
// is taken at the end of the step: f = c1 (xd - wd1) + k1 x + f0 with wd1 = (c1 xd - alpha z1 -
// k0 w1) / c. First order in the step. dt = +infinity is a quasi-static step: no viscous
// force, and the internal branch relaxes to rest (alpha z + k0 w = 0; from the virgin state it
// stays there), so f = k1 x + f0.
//
// Tangents (physical units, fRef / uRef times): trialTangent() and algorithmicTangent() are
// both the derivative of the trial force with respect to the trial deformation at fixed dt,
// through the sub-stepped integration (exact for the discrete map while the sub-steps do not
// change): c0 c1 / (c dt) + k1 + (c1 / c) (alpha dz1/dx + k0 dw1/dx); k1 for a quasi-static
// step. initialTangent() is k1 + k0 + alpha A, the virgin stiffness when the dashpot c1 holds
// y (for K0; the viscous terms are damping, not stiffness).
//
// Virgin state: x = y = 0, z = 0, force fRef f0.
// Admissible parameters (admissible()): all finite, c0 >= 0, c1 > 0, k0 >= 0, k1 >= 0,
// alpha >= 0, A > 0, n > 0, beta + gamma > 0 (bounded z), uRef > 0, fRef > 0; f0 any finite
// value.

#include "core/hysteresis/HysteresisLaw.h"

#include <limits>

namespace hsmu {

struct MrDamperParameters {
    double c0 = 1.0;    ///< dashpot of the internal branch [normalized force s / deformation]
    double c1 = 10.0;   ///< dashpot in series (low-velocity roll-off) [same]
    double k0 = 0.0;    ///< spring of the internal branch (normalized)
    double k1 = 0.0;    ///< spring over the whole damper (normalized)
    double f0 = 0.0;    ///< force offset (normalized): Spencer's -k1 x0
    double alpha = 1.0; ///< force per unit z (normalized)
    double A = 1.0;     ///< initial slope dz/dw [-]
    double beta = 0.5;  ///< loop shape (multiplies sgn(dw z)) [-]
    double gamma = 0.5; ///< loop shape [-]
    double n = 2.0;     ///< smoothness of the transition [-]
    double uRef = 1.0;  ///< deformation reference scale (physical units), > 0
    double fRef = 1.0;  ///< force reference scale (physical units), > 0
};

/// The internal state (normalized).
struct MrDamperState {
    double w = 0.0; ///< deformation of the internal branch, x - y
    double z = 0.0; ///< hysteretic variable
};

class MrDamper final : public HysteresisLaw {
public:
    /// Throws std::invalid_argument if p is not admissible (use LawFactory for a message that
    /// names the parameter). The time increment starts unset (NaN).
    explicit MrDamper(const MrDamperParameters& p = {});

    /// Halvings of a step allowed (2^12 sub-steps).
    static constexpr int kMaxSubdivisions = 12;

    static bool admissible(const MrDamperParameters& p);
    const MrDamperParameters& parameters() const { return m_p; }
    /// Replace all parameters; the committed state (x, w, z and the committed velocity) is
    /// kept, the committed force re-evaluated and a pending trial dropped. False, and nothing
    /// changes, if p is not admissible.
    bool setParameters(const MrDamperParameters& p);
    /// Ultimate |z|: (A / (beta + gamma))^(1/n).
    static double ultimateZ(const MrDamperParameters& p);

    /// The same physical law in other reference scales (exact): with s = uRef / uRef' and
    /// c = fRef / fRef', c0, c1, k0, k1 and alpha times c / s, f0 times c, beta and gamma
    /// times s^-n (z scales as the deformation: z' = s z, w' = s w); A and n unchanged.
    static MrDamperParameters rescaled(const MrDamperParameters& p, double uRef, double fRef);

    MrDamperState committedState() const { return m_committed; }
    /// Set the committed (and trial) state, e.g. to continue a replayed model: the internal
    /// state (normalized), the deformation and the velocity of the step that reached it
    /// (physical; it enters the committed force only).
    void setCommittedState(const MrDamperState& s, double deformation, double velocity);
    MrDamperState trialState() const { return m_trial; }
    /// The velocity of the trial [physical deformation units / s]: (u - committed u) / dt
    /// (0 for a quasi-static step).
    double trialVelocity() const { return m_vTrial; }
    /// Sub-steps of the last trial (0 for a quasi-static step from rest).
    int trialSubSteps() const { return m_subSteps; }

    // HysteresisLaw
    std::string lawName() const override { return "mrDamper"; }
    bool isRateDependent() const override { return true; }
    void setTimeIncrement(double dt) override { m_dt = dt; }
    double timeIncrement() const override { return m_dt; }
    /// InvalidInput for a non-finite u or a time increment not > 0 (failureReason() says
    /// which); NoConvergence if the internal state cannot be integrated. Either way the trial
    /// is reset to the committed state.
    LawStatus setTrialDeformation(double u) override;
    std::string failureReason() const override { return m_failure; }
    double trialDeformation() const override { return m_uTrial; }
    double trialForce() const override { return m_fTrial; }
    /// After commit(), revert() or a parameter change (no trial yet): the tangent of a trial at
    /// the trial deformation with the current time increment (initialTangent() without one).
    double trialTangent() const override;
    double algorithmicTangent() const override { return trialTangent(); }
    double committedDeformation() const override { return m_uCommitted; }
    double committedForce() const override { return m_fCommitted; }
    double initialTangent() const override;
    void commit() override;
    void revert() override;
    void revertToStart() override;
    std::unique_ptr<HysteresisLaw> clone() const override;
    /// c0, c1, k0, k1, f0, alpha, A, beta, gamma, n, uRef, fRef.
    std::vector<std::string> parameterNames() const override;
    double parameterValue(int index) const override;
    int setParameterValues(std::span<const int> indices, std::span<const double> values,
                           bool allOrNothing) override;

private:
    /// The trial at u from the committed state: end state, tangent (physical), sub-steps.
    LawStatus integrateTrial(double u, MrDamperState& s, double& tangent, int& subSteps) const;
    /// Physical force at normalized x, velocity xd and internal state s.
    double forceOf(double x, double xd, const MrDamperState& s) const;
    MrDamperParameters m_p;
    double m_dt = std::numeric_limits<double>::quiet_NaN();
    MrDamperState m_committed, m_trial;
    double m_uCommitted = 0.0, m_uTrial = 0.0;
    double m_vCommitted = 0.0, m_vTrial = 0.0; // physical velocities
    double m_fCommitted = 0.0, m_fTrial = 0.0;
    double m_tangentTrial = std::numeric_limits<double>::quiet_NaN(); ///< NaN: not computed
    int m_subSteps = 0;
    std::string m_failure;
};

} // namespace hsmu
