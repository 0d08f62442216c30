#include "gui/plots/PlotReferences.h"

#include "core/config/ConfigLoader.h"

#include <exception>

namespace hsmu::gui {

PlotReferences PlotReferences::of(const TestConfig& cfg) {
    PlotReferences r;
    for (const ElementSpec& e : cfg.elements)
        if (e.experimental && e.link2d)
            r.link2dSpecimens.emplace_back(e.name, *e.link2d);
    if (!cfg.updating.enabled)
        return r;
    if (cfg.updating.method == "ukf")
        r.bounds = tableIIIBounds();
    for (const auto& [name, b] : cfg.updating.bounds)
        r.bounds[name] = b;
    r.fitThreshold = cfg.updating.inspector.threshold;
    return r;
}

PlotReferences PlotReferences::ofConfigurationJson(const std::string& json) {
    try {
        // The updating section and the elements; a record's ground-motion file need not exist.
        return of(parseConfig(nlohmann::json::parse(json), "record"));
    } catch (const std::exception&) {
        return {}; // an old or foreign configuration: plots without reference lines
    }
}

} // namespace hsmu::gui
