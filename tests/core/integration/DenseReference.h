#pragma once
// The dense path the sparse structure replaced (issue 17), kept as the tests' reference:
// T, M, K0 and C as dense matrices assembled as Structure::finalize() did before (K_full from
// the elements' DofTerms, K0 = T^T K_full T, a dense generalized eigen-solve for modal
// Rayleigh damping) and the integrators solving a dense LDL^T every step.
// Units: those of the Structure (kN, m, s, t).

#include "core/config/TestConfig.h"
#include "core/integration/Integrator.h"
#include "core/structure/Structure.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <memory>
#include <string>

namespace hsmu::testing {

struct DenseModel {
    Eigen::MatrixXd t, m, k0, c;
    Eigen::VectorXd omega;
    RayleighDamping rayleigh;
};

/// The old assembly over a finalized structure, with the configuration's damping spec.
inline DenseModel denseModel(const Structure& s, const DampingSpec& damping) {
    DenseModel d;
    d.t = Eigen::MatrixXd(s.transform());
    const int n = s.fullDofCount();
    Eigen::MatrixXd kFull = Eigen::MatrixXd::Zero(n, n);
    for (const auto& e : s.elements()) {
        if (e->typeName() == "link2d" || e->typeName() == "experimentalLink2d") {
            // multi-DOF (A^T Kb A, eq. L2): its own dense block over the full DOFs
            std::vector<Eigen::Triplet<double>> tr;
            std::vector<int> identity(n);
            for (int i = 0; i < n; ++i)
                identity[i] = i;
            e->addInitialStiffness(tr, identity);
            for (const auto& t : tr)
                kFull(t.row(), t.col()) += t.value();
            continue;
        }
        const double k = e->initialGeneralizedStiffness();
        for (const auto& a : e->terms())
            for (const auto& b : e->terms())
                kFull(a.dof, b.dof) += a.coefficient * b.coefficient * k;
    }
    d.k0 = d.t.transpose() * kFull * d.t;
    d.m = Eigen::MatrixXd(s.massDiagonal().asDiagonal());
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(d.k0, d.m);
    d.omega = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    if (damping.kind == DampingSpec::Kind::ModalRatio) {
        const int nf = int(d.omega.size());
        const double w1 = d.omega[std::clamp(damping.modeI, 1, nf) - 1];
        const double w2 = d.omega[std::clamp(damping.modeJ, 1, nf) - 1];
        d.rayleigh = RayleighDamping::fromRatio(damping.ratio, w1, w2);
    } else if (damping.kind == DampingSpec::Kind::Coefficients) {
        d.rayleigh = {damping.a0, damping.a1};
    }
    d.c = d.rayleigh.a0 * d.m + d.rayleigh.a1 * d.k0;
    return d;
}

/// Explicit Newmark as before issue 17 (dense LDL^T of M + gamma dt C).
class DenseExplicitNewmark final : public Integrator {
public:
    explicit DenseExplicitNewmark(DampingSpec damping) : m_damping(damping) {}
    std::string name() const override { return "explicitNewmark"; }
    bool isExplicit() const override { return true; }
    double stabilityLimit() const override { return 2.0; }
    void initialize(const Structure& s, double dt, const Eigen::VectorXd& u0,
                    const Eigen::VectorXd& v0, double ag0, const Eigen::VectorXd& r0) override {
        m_d = denseModel(s, m_damping);
        m_s = &s;
        m_dt = dt;
        m_u = u0;
        m_v = v0;
        m_a = m_d.m.ldlt().solve(-s.influence() * ag0 - m_d.c * v0 - r0);
        m_lhs.compute(m_d.m + 0.5 * dt * m_d.c);
    }
    Eigen::VectorXd predict() const override { return m_u + m_dt * m_v + 0.5 * m_dt * m_dt * m_a; }
    bool correct(const Eigen::VectorXd& rTrial, double agNext) override {
        const Eigen::VectorXd vHalf = m_v + 0.5 * m_dt * m_a;
        const Eigen::VectorXd rhs = -m_s->influence() * agNext - rTrial - m_d.c * vHalf;
        const Eigen::VectorXd aNext = m_lhs.solve(rhs);
        if (!aNext.allFinite())
            return false;
        m_u = predict();
        m_v = vHalf + 0.5 * m_dt * aNext;
        m_a = aNext;
        return true;
    }

private:
    DampingSpec m_damping;
    DenseModel m_d;
    Eigen::LDLT<Eigen::MatrixXd> m_lhs;
};

/// Alpha-OS as before issue 17 (dense LDL^T, dense C and K_I products).
class DenseAlphaOS final : public Integrator {
public:
    DenseAlphaOS(DampingSpec damping, double alpha)
        : m_damping(damping), m_alpha(alpha), m_beta((1.0 - alpha) * (1.0 - alpha) / 4.0),
          m_gamma((1.0 - 2.0 * alpha) / 2.0) {}
    std::string name() const override { return "alphaOS"; }
    bool isExplicit() const override { return false; }
    double stabilityLimit() const override { return std::numeric_limits<double>::infinity(); }
    void initialize(const Structure& s, double dt, const Eigen::VectorXd& u0,
                    const Eigen::VectorXd& v0, double ag0, const Eigen::VectorXd& r0) override {
        m_d = denseModel(s, m_damping);
        m_s = &s;
        m_dt = dt;
        m_u = u0;
        m_v = v0;
        m_a = m_d.m.ldlt().solve(-s.influence() * ag0 - m_d.c * v0 - r0);
        const double c = 1.0 + m_alpha;
        m_lhs.compute(m_d.m + c * (m_gamma * dt * m_d.c + m_beta * dt * dt * m_d.k0));
        m_fPrev = -s.influence() * ag0 - m_d.c * v0 - r0;
    }
    Eigen::VectorXd predict() const override {
        return m_u + m_dt * m_v + m_dt * m_dt * (0.5 - m_beta) * m_a;
    }
    bool correct(const Eigen::VectorXd& rTrial, double agNext) override {
        const Eigen::VectorXd uTilde = predict();
        const Eigen::VectorXd vTilde = m_v + m_dt * (1.0 - m_gamma) * m_a;
        const Eigen::VectorXd fTilde = -m_s->influence() * agNext - m_d.c * vTilde - rTrial;
        const Eigen::VectorXd aNext = m_lhs.solve((1.0 + m_alpha) * fTilde - m_alpha * m_fPrev);
        if (!aNext.allFinite())
            return false;
        m_u = uTilde + m_beta * m_dt * m_dt * aNext;
        m_v = vTilde + m_gamma * m_dt * aNext;
        m_a = aNext;
        const Eigen::VectorXd rNext = rTrial + m_d.k0 * (m_u - uTilde);
        m_fPrev = -m_s->influence() * agNext - m_d.c * m_v - rNext;
        return true;
    }
    void snapshot(Snapshot& into) const override {
        Integrator::snapshot(into);
        into.extra = m_fPrev;
    }
    void restore(const Snapshot& s) override {
        Integrator::restore(s);
        m_fPrev = s.extra;
    }

private:
    DampingSpec m_damping;
    double m_alpha, m_beta, m_gamma;
    DenseModel m_d;
    Eigen::LDLT<Eigen::MatrixXd> m_lhs;
    Eigen::VectorXd m_fPrev;
};

} // namespace hsmu::testing
