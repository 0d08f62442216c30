#include "gui/app/UpdatingSnapshot.h"

#include "core/hysteresis/HysteresisLaw.h"
#include "core/structure/Element.h"
#include "core/structure/Structure.h"
#include "core/experiment/HybridTest.h"
#include "core/updating/ModelUpdater.h"

namespace hsmu::gui {

const ParameterState* UpdatingSnapshot::parameter(const std::string& name) const {
    for (const ParameterState& p : parameters)
        if (p.name == name)
            return &p;
    return nullptr;
}

UpdatingSnapshot snapshotOf(const HybridTest& test) {
    UpdatingSnapshot s;
    s.step = test.currentStep();
    const ModelUpdater* u = test.updater();
    if (!u)
        return s;
    s.enabled = true;
    const Identifier& id = u->identifier();
    s.specimen = u->specimenElement();
    s.method = id.methodName();
    const ParameterValues estimate = id.estimate();
    const ParameterValues sigma = id.standardDeviation();
    const ParameterBoundsMap& bounds = id.bounds();
    for (const std::string& name : id.parameterNames()) {
        ParameterState p;
        p.name = name;
        if (auto it = estimate.find(name); it != estimate.end())
            p.value = it->second;
        if (auto it = sigma.find(name); it != sigma.end())
            p.sigma = it->second;
        if (auto it = bounds.find(name); it != bounds.end())
            p.bounds = it->second;
        p.locked = id.locked(name);
        s.parameters.push_back(p);
    }
    s.canLock = id.canLock();
    const Reporter& r = u->reporter();
    s.pending.assign(r.pending().begin(), r.pending().end());
    for (const ReporterTarget& t : r.targets()) {
        const Element* e = test.structure().element(t.element);
        const HysteresisLaw* law = e ? e->law() : nullptr;
        ParameterValues& values = s.targets[t.element];
        if (law)
            for (const std::string& name : t.parameters)
                if (auto v = law->parameter(name))
                    values[name] = *v;
    }
    s.policy = r.policy();
    s.everyN = r.everyN();
    s.fitError = u->inspector().fitError();
    s.fitThreshold = u->inspector().settings().threshold;
    s.appliedUpdates = r.appliedCount();
    s.notQueued = r.notQueuedCount();
    s.maxPending = r.maxPending();
    return s;
}

} // namespace hsmu::gui
