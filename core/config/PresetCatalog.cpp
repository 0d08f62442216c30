#include "core/config/PresetCatalog.h"

#include "core/config/ConfigLoader.h"
#include "core/config/ShearBuilding.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace hsmu {

namespace {

bool endsWithJson(const std::string& name) {
    if (name.size() < 5)
        return false;
    std::string tail = name.substr(name.size() - 5);
    std::transform(tail.begin(), tail.end(), tail.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return tail == ".json";
}

} // namespace

std::optional<std::string> presetFile(const std::string& name,
                                      const std::vector<std::string>& folders) {
    if (name.empty() || name.find('/') != std::string::npos)
        return std::nullopt;
    for (const std::string& folder : folders) {
        const fs::path file = fs::path(folder) / (name + ".json");
        std::error_code ec;
        if (fs::is_regular_file(file, ec))
            return file.string();
    }
    return std::nullopt;
}

PresetCatalog presetFolders(std::vector<std::string> folders) {
    PresetCatalog c;
    c.ids = [folders] {
        std::vector<std::string> ids;
        for (const std::string& folder : folders) {
            std::error_code ec;
            for (const auto& entry : fs::directory_iterator(folder, ec))
                if (entry.path().extension() == ".json")
                    ids.push_back(entry.path().stem().string());
            if (!ids.empty())
                break;
        }
        std::sort(ids.begin(), ids.end());
        return ids;
    };
    c.text = [folders](const std::string& id) -> std::optional<std::string> {
        const auto file = presetFile(id, folders);
        if (!file)
            return std::nullopt;
        std::ifstream in(*file);
        if (!in)
            throw ConfigError("preset " + id + ": cannot be read (" + *file + ")");
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    };
    return c;
}

TestConfig parsePreset(const std::string& id, const std::string& text) {
    const std::string source = "preset " + id;
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw ConfigError(source + ": " + e.what());
    }
    return parseConfig(doc, source);
}

TestConfig loadConfigOrPreset(const std::string& nameOrPath, const PresetCatalog& catalog) {
    std::error_code ec;
    if (fs::is_regular_file(nameOrPath, ec))
        return loadConfigFile(nameOrPath);
    if (!nameOrPath.empty() && nameOrPath.find('/') == std::string::npos)
        if (const auto text = catalog.text(nameOrPath))
            return parsePreset(nameOrPath, *text);
    if (auto spec = parseShearBuildingName(nameOrPath))
        return parseConfig(shearBuildingConfig(*spec), "preset " + nameOrPath);
    if (nameOrPath.find('/') != std::string::npos || endsWithJson(nameOrPath))
        return loadConfigFile(nameOrPath);
    std::string ids;
    for (const std::string& id : catalog.ids())
        ids += (ids.empty() ? "" : ", ") + id;
    throw ConfigError(nameOrPath + ": neither a configuration file nor a preset (presets: " + ids +
                      ", and the generated shear-building-<N>[-elastic][-mass-damped])");
}

} // namespace hsmu
