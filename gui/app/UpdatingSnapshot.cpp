#include "gui/app/UpdatingSnapshot.h"

#include "core/hysteresis/HysteresisLaw.h"
#include "core/output/ElementUnits.h"
#include "core/structure/Element.h"
#include "core/structure/Link2dKinematics.h"
#include "core/structure/Structure.h"
#include "core/experiment/HybridTest.h"
#include "core/updating/ModelUpdater.h"

#include <cmath>

namespace hsmu::gui {

const ParameterState* UpdatingSnapshot::parameter(const std::string& name) const {
    for (const ParameterState& p : parameters)
        if (p.name == name)
            return &p;
    return nullptr;
}

bool UpdatingSnapshot::stale(const UpdateProposal& p) const {
    return Reporter::stale(p, time, proposalInterval);
}

UpdatingSnapshot snapshotOf(const HybridTest& test) {
    UpdatingSnapshot s;
    s.step = test.currentStep();
    s.time = test.time();
    const ModelUpdater* u = test.updater();
    if (!u)
        return s;
    s.enabled = true;
    const Identifier& id = u->identifier();
    s.specimen = u->specimenElement();
    s.method = id.methodName();
    for (std::size_t k = 0; k < id.layout().size(); ++k) {
        ParameterState p;
        p.name = id.layout().name(k);
        p.value = id.estimate()[k];
        p.sigma = id.standardDeviation()[k];
        if (!std::isnan(id.bounds()[k].lower))
            p.bounds = id.bounds()[k];
        p.locked = id.locked(k);
        s.parameters.push_back(p);
    }
    s.canLock = id.canLock();
    const Reporter& r = u->reporter();
    s.pending.assign(r.pending().begin(), r.pending().end());
    s.proposalInterval = r.proposalInterval();
    for (const ReporterTarget& t : r.targets())
        if (const auto v = r.latestOffer(t.element); !v.empty())
            s.latest[t.element].assign(v.begin(), v.end());
    for (const ReporterTarget& t : r.targets()) {
        const Element* e = test.structure().element(t.element);
        const HysteresisLaw* law = reporterTargetLaw(e, t.basicDof);
        ParameterValues& values = s.targets[t.element];
        if (law)
            for (const std::string& name : t.parameters)
                if (const int i = law->parameterIndex(name); i >= 0)
                    values[name] = law->parameterValue(i);
    }
    s.policy = r.policy();
    s.everyN = r.everyN();
    s.fitError = u->inspector().fitError();
    s.fitThreshold = u->inspector().settings().threshold;
    s.appliedUpdates = r.appliedCount();
    s.notQueued = r.notQueuedCount();
    s.maxPending = r.maxPending();
    if (const OffsetProposal* p = u->pendingOffsets())
        s.offsets = *p;
    if (const Element* e = test.structure().element(s.specimen)) {
        const ElementUnits units = elementUnits(e->typeName());
        s.deformationUnit = units.deformation;
        s.forceUnit = units.force;
    }
    if (const int k = u->basicDof(); k >= 0) { // a link2d's identified basic DOF
        s.deformationUnit = link2dBasicDeformationUnit(k);
        s.forceUnit = link2dBasicForceUnit(k);
    }
    return s;
}

} // namespace hsmu::gui
