#include "core/offline/IdentificationSettings.h"

#include "core/config/ConfigLoader.h"
#include "core/config/UpdatingConfig.h"
#include "core/identification/ParameterSet.h"

namespace hsmu {

namespace {

/// Parse an updating section for `model` through the configuration's own parser: a
/// configuration holding only the specimen, experimental, with that model.
IdentificationSettings reparse(const IdentificationSettings& base, nlohmann::json section,
                               const std::string& sourceName) {
    // basicDof and model: the base's (the identified DOF and its model, taken apart below).
    for (const char* unused : {"specimen", "enabled", "reporter", "approval", "basicDof", "model"})
        section.erase(unused);
    TestConfig cfg;
    cfg.sourcePath = sourceName;
    ElementSpec e;
    e.name = base.specimen;
    e.experimental = true;
    e.material = base.model;
    cfg.elements.push_back(e);
    nlohmann::json full = section;
    full["specimen"] = base.specimen;
    IdentificationSettings s = base;
    s.updating = parseUpdating(JsonCursor(full, sourceName, "updating"), cfg);
    s.updating.basicDof = base.updating.basicDof;
    // Nelder-Mead's missing bounds (and, without the model's uRef / fRef, its scales) come
    // from the data as the calibration's (NelderMeadIdentifier.h): Table III only where the
    // configuration names it (the paper's presets).
    s.updatingDocument = std::move(section);
    return s;
}

} // namespace

IdentificationSettings identificationSettingsFrom(const TestConfig& cfg,
                                                  const std::string& specimen) {
    std::string name = specimen;
    std::vector<std::string> experimental;
    for (const ElementSpec& e : cfg.elements)
        if (e.experimental)
            experimental.push_back(e.name);
    if (name.empty() && cfg.updating.enabled)
        name = cfg.updating.specimen;
    if (name.empty() && experimental.size() == 1)
        name = experimental.front();
    if (name.empty())
        throw ConfigError(cfg.sourcePath + ": " + std::to_string(experimental.size()) +
                          " specimens (experimental elements) and no updating section: name "
                          "the specimen to identify (--specimen)");
    const ElementSpec* spec = nullptr;
    for (const ElementSpec& e : cfg.elements)
        if (e.name == name && e.experimental)
            spec = &e;
    if (!spec)
        throw ConfigError(cfg.sourcePath + ": no specimen (experimental element) named '" + name +
                          "'");
    IdentificationSettings s;
    s.specimen = name;
    // The identified DOF's model: a link2d specimen's is the updating section's (its basic
    // DOFs carry no material).
    const bool updated = cfg.updating.enabled && cfg.updating.specimen == name;
    s.model = updated ? cfg.updating.model : spec->material;
    s.dt = cfg.analysis.dt;
    if (spec->link2d && !updated)
        throw ConfigError(cfg.sourcePath + ": '" + name + "' is a link2d specimen: its basic "
                          "DOF and that DOF's model come from an updating section naming it "
                          "(updating.basicDof, updating.model)");
    if (updated) {
        s.updating = cfg.updating;
        if (cfg.raw.contains("updating"))
            s.updatingDocument = cfg.raw["updating"];
        return s;
    }
    nlohmann::json section = nlohmann::json::object();
    if (s.model.law != "boucWenPinching") // its default (the pinching UKF) left implicit:
        section["method"] = s.model.law == "boucWen" || s.model.law == "mrDamper"
                                ? "ukf"
                                : "nelderMead"; // replay calibrates
    return reparse(s, section, cfg.sourcePath);
}

IdentificationSettings defaultIdentificationSettings() {
    IdentificationSettings s;
    s.model.law = "boucWen";
    return reparse(s, nlohmann::json::object(), "defaults");
}

IdentificationSettings withOverride(const IdentificationSettings& base,
                                    const nlohmann::json& override, const std::string& sourceName,
                                    const std::string& method) {
    const JsonCursor root(override, sourceName);
    root.requireObject();
    root.allowOnly({"model", "updating"});
    IdentificationSettings s = base;
    if (root.has("model"))
        s.model = parseMaterial(root.child("model"));
    nlohmann::json section = base.updatingDocument;
    if (root.has("updating")) {
        root.child("updating").requireObject();
        section.merge_patch(override["updating"]);
    }
    if (method == "calibration") {
        // Only the calibration runs: the online method is not used, so a model the UKF
        // cannot identify (e.g. boucWenPinching) must not be refused for it.
        if (s.model.law != "boucWen")
            section["method"] = "nelderMead";
    } else if (!method.empty()) {
        const std::string m = method == "nelder-mead" ? "nelderMead" : method;
        if (m != "ukf" && m != "nelderMead")
            throw ConfigError("--method: expected ukf, nelder-mead, calibration or all, found '" +
                              method + "'");
        section["method"] = m;
    }
    return reparse(s, section, sourceName);
}

bool calibrationOnlyByDefault(const IdentificationSettings& s) {
    return s.model.law == "boucWenPinching" && !s.updatingDocument.contains("method");
}

IdentificationSettings withMethod(const IdentificationSettings& base, const std::string& method) {
    return withOverride(base, nlohmann::json::object(), "--method " + method, method);
}

} // namespace hsmu
