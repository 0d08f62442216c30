#pragma once
// StabilityCheck: omega_max dt of the initial-stiffness model against an integrator's limit
// (docs/method.md, Hybrid simulation: explicit Newmark needs omega_max dt <= 2).

#include <string>

namespace hsmu {

class Integrator;
class Structure;

struct StabilityReport {
    double omegaMax = 0.0;  ///< largest undamped circular frequency of (K0, M) [rad/s]
    double omegaDt = 0.0;   ///< omega_max dt [-]
    double limit = 0.0;     ///< the scheme's limit on omega dt [-] (inf if unconditional)
    double maxStableDt = 0.0; ///< limit / omega_max [s]
    bool stable = true;
    std::string message;    ///< one sentence for the operator
};

/// Requires s.finalize() to have run.
StabilityReport checkStability(const Structure& s, const Integrator& integrator, double dt);

} // namespace hsmu
