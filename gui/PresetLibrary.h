#pragma once
// PresetLibrary: the test configurations embedded in the binary (resources/hsmu.qrc,
// ":/presets/<name>.json") and the rule that turns a command-line CONFIG into a TestConfig:
// an existing file is read from disk; otherwise a preset name ("paper-condition-3") is looked
// up among the embedded presets; then the generated family "shear-building-<N>[-elastic]
// [-mass-damped]" (core/config/ShearBuilding.h); otherwise the name is read as a path (and
// fails naming it).
// Thread rules: any thread (read-only resources).

#include "core/config/TestConfig.h"

#include <QList>
#include <QString>

namespace hsmu::gui {

class PresetLibrary {
public:
    struct Preset {
        QString id;    ///< e.g. "paper-condition-3"
        QString title; ///< the configuration's "name"
    };

    /// Every embedded preset, sorted by id.
    static QList<Preset> presets();
    /// The resource path of preset id, or an empty string if there is none.
    static QString resourcePath(const QString& id);
    /// Load a configuration file or an embedded preset. Throws hsmu::ConfigError naming the
    /// file (or "preset <id>") and the field at fault.
    static TestConfig load(const QString& nameOrPath);
};

} // namespace hsmu::gui
