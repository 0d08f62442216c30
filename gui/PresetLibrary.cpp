#include "gui/PresetLibrary.h"

#include "core/config/ConfigLoader.h"
#include "core/config/ShearBuilding.h"

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

TestConfig parsePreset(const QString& id) {
    QFile f(PresetLibrary::resourcePath(id));
    if (!f.open(QIODevice::ReadOnly))
        throw ConfigError("preset " + id.toStdString() + ": cannot be read");
    const QByteArray bytes = f.readAll();
    const std::string source = "preset " + id.toStdString();
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(bytes.constBegin(), bytes.constEnd());
    } catch (const nlohmann::json::exception& e) {
        throw ConfigError(source + ": " + e.what());
    }
    return parseConfig(doc, source);
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
            title = QString::fromStdString(parsePreset(id).name);
        } catch (const std::exception&) {
            // keep the id as the title; loading it will report the error
        }
        out.push_back({id, title});
    }
    std::sort(out.begin(), out.end(), [](const Preset& a, const Preset& b) { return a.id < b.id; });
    return out;
}

TestConfig PresetLibrary::load(const QString& nameOrPath) {
    if (QFileInfo(nameOrPath).isFile())
        return loadConfigFile(nameOrPath.toStdString());
    if (!resourcePath(nameOrPath).isEmpty())
        return parsePreset(nameOrPath);
    if (auto spec = parseShearBuildingName(nameOrPath.toStdString()))
        return parseConfig(shearBuildingConfig(*spec), "preset " + nameOrPath.toStdString());
    const bool looksLikePath = nameOrPath.contains(QLatin1Char('/')) ||
                               nameOrPath.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive);
    if (looksLikePath)
        return loadConfigFile(nameOrPath.toStdString());
    QStringList ids;
    for (const Preset& p : presets())
        ids << p.id;
    throw ConfigError(nameOrPath.toStdString() +
                      ": neither a configuration file nor a preset (presets: " +
                      ids.join(QStringLiteral(", ")).toStdString() +
                      ", and the generated shear-building-<N>[-elastic][-mass-damped])");
}

} // namespace hsmu::gui
