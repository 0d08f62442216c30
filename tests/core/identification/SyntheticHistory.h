#pragma once
// Synthetic specimen histories for the identification tests: a cyclic deformation and the
// force a law gives along it.

#include "core/hysteresis/HysteresisLaw.h"

#include <cmath>
#include <vector>

namespace hsmu::testing {

/// Cyclic deformation with an amplitude growing linearly to `peak` over `cycles` cycles.
inline std::vector<double> cyclic(double peak, int cycles, int pointsPerCycle) {
    std::vector<double> u;
    for (int k = 1; k <= cycles * pointsPerCycle; ++k) {
        const double c = double(k) / pointsPerCycle;
        u.push_back(peak * c / cycles * std::sin(2.0 * M_PI * c));
    }
    return u;
}

/// The committed force of `law` after each deformation of u, from its current state.
inline std::vector<double> forcesOf(HysteresisLaw& law, const std::vector<double>& u) {
    std::vector<double> f;
    for (const double v : u) {
        law.setTrialDeformation(v);
        law.commit();
        f.push_back(law.committedForce());
    }
    return f;
}

} // namespace hsmu::testing
