#pragma once
// Explicit Newmark (beta = 0, gamma = 1/2), the paper's scheme (docs/method.md, Hybrid
// simulation):
//
//   u[n+1] = u[n] + dt v[n] + dt^2/2 a[n]                              (predict; to specimen)
//   (M + gamma dt C) a[n+1] = F[n+1] - R[n+1] - C (v[n] + (1-gamma) dt a[n])
//   v[n+1] = v[n] + dt ((1-gamma) a[n] + gamma a[n+1])
//
// Conditionally stable: omega_max dt <= 2 (undamped); second-order accurate.
// Cost per step O(non-zeros of C): M is lumped (diagonal), so with mass-proportional damping
// M + gamma dt C is diagonal and needs no solve; otherwise its sparse LDL^T is computed once
// in initialize() (LeftHandSide.h).

#include "core/integration/Integrator.h"

#include "core/integration/LeftHandSide.h"
#include "core/integration/StepMatrix.h"

namespace hsmu {

class ExplicitNewmark final : public Integrator {
public:
    std::string name() const override { return "explicitNewmark"; }
    bool isExplicit() const override { return true; }
    double stabilityLimit() const override { return 2.0; }
    void initialize(const Structure& s, double dt, const Eigen::VectorXd& u0,
                    const Eigen::VectorXd& v0, double ag0, const Eigen::VectorXd& r0) override;
    Eigen::VectorXd predict() const override;
    void predictInto(Eigen::VectorXd& out) const override;
    bool correct(const Eigen::VectorXd& rTrial, double agNext) override;

private:
    static constexpr double kGamma = 0.5;
    LeftHandSide m_lhs; // M + gamma dt C, factored once
    StepMatrix m_c;     // C
    // correct()'s intermediate vectors, kept so that a step allocates nothing (issue 27).
    Eigen::VectorXd m_vHalf, m_cv, m_rhs, m_aNext;
};

} // namespace hsmu
