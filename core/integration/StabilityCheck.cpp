#include "core/integration/StabilityCheck.h"

#include "core/integration/Integrator.h"
#include "core/structure/Structure.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace hsmu {

StabilityReport checkStability(const Structure& s, const Integrator& integrator, double dt)
{
    StabilityReport r;
    r.omegaMax = s.maxFrequency();
    r.omegaDt = r.omegaMax * dt;
    r.limit = integrator.stabilityLimit();
    r.maxStableDt = r.omegaMax > 0.0 ? r.limit / r.omegaMax
                                     : std::numeric_limits<double>::infinity();
    r.stable = !integrator.isExplicit() || r.omegaDt <= r.limit;
    char buf[256];
    if (r.stable)
        std::snprintf(buf, sizeof buf,
                      "%s: omega_max dt = %.4g (omega_max = %.4g rad/s, dt = %.4g s) within "
                      "the limit %.4g",
                      integrator.name().c_str(), r.omegaDt, r.omegaMax, dt, r.limit);
    else
        std::snprintf(buf, sizeof buf,
                      "%s is unstable for this model: omega_max dt = %.4g exceeds %.4g "
                      "(omega_max = %.4g rad/s, dt = %.4g s); use dt <= %.4g s or the alphaOS "
                      "integrator",
                      integrator.name().c_str(), r.omegaDt, r.limit, r.omegaMax, dt,
                      r.maxStableDt);
    r.message = buf;
    return r;
}

} // namespace hsmu
