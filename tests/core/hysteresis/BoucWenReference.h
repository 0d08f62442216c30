#pragma once
// Independent reference for TestBoucWen: the Bouc-Wen ODE (docs/method.md, The Bouc-Wen law with
// degradation, Eqs 1-6) integrated with classical fourth-order Runge-Kutta in x, written here
// without using the BoucWen class. Between two history points x moves linearly, so sgn(dx) is
// constant over each segment and the segment is split into `subSteps` RK4 steps.

#include "core/hysteresis/BoucWen.h"

#include <cmath>
#include <vector>

namespace hsmu::testref {

inline void boucWenRates(const BoucWenParameters& p, double z, double e, double dir, double& dz,
                         double& de) {
    const double a = p.A0 - p.deltaA * e;
    const double nu = 1.0 + p.deltaNu * e;
    const double eta = 1.0 + p.deltaEta * e;
    const double s = (dir * z > 0.0) ? 1.0 : (dir * z < 0.0 ? -1.0 : 0.0);
    dz = dir * (a - std::pow(std::abs(z), p.n) * (p.beta * s + p.gamma) * nu) / eta;
    de = (1.0 - p.alpha) * p.k0 * z * dir;
}

/// Physical forces along the physical deformation history u (starting from the virgin state at
/// u = 0), using uRef / fRef of p.
inline std::vector<double> rk4Forces(const BoucWenParameters& p, const std::vector<double>& u,
                                     int subSteps) {
    std::vector<double> forces;
    forces.reserve(u.size());
    double z = 0.0, e = 0.0, xPrev = 0.0;
    for (const double ui : u) {
        const double x = ui / p.uRef;
        const double dx = x - xPrev;
        const double dir = dx > 0.0 ? 1.0 : -1.0;
        const double h = std::abs(dx) / subSteps; // integrate in |x| travelled
        for (int k = 0; k < subSteps && dx != 0.0; ++k) {
            double z1, e1, z2, e2, z3, e3, z4, e4;
            boucWenRates(p, z, e, dir, z1, e1);
            boucWenRates(p, z + 0.5 * h * z1, e + 0.5 * h * e1, dir, z2, e2);
            boucWenRates(p, z + 0.5 * h * z2, e + 0.5 * h * e2, dir, z3, e3);
            boucWenRates(p, z + h * z3, e + h * e3, dir, z4, e4);
            z += h / 6.0 * (z1 + 2.0 * z2 + 2.0 * z3 + z4);
            e += h / 6.0 * (e1 + 2.0 * e2 + 2.0 * e3 + e4);
        }
        xPrev = x;
        forces.push_back(p.fRef * p.k0 * (p.alpha * x + (1.0 - p.alpha) * z));
    }
    return forces;
}

} // namespace hsmu::testref
