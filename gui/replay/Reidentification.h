#pragma once
// Reidentification: offline identification of a recorded specimen (OfflineIdentification.h)
// with the recorded settings or other ones, for the replay window's "Re-identify..." and
// `hsmu replay --identify` (docs/cli.md): the settings are the record's configuration's
// (identificationSettingsFrom), then an override JSON file ({"model": ..., "updating": ...},
// IdentificationSettings.h) and / or a method ("ukf", "nelderMead" or "nelder-mead").
// Errors: ConfigError (unreadable or invalid override, a method the model cannot use),
// std::invalid_argument (no such specimen); never a crash.
// Thread rules: none; reidentifyRecord() is meant to run off the GUI thread.

#include "core/offline/IdentificationSettings.h"
#include "core/offline/OfflineIdentification.h"

#include <QString>

#include <vector>

namespace hsmu {
struct RecordData;
}

namespace hsmu::gui {

/// A JSON file parsed; ConfigError naming the file if unreadable or not JSON.
nlohmann::json readJsonFile(const QString& path);

/// base with the override file (if any) and the method (if any) applied, as `--config` and
/// `--method` of `hsmu replay`.
IdentificationSettings withOverrides(const IdentificationSettings& base, const QString& overridePath,
                                     const QString& method);

struct Reidentification {
    IdentificationSettings settings;
    std::vector<double> time; ///< [s] of each sample (rows 1 .. N-1 of the record)
    OfflineIdentificationResult result;
};

/// Identify the record's updating specimen (else its only experimental element) again.
/// source names the record in messages.
Reidentification reidentifyRecord(const RecordData& record, const QString& source,
                                  const QString& method, const QString& overridePath);

} // namespace hsmu::gui
