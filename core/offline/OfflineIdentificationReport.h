#pragma once
// OfflineIdentificationReport: the files of `hsmu replay --identify ... --out DIR`
// (docs/cli.md) from an OfflineIdentificationResult:
//
//   parameters.csv  one row per sample: time [s], deformation [unit], force [unit],
//                   auxiliary_force [unit], fit_error [-], <parameter> [its unit] ...,
//                   stddev <parameter> [its unit] ...   (parameterUnit(); CsvText.h
//                   formatting: exact round trip)
//   summary.json    { "source", "specimen", "method", "samples", "dt", "units":
//                     {"deformation", "force"}, "model": {law, parameters},
//                     "updating": the settings section used (absent when only the
//                     calibration ran: "method" is then "calibration"),
//                     "parameterUnits": { NAME: unit },
//                     "parameters": { NAME: {"initial", "final", "stddev"[, "online"]} },
//                     "finalRmsError", "finalNrmse", "initialNrmse",
//                     "worseThanInitial" (when it is), "auxiliaryNrmse" and
//                     "finalFitError" (the inspector's last window; online runs only),
//                     "refits", "estimatorWarnings", "messages": [...],
//                     "calibration": { "nrmse", "rmsError", "starts", "replays", "seconds",
//                        "model": {every parameter}, "parameters": { NAME: {"value",
//                        "onBound", "stddev", "ci95": [lo, hi], "correlation": {NAME: r}}},
//                        "offsets": {"used", "nrmseWithout", "nrmseWith", "branches",
//                        "criterion"} when the offset test ran (CalibrationDefaults.h)},
//                     "verdict": "" or "the model family cannot represent ..." }
// "online" is the run's own final estimate when the record holds one for the same method
// and parameter. Parameters are in the law's units (normalized by uRef / fRef for Bouc-Wen).
// Throws std::runtime_error naming a file that cannot be written.

#include "core/offline/OfflineIdentification.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace hsmu {

/// summary.json's "calibration" object (above) for an ok calibration: the one shape for the
/// file and for the Python module's hsmu.calibrate.
nlohmann::json calibrationJson(const CalibrationResult& c);

/// j written (indented) to path, appended to `written`; std::runtime_error naming the file
/// when it cannot be written.
void writeJsonFile(const std::string& path, const nlohmann::json& j,
                   std::vector<std::string>& written);

/// The unit of a law's parameter as the tables and files state it: uRef in the deformation's
/// unit, fRef in the force's (and the offsets of every law, OffsetLaw.h: deformationOffset in
/// the deformation's unit, forceOffset in the force's); "-" for the Bouc-Wen laws' normalized parameters; the bilinear
/// law's k0 in force / deformation, fy in force, b "-"; the elastic law's k in force /
/// deformation; "-" otherwise.
std::string parameterUnit(const std::string& law, const std::string& name,
                          const std::string& deformationUnits, const std::string& forceUnits);

/// Returns the paths written (DIR must exist).
std::vector<std::string> writeIdentificationReport(const std::string& dir,
                                                   const SpecimenHistory& history,
                                                   const IdentificationSettings& settings,
                                                   const OfflineIdentificationResult& result,
                                                   const ParameterValues& online = {});

/// The partial summary of an interrupted identification (`hsmu replay` sent SIGINT /
/// SIGTERM; docs/cli.md): DIR/summary.json with { "source", "specimen", "method", "samples",
/// "units", "interrupted": reason, "phase", "samplesDone", "refits", "estimatorWarnings",
/// "parameterUnits", "parameters": { NAME: {"current"} } (the estimate after the last sample
/// done; empty when none) }. Returns the paths written (DIR must exist).
std::vector<std::string> writeInterruptedReport(const std::string& dir,
                                                const SpecimenHistory& history,
                                                const IdentificationSettings& settings,
                                                const OfflinePartial& partial,
                                                const std::string& reason);

} // namespace hsmu
