#include "core/experiment/ElementChannels.h"

#include "core/experimental/ExperimentalLink2d.h"
#include "core/structure/Link2dElement.h"

namespace hsmu {

std::vector<ElementChannel> elementChannels(const Element& e) {
    std::vector<ElementChannel> out;
    const std::string& n = e.name();
    if (const auto* x = dynamic_cast<const ExperimentalLink2d*>(&e)) {
        for (int k = 0; k < 3; ++k) {
            const std::string b = link2dBasicDofName(k);
            out.push_back({n, b + " commanded", link2dBasicDeformationUnit(k)});
            out.push_back({n, b + " deformation", link2dBasicDeformationUnit(k)});
            out.push_back({n, b + " force", link2dBasicForceUnit(k)});
        }
        for (const ActuatorChannelSpec& c : x->channels()) {
            out.push_back({n, c.name + " command", c.mode == ActuatorMode::Force ? "kN" : "m"});
            out.push_back({n, c.name + " stroke", "m"});
            out.push_back({n, c.name + " force", "kN"});
        }
    } else if (dynamic_cast<const Link2dElement*>(&e)) {
        for (int k = 0; k < 3; ++k) {
            const std::string b = link2dBasicDofName(k);
            out.push_back({n, b + " deformation", link2dBasicDeformationUnit(k)});
            out.push_back({n, b + " force", link2dBasicForceUnit(k)});
        }
    }
    return out;
}

void appendChannelValues(const Element& e, std::vector<double>& out) {
    if (const auto* x = dynamic_cast<const ExperimentalLink2d*>(&e)) {
        for (int k = 0; k < 3; ++k) {
            out.push_back(x->commandedBasic()[k]);
            out.push_back(x->basicDeformations()[k]);
            out.push_back(x->basicForces()[k]);
        }
        for (Eigen::Index a = 0; a < x->commands().size(); ++a) {
            out.push_back(x->commands()[a]);
            out.push_back(x->strokes()[a]);
            out.push_back(x->actuatorForces()[a]);
        }
    } else if (const auto* l = dynamic_cast<const Link2dElement*>(&e)) {
        for (int k = 0; k < 3; ++k) {
            out.push_back(l->basicDeformations()[k]);
            out.push_back(l->basicForces()[k]);
        }
    }
}

} // namespace hsmu
