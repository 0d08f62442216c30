#include "core/output/RunLayout.h"

#include "core/experimental/SiteStatus.h"
#include "core/structure/Link2dKinematics.h"
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
        for (ElementChannel& c : elementChannels(*e))
            layout.channels.push_back(std::move(c));
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
        if (const int k = updater->basicDof(); k >= 0) { // a link2d's basic DOF
            u.basicDof = link2dBasicDofName(k);
            u.units = {link2dBasicDeformationUnit(k), link2dBasicForceUnit(k)};
        }
        layout.updating = std::move(u);
    }
    return layout;
}

std::vector<std::string> securityOfSites(const std::vector<std::string>& sites,
                                         const SiteSecurity& given) {
    std::vector<std::string> out;
    out.reserve(sites.size());
    for (const std::string& site : sites) {
        std::string value;
        for (const auto& [name, how] : given)
            if (name == site)
                value = how;
        out.push_back(std::move(value));
    }
    return out;
}

SiteSecurity builtinSiteSecurity(const RunLayout& layout) {
    SiteSecurity out;
    for (const std::string& site : layout.sites)
        out.emplace_back(site, "builtin");
    return out;
}

} // namespace hsmu
