#pragma once
// Shared by the integration tests: linear structures built from elastic springs, the step
// loop of HybridTest reduced to its numerical core (predict, Structure::setTrial,
// restoringForce, correct, commit), and closed-form SDOF responses.
// Units: kN, m, s, t.

#include "core/hysteresis/LinearElastic.h"
#include "core/integration/Integrator.h"
#include "core/structure/SpringElement.h"
#include "core/structure/Structure.h"

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace hsmu::testing {

/// SDOF: mass m [t] on an elastic lateral spring k [kN/m]; mass-proportional damping
/// c = 2 zeta omega m exactly (a0 = 2 zeta omega, a1 = 0).
inline std::unique_ptr<Structure> makeSdof(double m, double k, double zeta) {
    auto s = std::make_unique<Structure>();
    s->addDof("DOF 1", m);
    s->addElement(SpringElement::lateral("spring", 0, std::make_unique<LinearElastic>(k)));
    s->setRayleigh({2.0 * zeta * std::sqrt(k / m), 0.0});
    s->finalize();
    return s;
}

/// 2-DOF chain: lateral springs k1, k2 and a truss k3 between the masses.
inline std::unique_ptr<Structure> makeChain(double m1, double m2, double k1, double k2, double k3,
                                            double zeta) {
    auto s = std::make_unique<Structure>();
    s->addDof("DOF 1", m1);
    s->addDof("DOF 2", m2);
    s->addElement(SpringElement::lateral("k1", 0, std::make_unique<LinearElastic>(k1)));
    s->addElement(SpringElement::lateral("k2", 1, std::make_unique<LinearElastic>(k2)));
    s->addElement(SpringElement::truss("k3", 0, 1, std::make_unique<LinearElastic>(k3)));
    if (zeta > 0.0)
        s->setModalDamping(zeta, 1, 2);
    s->finalize();
    return s;
}

/// Free-DOF displacement history u[n] (n = 0..steps) of integrator `in` on structure `s`
/// from u0, v0 under ground acceleration ag(t). Stops early (shorter history) if correct()
/// refuses a step.
inline std::vector<Eigen::VectorXd> run(Structure& s, Integrator& in, double dt, int steps,
                                        const Eigen::VectorXd& u0, const Eigen::VectorXd& v0,
                                        const std::function<double(double)>& ag = {}) {
    auto accel = [&](int n) { return ag ? ag(n * dt) : 0.0; };
    s.setTrial(u0);
    const Eigen::VectorXd r0 = s.restoringForce();
    s.commit();
    in.initialize(s, dt, u0, v0, accel(0), r0);
    std::vector<Eigen::VectorXd> u{in.displacement()};
    for (int n = 0; n < steps; ++n) {
        s.setTrial(in.predict());
        if (!in.correct(s.restoringForce(), accel(n + 1)))
            break;
        s.commit();
        u.push_back(in.displacement());
    }
    return u;
}

inline std::vector<Eigen::VectorXd> run(Structure& s, Integrator& in, double dt, int steps,
                                        double u0, double v0 = 0.0) {
    return run(s, in, dt, steps, Eigen::VectorXd::Constant(1, u0),
               Eigen::VectorXd::Constant(1, v0));
}

/// Damped free vibration of m u'' + c u' + k u = 0 (zeta < 1) from u0, v0.
inline double freeVibration(double omega, double zeta, double u0, double v0, double t) {
    const double wd = omega * std::sqrt(1.0 - zeta * zeta);
    return std::exp(-zeta * omega * t) *
           (u0 * std::cos(wd * t) + (v0 + zeta * omega * u0) / wd * std::sin(wd * t));
}

/// u'' + 2 zeta omega u' + omega^2 u = -A sin(W t) from rest (u(0) = u'(0) = 0):
/// steady state u_p = P [(w^2 - W^2) sin Wt - 2 zeta w W cos Wt] / D with P = -A,
/// D = (w^2 - W^2)^2 + (2 zeta w W)^2, plus the transient that cancels u_p(0) and u_p'(0).
inline double harmonicFromRest(double omega, double zeta, double amp, double bigW, double t) {
    const double p = -amp;
    const double d =
        std::pow(omega * omega - bigW * bigW, 2) + std::pow(2 * zeta * omega * bigW, 2);
    const double c1 = p * (omega * omega - bigW * bigW) / d; // sin coefficient
    const double c2 = -p * 2.0 * zeta * omega * bigW / d;    // cos coefficient
    const double wd = omega * std::sqrt(1.0 - zeta * zeta);
    const double b1 = -c2;
    const double b2 = (zeta * omega * b1 - c1 * bigW) / wd;
    return c1 * std::sin(bigW * t) + c2 * std::cos(bigW * t) +
           std::exp(-zeta * omega * t) * (b1 * std::cos(wd * t) + b2 * std::sin(wd * t));
}

/// max_n |u[n](0) - exact(n dt)|.
inline double maxError(const std::vector<Eigen::VectorXd>& u, double dt,
                       const std::function<double(double)>& exact) {
    double e = 0.0;
    for (std::size_t n = 0; n < u.size(); ++n)
        e = std::max(e, std::abs(u[n][0] - exact(static_cast<double>(n) * dt)));
    return e;
}

/// max_n |u[n]|_inf.
inline double peak(const std::vector<Eigen::VectorXd>& u) {
    double p = 0.0;
    for (const auto& x : u)
        p = std::max(p, x.cwiseAbs().maxCoeff());
    return p;
}

} // namespace hsmu::testing
