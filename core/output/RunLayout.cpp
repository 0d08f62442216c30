#include "core/output/RunLayout.h"

#include "core/structure/Structure.h"

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
    return layout;
}

} // namespace hsmu
