#include "gui/app/PreflightReport.h"

#include "core/experimental/ExperimentalElement.h"
#include "core/experimental/ExperimentalLink2d.h"
#include "core/integration/Integrator.h"
#include "core/output/ElementUnits.h"
#include "core/structure/Structure.h"
#include "core/experiment/HybridTest.h"

#include <limits>

namespace hsmu::gui {

PreflightReport preflightOf(const HybridTest& test, bool allowUnstable) {
    PreflightReport r;
    r.integrator = test.integrator().name();
    r.dt = test.dt();
    r.totalSteps = test.totalSteps();
    r.stability = test.stability();
    r.allowUnstable = allowUnstable;
    r.groundMotion = test.groundMotion().name;
    r.pga = test.groundMotion().pga();
    for (const auto& e : test.structure().elements()) {
        auto* x = dynamic_cast<ExperimentalElement*>(e.get()); // control() is non-const
        if (!x)
            continue;
        SpecimenPreflight s;
        s.element = x->name();
        s.control = x->control().description();
        const ElementUnits units = elementUnits(x->typeName());
        s.deformationUnit = units.deformation;
        s.forceUnit = units.force;
        s.limits = x->limits();
        s.measuredDeformation = x->measurement().deformation;
        s.measuredForce = x->measurement().force;
        if (const auto h = x->control().priorLoading(); h && h->committedSteps > 0) {
            // Nothing was measured yet: it stands where its last committed step left it.
            s.committedSteps = h->committedSteps;
            s.lastDeformation = h->lastDeformation;
            s.measuredDeformation = h->lastDeformation;
            s.measuredForce = std::numeric_limits<double>::quiet_NaN();
        }
        if (const auto* link = dynamic_cast<const ExperimentalLink2d*>(x))
            s.actuatorLimits = actuatorLimitLines(link->channels(), test.totalSteps() * test.dt());
        r.specimens.push_back(s);
    }
    return r;
}

} // namespace hsmu::gui
