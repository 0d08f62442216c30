#include "core/config/ShearBuilding.h"

#include <charconv>

namespace hsmu {

namespace {

constexpr char kPrefix[] = "shear-building-";

bool consumeSuffix(std::string& s, const std::string& suffix)
{
    if (s.size() <= suffix.size() || s.compare(s.size() - suffix.size(), suffix.size(), suffix))
        return false;
    s.resize(s.size() - suffix.size());
    return true;
}

nlohmann::json boucWenMaterial()
{
    return {{"law", "boucWen"}, {"k0", 1.0},      {"alpha", 0.05},   {"n", 2.0},
            {"beta", 0.75},     {"gamma", 0.25},  {"A0", 1.0},       {"deltaA", 0.0},
            {"deltaNu", 0.0},   {"deltaEta", 0.0}, {"uRef", 0.02},   {"fRef", 80.0}};
}

} // namespace

std::optional<ShearBuildingSpec> parseShearBuildingName(const std::string& name)
{
    const std::string prefix = kPrefix;
    if (name.rfind(prefix, 0) != 0)
        return std::nullopt;
    std::string rest = name.substr(prefix.size());
    ShearBuildingSpec spec;
    spec.massDamped = consumeSuffix(rest, "-mass-damped");
    spec.boucWen = !consumeSuffix(rest, "-elastic");
    if (!spec.massDamped) // either order of the suffixes
        spec.massDamped = consumeSuffix(rest, "-mass-damped");
    int n = 0;
    const auto r = std::from_chars(rest.data(), rest.data() + rest.size(), n);
    if (rest.empty() || r.ec != std::errc() || r.ptr != rest.data() + rest.size() || n < 1 ||
        n > kMaxShearBuildingStoreys)
        return std::nullopt;
    spec.storeys = n;
    return spec;
}

nlohmann::json shearBuildingConfig(const ShearBuildingSpec& spec)
{
    const int n = spec.storeys;
    nlohmann::json dofs = nlohmann::json::array();
    nlohmann::json elements = nlohmann::json::array();
    const nlohmann::json material =
        spec.boucWen ? boucWenMaterial() : nlohmann::json{{"law", "elastic"}, {"k", 4000.0}};
    for (int i = 0; i < n; ++i) {
        dofs.push_back({{"name", "S" + std::to_string(i + 1)}, {"mass", 10.0}});
        nlohmann::json e = {{"name", "storey " + std::to_string(i + 1)}, {"material", material}};
        if (i == 0) {
            e["type"] = "lateralSpring";
            e["dof"] = 0;
        } else {
            e["type"] = "truss";
            e["dofs"] = {i - 1, i};
        }
        elements.push_back(std::move(e));
    }
    const nlohmann::json damping = spec.massDamped
                                       ? nlohmann::json{{"a0", 0.5}, {"a1", 0.0}}
                                       : nlohmann::json{{"ratio", 0.05}, {"modes", {1, 2}}};
    std::string name = "shear-building-" + std::to_string(n);
    if (!spec.boucWen)
        name += "-elastic";
    if (spec.massDamped)
        name += "-mass-damped";
    return {
        {"name", name},
        {"description", "Generated shear building: " + std::to_string(n) +
                            " storeys of 10 t on " +
                            (spec.boucWen ? "Bouc-Wen" : "linear elastic") +
                            " storey springs of 4000 kN/m (docs/presets.md)."},
        {"units",
         {{"force", "kN"}, {"length", "m"}, {"time", "s"}, {"mass", "t"}, {"rotation", "rad"},
          {"moment", "kN m"}}},
        {"structure", {{"dofs", dofs}, {"damping", damping}, {"elements", elements}}},
        {"groundMotion", {{"builtin", "synthetic"}, {"scale", 1.0}}},
        {"analysis", {{"integrator", "explicitNewmark"}, {"dt", 0.001}, {"duration", 5.0}}},
    };
}

} // namespace hsmu
