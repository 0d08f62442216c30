#pragma once
// ComparisonSummary: the result of the paper's comparison protocol (ComparisonProtocol.h) as
// JSON (DIR/compare.json of `hsmu compare`). Keys:
//   config {name, file}, element, dof, force_unit, deformation_unit, displacement_unit ("m"),
//   runs {initial, updated}: {force_nrmse [-], force_peak_error [force_unit],
//        displacement_nrmse [-], displacement_peak_error [m], steps, final_state},
//   reference {steps, final_state},
//   runs.initial.tracking, runs.updated.tracking, reference.tracking: {specimen: as
//     summary.json's "tracking" (RunSummary.h), commanded against measured deformation},
//   runs.initial.link_security, runs.updated.link_security, reference.link_security: {site:
//     "builtin"}, as summary.json's "link_security" (the three runs are in-process),
//   parameters [names, the identifier's order],
//   final_parameters {name: value}, final_standard_deviations {name: value}
//     (the updated run's last estimate, the law's own units: normalized for Bouc-Wen),
//   true_parameters {name: value} (the updating specimen's own law, where it has the name and
//     is the identified model's law; a link2d specimen's: the material of the actuator that
//     alone drives the identified basic DOF, e.g. behind NoTransformation; empty otherwise),
//   applied_updates, steps (the updated run's committed steps),
//   alarms {reference, initial, updated: ["t = ... s: message", ...]}.
// NRMSE = RMS(x - x_ref) / RMS(x_ref) and peak error = max |x - x_ref| against the reference
// run. Non-finite numbers are written as null.
// Thread rules: pure functions, any thread.

#include "core/config/TestConfig.h"
#include "core/session/ComparisonProtocol.h"

#include <nlohmann/json.hpp>

#include <string>

namespace hsmu {

nlohmann::json makeComparisonSummary(const ComparisonResult& result, const TestConfig& cfg);

/// The updating specimen's true law parameters for the identified names; empty if its true
/// law is not the law of its model (the one identified). A link2d specimen (updating.basicDof):
/// the material of the actuator that alone drives that basic DOF at rest.
ParameterValues trueParameters(const TestConfig& cfg, const std::vector<std::string>& names);

/// makeComparisonSummary written with 2-space indentation. Throws std::runtime_error naming
/// the file if it cannot be written.
void writeComparisonJson(const std::string& path, const ComparisonResult& result,
                         const TestConfig& cfg);

} // namespace hsmu
