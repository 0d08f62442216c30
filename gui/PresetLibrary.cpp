#include "gui/PresetLibrary.h"

#include "core/config/ConfigLoader.h"
#include "core/config/PresetCatalog.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>

// Q_INIT_RESOURCE must be used outside any namespace; the library is static, so the resource
// initializer is referenced explicitly or the linker may drop it.
static void initPresetResources() {
    Q_INIT_RESOURCE(hsmu);
}

namespace hsmu::gui {

namespace {

void ensureResources() {
    static const bool done = [] {
        initPresetResources();
        return true;
    }();
    (void)done;
}

/// The embedded presets as the core rule's catalog (core/config/PresetCatalog.h).
PresetCatalog embedded() {
    PresetCatalog c;
    c.ids = [] {
        std::vector<std::string> ids;
        for (const PresetLibrary::Preset& p : PresetLibrary::presets())
            ids.push_back(p.id.toStdString());
        return ids;
    };
    c.text = [](const std::string& id) -> std::optional<std::string> {
        const QString path = PresetLibrary::resourcePath(QString::fromStdString(id));
        if (path.isEmpty())
            return std::nullopt;
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            throw ConfigError("preset " + id + ": cannot be read");
        return f.readAll().toStdString();
    };
    return c;
}

} // namespace

QString PresetLibrary::resourcePath(const QString& id) {
    ensureResources();
    if (id.isEmpty() || id.contains(QLatin1Char('/')))
        return {};
    const QString path = QStringLiteral(":/presets/") + id + QStringLiteral(".json");
    return QFile::exists(path) ? path : QString();
}

QList<PresetLibrary::Preset> PresetLibrary::presets() {
    ensureResources();
    QList<Preset> out;
    const QStringList files =
        QDir(QStringLiteral(":/presets")).entryList({QStringLiteral("*.json")}, QDir::Files);
    for (const QString& file : files) {
        const QString id = QFileInfo(file).completeBaseName();
        QString title = id;
        try {
            title = QString::fromStdString(
                parsePreset(id.toStdString(), *embedded().text(id.toStdString())).name);
        } catch (const std::exception&) {
            // keep the id as the title; loading it will report the error
        }
        out.push_back({id, title});
    }
    std::sort(out.begin(), out.end(), [](const Preset& a, const Preset& b) { return a.id < b.id; });
    return out;
}

PresetCatalog PresetLibrary::catalog() {
    return embedded();
}

TestConfig PresetLibrary::load(const QString& nameOrPath) {
    return loadConfigOrPreset(nameOrPath.toStdString(), embedded());
}

} // namespace hsmu::gui
