#pragma once
// Alpha operator-splitting (Combescure & Pegon 1997; Nakashima et al. 1990), the
// pseudo-dynamic standard: HHT-alpha with the restoring force split into the measured
// force at an explicit predictor plus an initial-stiffness correction.
//
//   beta = (1 - alpha)^2 / 4,  gamma = (1 - 2 alpha) / 2,  -1/3 <= alpha <= 0
//   u~[n+1] = u[n] + dt v[n] + dt^2 (1/2 - beta) a[n]          (predict; to specimen)
//   v~[n+1] = v[n] + dt (1 - gamma) a[n]
//   R[n+1] ~= R~[n+1] + K_I (u[n+1] - u~[n+1]),  u[n+1] = u~[n+1] + beta dt^2 a[n+1]
//   M a[n+1] + (1+alpha) (C v[n+1] + R[n+1]) - alpha (C v[n] + R[n]) = (1+alpha) F[n+1] - alpha F[n]
//
// so that  [M + (1+alpha)(gamma dt C + beta dt^2 K_I)] a[n+1] =
//   (1+alpha) (F[n+1] - C v~[n+1] - R~[n+1]) - alpha (F[n] - C v[n] - R[n]).
// K_I is the initial stiffness. Unconditionally stable for linear and softening systems;
// for a linear system with K_I = K it is exactly HHT-alpha.
// Cost per step O(non-zeros of K_I and C): the left-hand side is a sparse matrix factored once
// in initialize() (LeftHandSide.h), the products C v and K_I du are sparse.

#include "core/integration/Integrator.h"

#include "core/integration/LeftHandSide.h"
#include "core/integration/StepMatrix.h"

namespace hsmu {

class AlphaOS final : public Integrator {
public:
    /// alpha in [-1/3, 0]; throws std::invalid_argument otherwise.
    explicit AlphaOS(double alpha = -0.05);
    std::string name() const override { return "alphaOS"; }
    bool isExplicit() const override { return false; }
    double stabilityLimit() const override;
    void initialize(const Structure& s, double dt, const Eigen::VectorXd& u0,
                    const Eigen::VectorXd& v0, double ag0, const Eigen::VectorXd& r0) override;
    Eigen::VectorXd predict() const override;
    bool correct(const Eigen::VectorXd& rTrial, double agNext) override;
    double alpha() const { return m_alpha; }
    void snapshot(Snapshot& into) const override
    {
        Integrator::snapshot(into);
        into.extra = m_fPrev;
    }
    void restore(const Snapshot& s) override
    {
        Integrator::restore(s);
        m_fPrev = s.extra;
    }

private:
    double m_alpha, m_beta, m_gamma;
    LeftHandSide m_lhs;
    StepMatrix m_c, m_k; // C, K_I
    Eigen::VectorXd m_fPrev; // F[n] - C v[n] - R[n] of the accepted step
};

} // namespace hsmu
