#pragma once
// PresetCatalog: where preset configurations come from, and the one rule that turns a CONFIG
// argument into a TestConfig for every front end (`hsmu run CONFIG`, the console's preset
// box, `hsmu compare`, hsmu.run(config) in Python, docs/presets.md):
//   1. an existing file is read from disk (loadConfigFile);
//   2. a name without '/' that the catalog holds is that preset, read with the source name
//      "preset <id>" (so errors name it, as the program's embedded copy does);
//   3. the generated family "shear-building-<N>[-elastic][-mass-damped]"
//      (core/config/ShearBuilding.h);
//   4. a name with '/' or ending in ".json" is read as a path (and fails naming it);
//   5. otherwise ConfigError "NAME: neither a configuration file nor a preset (presets: ...)".
// The program's catalog is its embedded copies (gui/PresetLibrary, Qt resources); the Python
// module's and hsmu-controller's are folders of NAME.json (presetFolders: the installed
// PREFIX/share/hsmu/presets, else the source tree's resources/presets).
// Thread rules: none (a catalog's functions must be callable from the caller's thread).

#include "core/config/TestConfig.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hsmu {

struct PresetCatalog {
    /// The preset ids (file stems, e.g. "paper-condition-3"), sorted.
    std::function<std::vector<std::string>()> ids;
    /// The JSON text of preset `id`; nullopt if the catalog has none of that id.
    std::function<std::optional<std::string>(const std::string& id)> text;
};

/// A catalog of NAME.json files in folders: ids are those of the first folder that holds any
/// preset, a preset's text the first folder's that holds its file. Missing folders are skipped.
PresetCatalog presetFolders(std::vector<std::string> folders);

/// The file of preset `name` in the first of `folders` that holds NAME.json; nullopt if none
/// does or name holds a '/'.
std::optional<std::string> presetFile(const std::string& name,
                                      const std::vector<std::string>& folders);

/// Parse a preset's JSON text with the source name "preset <id>". Throws ConfigError.
TestConfig parsePreset(const std::string& id, const std::string& text);

/// The rule above. Throws ConfigError naming the file (or "preset <id>") and the field.
TestConfig loadConfigOrPreset(const std::string& nameOrPath, const PresetCatalog& catalog);

} // namespace hsmu
