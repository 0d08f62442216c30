#pragma once
// Bouc-Wen-Baber-Noori hysteresis with pinching (docs/hysteresis-laws.md): the law of
// BoucWen.h (same convention, same normalization by uRef / fRef, same 9 parameters) with
// Eq. 2 multiplied by the pinching function of Foliente (1995):
//
//   dz/dx = h(z) [ A - |z|^n (beta sgn(dx z) + gamma) nu ] / eta                       (P1)
//   h(z)  = 1 - zeta1 exp( -(z sgn(dx) - q zu)^2 / zeta2^2 )                            (P2)
//   zeta1 = zetaS (1 - exp(-p e)),  zeta2 = (psi + deltaPsi e) (lambda + zeta1)         (P3)
//   zu    = ( A / (nu (beta + gamma)) )^(1/n)                                           (P4)
//
// with F, e, A, nu, eta as in BoucWen.h (Eqs 1, 3-6). zeta1 is the pinching severity (grows
// from 0 with the dissipated energy e towards zetaS), zeta2 the width of the pinched zone, q
// the fraction of the ultimate z around which z sgn(dx) is pinched. With zetaS = 0 (or before
// any energy is dissipated) h = 1 and the law is BoucWen.
//
// Integration over an increment from the committed (z0, e0): backward Euler in z and e as in
// BoucWen.h (same Newton, tolerances, step limits and sub-stepping up to 2^12 sub-steps), with
// the pinching quantities zeta1, zeta2 and zu evaluated at the energy e0 at the start of each
// sub-step (first order, like the rest of the step); z in h(z) is implicit. A sub-step whose
// zeta1 is 0 is exactly BoucWen's step (bit for bit). While zeta1 > 0 an increment is also
// halved until |dx| A / eta <= zeta2 (z moves at most one width of the pinched zone per
// sub-step). Failure is LawStatus::NoConvergence and leaves the committed state untouched.
//
// Tangent (physical units): fRef / uRef * k0 [alpha + (1 - alpha) dz/dx] with dz/dx of P1 at
// the end state.
//
// Admissible parameters: those of BoucWen::admissible() and 0 <= zetaS < 1 (h > 0), p >= 0,
// 0 <= q < 1, psi > 0, deltaPsi >= 0, lambda > 0, all finite.

#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/HysteresisLaw.h"

#include <span>

namespace hsmu {

/// The pinching parameters of P2-P3 (normalized units, like BoucWenParameters).
struct PinchingParameters {
    double zetaS = 0.8;    ///< pinching severity reached with energy, in [0, 1) [-]
    double p = 1.0;        ///< rate of that growth with the normalized energy e [-]
    double q = 0.1;        ///< pinched z sgn(dx) as a fraction of zu, in [0, 1) [-]
    double psi = 0.2;      ///< width of the pinched zone [-], > 0
    double deltaPsi = 0.0; ///< growth of that width with e, >= 0
    double lambda = 0.5;   ///< width coupling with zeta1 [-], > 0
};

struct BoucWenPinchingParameters {
    BoucWenParameters boucWen;
    PinchingParameters pinching;
};

class BoucWenPinching final : public HysteresisLaw {
public:
    /// Throws std::invalid_argument if p is not admissible (LawFactory names the parameter).
    explicit BoucWenPinching(const BoucWenPinchingParameters& p = {});

    /// Integrate over the normalized increment dx from `from` (pure function). InvalidInput if
    /// dx or `from` is not finite or p is not admissible; NoConvergence if even
    /// maxSubdivisions halvings fail. On failure `state` is `from` and subSteps is 0. dzdx is
    /// P1 at the end state in the direction of dx (+1 for dx == 0).
    static BoucWenIncrement integrate(const BoucWenPinchingParameters& p, const BoucWenState& from,
                                      double dx,
                                      int maxSubdivisions = BoucWen::kDefaultMaxSubdivisions);
    static bool admissible(const BoucWenPinchingParameters& p);
    /// h(z) of P2 at the state s for motion in direction dir (+1 / -1).
    static double pinchingFactor(const BoucWenPinchingParameters& p, const BoucWenState& s,
                                 double dir);

    const BoucWenPinchingParameters& parameters() const { return m_p; }
    /// As BoucWen::setParameters: false, and nothing changes, if p is not admissible.
    bool setParameters(const BoucWenPinchingParameters& p);

    BoucWenState committedState() const { return m_committed; }
    /// Sets the committed state (z, e) at the committed deformation (physical units), e.g. a
    /// state replayed elsewhere; the trial is reset to it.
    void setCommittedState(const BoucWenState& s, double committedDeformation);
    BoucWenState trialState() const { return m_trial; }

    std::string lawName() const override { return "boucWenPinching"; }
    LawStatus setTrialDeformation(double u) override;
    double trialDeformation() const override { return m_uTrial; }
    double trialForce() const override { return m_fTrial; }
    double trialTangent() const override { return tangentOf(m_trial, m_dirTrial); }
    double committedDeformation() const override { return m_uCommitted; }
    double committedForce() const override { return m_fCommitted; }
    double initialTangent() const override;
    void commit() override;
    void revert() override;
    void revertToStart() override;
    std::unique_ptr<HysteresisLaw> clone() const override;
    /// k0, alpha, n, beta, gamma, A0, deltaA, deltaNu, deltaEta, uRef, fRef (BoucWen's, at the
    /// same indices), then zetaS, p, q, psi, deltaPsi, lambda.
    std::vector<std::string> parameterNames() const override;
    double parameterValue(int index) const override;
    /// As BoucWen's: with allOrNothing the values are judged together as one set.
    int setParameterValues(std::span<const int> indices, std::span<const double> values,
                           bool allOrNothing) override;

private:
    double forceOf(double x, const BoucWenState& s) const;
    double tangentOf(const BoucWenState& s, double dir) const;
    BoucWenPinchingParameters m_p;
    BoucWenState m_committed, m_trial;
    double m_uCommitted = 0.0, m_uTrial = 0.0;
    double m_fCommitted = 0.0, m_fTrial = 0.0;
    double m_dirCommitted = 1.0, m_dirTrial = 1.0;
};

/// The same physical pinching model in the scales (uRef, fRef): the Bouc-Wen part as
/// rescaled(); with s = p.uRef / uRef and c = p.fRef / fRef, z scales by s and e by c s, so
/// the pinched zone's width psi s, deltaPsi / c, the energy rate p / (c s); zetaS, q, lambda
/// unchanged (Eqs P2-P4, docs/hysteresis-laws.md).
BoucWenPinchingParameters rescaled(const BoucWenPinchingParameters& p, double uRef, double fRef);

} // namespace hsmu
