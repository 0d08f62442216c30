#include "core/output/RunLayout.h"

#include "core/experimental/SiteStatus.h"
#include "core/structure/Structure.h"
#include "core/experiment/HybridTest.h"
#include "core/updating/ModelUpdater.h"

namespace hsmu {

RunLayout RunLayout::of(const Structure& structure) {
    RunLayout layout;
    layout.dofNames = structure.dofNames();
    for (const auto& e : structure.elements()) {
        ElementInfo info;
        info.name = e->name();
        info.type = e->typeName();
        info.experimental = e->isExperimental();
        const HysteresisLaw* law = e->law();
        info.nonlinear = info.experimental || (law && law->lawName() != "elastic");
        info.units = elementUnits(info.type);
        layout.elements.push_back(std::move(info));
    }
    layout.sites = siteNames(structure);
    return layout;
}

RunLayout RunLayout::of(const HybridTest& test) {
    RunLayout layout = of(test.structure());
    if (const ModelUpdater* updater = test.updater()) {
        UpdatingInfo u;
        u.specimen = updater->specimenElement();
        u.method = updater->identifier().methodName();
        u.parameters = updater->parameterNames();
        u.units = elementUnits("");
        for (const ElementInfo& e : layout.elements)
            if (e.name == u.specimen)
                u.units = e.units;
        layout.updating = std::move(u);
    }
    return layout;
}

} // namespace hsmu
