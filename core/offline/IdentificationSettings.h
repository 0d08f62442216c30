#pragma once
// IdentificationSettings: what offline identification (OfflineIdentification.h) needs: the
// specimen's initial numerical model and the "updating" settings of a configuration
// (docs/configuration.md: method, bounds, ukf, nelderMead, inspector), taken from a recorded
// configuration and optionally overridden by a small JSON document:
//
//   { "model":    { "law": "boucWen", "k0": 1.1, "uRef": 0.02, "fRef": 20, ... },
//     "updating": { "method": "nelderMead", "bounds": { "k0": [0.7, 1.4] }, ... } }
//
// "model" replaces the initial model; "updating" is merged into the recorded section (JSON
// merge patch, RFC 7386: a key given replaces, null removes). The merged section is validated
// exactly as a configuration's (ConfigError naming the file and field); "specimen",
// "enabled", "reporter" and "approval" play no part offline and are ignored.
// Thread rules: plain data.

#include "core/config/TestConfig.h"
#include "core/identification/CalibrationDefaults.h"

#include <nlohmann/json.hpp>

#include <atomic>

#include <string>

namespace hsmu {

struct IdentificationSettings {
    std::string specimen = "specimen"; ///< the identified element's name (labels only)
    MaterialSpec model;                ///< initial model (law and parameters)
    UpdatingSpec updating;             ///< method, bounds, UKF / Nelder-Mead, inspector
    nlohmann::json updatingDocument = nlohmann::json::object(); ///< the section as given
    double dt = 0.01; ///< [s] sample step: Nelder-Mead cooldown / window, inspector windows
    /// Nelder-Mead only: after the last sample, one more fit over the whole history (what a
    /// calibration from an old test wants); the online run has no such fit.
    bool finalFit = true;
    /// Replay the online method over the samples (false: only the calibration below).
    bool online = true;
    /// Calibrate the law over the whole history (Calibration.h): the best the law can do,
    /// reported beside the online result, and the verdict on the model family.
    bool calibrate = true;
    /// The calibration's deformation and force offsets (CalibrationDefaults.h, "Offsets";
    /// `hsmu replay --offsets`): fitted when the data ask for them (auto), always (on) or
    /// never (off). Offline only: the online identifiers and the twins take no offsets.
    CalibrationOffsets offsets = CalibrationOffsets::Auto;
    /// A calibration NRMSE above this says that the law cannot represent the specimen [-].
    double verdictNrmse = 0.25;
    /// When set and true (from any thread), the work stops at the calibration's next
    /// iteration or the online pass's next sample and identifyOffline throws
    /// OfflineCancelled (the Python module's Ctrl+C). May be null; not owned.
    const std::atomic<bool>* cancel = nullptr;
};

/// Settings for the experimental element `specimen` of a parsed configuration ("": the
/// updating specimen, else the only experimental element): its model, the configuration's
/// updating section when that identifies this specimen (else the defaults: the UKF for a
/// boucWen or mrDamper model, Nelder-Mead otherwise), and the configuration's dt. Throws ConfigError
/// when there is no such specimen or the choice is ambiguous.
IdentificationSettings identificationSettingsFrom(const TestConfig& cfg,
                                                  const std::string& specimen = {});

/// Defaults for data without a configuration (an imported CSV): a boucWen model with the
/// law's default parameters, the UKF with the default settings, dt = 0.01 s.
IdentificationSettings defaultIdentificationSettings();

/// base with `override` (the document above) applied, then `method` ("ukf", "nelderMead" or
/// "nelder-mead"; "calibration": only the calibration will run, so the online method is not
/// checked against the model; "" keeps the section's) in the same step, so that a new model and its
/// method are checked together. sourceName names the override in messages. Throws
/// ConfigError (unknown keys, bad values, a method the model does not support, e.g. the UKF
/// on a bilinear model).
IdentificationSettings withOverride(const IdentificationSettings& base,
                                    const nlohmann::json& override, const std::string& sourceName,
                                    const std::string& method = {});

/// hsmu replay's default when no --method is given: true (only the calibration over the whole
/// history, the documented offline way) for a boucWenPinching model whose updating section does
/// not name a method (its online method, the pinching UKF, anchors a pinching calibration every
/// time the history grows: much more work for about the same fit); false otherwise (the
/// section's method, e.g. a record's own online settings, or the UKF for boucWen).
bool calibrationOnlyByDefault(const IdentificationSettings& s);

/// base with method "ukf" or "nelderMead" (also accepted: "nelder-mead"). Throws ConfigError.
IdentificationSettings withMethod(const IdentificationSettings& base, const std::string& method);

} // namespace hsmu
