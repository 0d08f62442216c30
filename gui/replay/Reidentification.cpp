#include "gui/replay/Reidentification.h"

#include "core/config/ConfigLoader.h"
#include "core/record/RecordData.h"

#include <QFile>

namespace hsmu::gui {

nlohmann::json readJsonFile(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        throw ConfigError(path.toStdString() + ": cannot be opened");
    try {
        return nlohmann::json::parse(f.readAll().toStdString());
    } catch (const nlohmann::json::parse_error& e) {
        throw ConfigError(path.toStdString() + ": not valid JSON (" + e.what() + ")");
    }
}

IdentificationSettings withOverrides(const IdentificationSettings& base, const QString& overridePath,
                                     const QString& method) {
    if (!overridePath.isEmpty())
        return withOverride(base, readJsonFile(overridePath), overridePath.toStdString(),
                            method.toStdString());
    if (!method.isEmpty())
        return withMethod(base, method.toStdString());
    return base;
}

Reidentification reidentifyRecord(const RecordData& record, const QString& source,
                                  const QString& method, const QString& overridePath) {
    const std::string name = source.toStdString();
    const TestConfig cfg = parseConfig(nlohmann::json::parse(record.meta.configuration), name);
    Reidentification out;
    out.settings = withOverrides(identificationSettingsFrom(cfg), overridePath, method);
    const SpecimenHistory history = historyFromRecord(record, out.settings.specimen, name);
    out.time = history.time;
    out.result = identifyOffline(history, out.settings);
    return out;
}

} // namespace hsmu::gui
