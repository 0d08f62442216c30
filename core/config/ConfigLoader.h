#pragma once
// ConfigLoader: reads a test configuration (JSON, schema in docs/configuration.md) into a
// TestConfig. Every error is a ConfigError naming the file, the field and what was expected.

#include "core/config/JsonCursor.h"
#include "core/config/TestConfig.h"

#include <string>

namespace hsmu {

/// Parse a material object {"law": NAME, PARAMETER: value, ...} and check that the law
/// accepts it. Throws ConfigError naming the field.
MaterialSpec parseMaterial(const JsonCursor& c);
/// A "limits" object (deformation, force, increment; each > 0 when given).
SafetyLimits parseLimits(const JsonCursor& c);
/// An "actuator" block: {"type": "ideal" | "lag" (timeConstant [s]) | "delay" (delay [s]) |
/// "servoHydraulic" (docs/rths.md)}; ConfigErrors name the field.
ActuatorModel parseActuatorModel(const JsonCursor& c);
/// A DOF given by name or index v (the field `key` of c), checked against dofs.
int parseDof(const JsonCursor& c, const nlohmann::json& v, const std::vector<DofSpec>& dofs,
             const std::string& key);
/// Read and parse a file. Throws ConfigError (unreadable file, JSON syntax with line/column,
/// schema violations).
TestConfig loadConfigFile(const std::string& path);
/// Parse a document; sourceName is used in messages and to resolve relative paths.
TestConfig parseConfig(const nlohmann::json& document, const std::string& sourceName);

} // namespace hsmu
