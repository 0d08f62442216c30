#pragma once
// PresetLibrary: the test configurations embedded in the binary (resources/hsmu.qrc,
// ":/presets/<name>.json"), as the catalog of the one CONFIG rule of every front end
// (core/config/PresetCatalog.h: an existing file, else an embedded preset, else the generated
// shear-building family, else a path that fails naming it).
// Thread rules: any thread (read-only resources).

#include "core/config/PresetCatalog.h"
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
    /// The embedded presets as the CONFIG rule's catalog (RunFlow).
    static PresetCatalog catalog();
};

} // namespace hsmu::gui
