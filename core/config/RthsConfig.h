#pragma once
// RthsConfig: a real-time hybrid simulation (docs/rths.md, "Configuration"): the JSON
// object "rths" of a configuration file, in SI units (m, N, kg, s), parsed into the loop's
// settings; and the generated benchmark configurations "rths-benchmark-case-<1..4>" (the RTHS
// benchmark's reference structure, partition, El Centro x 0.4, nominal plant, sample
// controller). Every error is a ConfigError naming the file and the field.

#include "core/config/JsonCursor.h"
#include "core/groundmotion/GroundMotion.h"
#include "core/rths/Partition.h"
#include "core/rths/RthsLoop.h"
#include "core/rths/ServoActuator.h"
#include "core/updating/TwinIdentification.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace hsmu {

struct RthsConfig {
    std::string name;
    rths::LinearStructure reference;
    int benchmarkCase = 0;        ///< 1..4 when the structure is the benchmark's, else 0
    int specimenDof = 0;          ///< the experimental substructure's DOF (0-based)
    rths::RthsSettings settings;  ///< plant, controller, compensation, sensors, limits, rate
    std::string groundMotionFile; ///< "" when none is named (the command line gives one)
    double groundMotionScale = 1.0;
    std::string groundMotionUnit = "m/s^2";
    int holdAfterMisses = 10;     ///< deadline misses (real-time pace) before the test holds; 0: never
    /// "damper": {"identification": {...}}: the online identification of the damper that
    /// updates its twin (settings.damper: the damper and the twin themselves)
    rths::TwinIdentificationSettings identification;
    nlohmann::json raw;           ///< the whole document as given (the record keeps it)
    /// The partition of `reference` with the plant's specimen (me, ce, ke) at specimenDof.
    rths::Partition partition() const;
};

/// The pieces shared with the virtual specimen's servo-hydraulic actuator (ConfigLoader): each
/// reads the object at c over the defaults already in out.
void parsePlantParameters(const JsonCursor& c, rths::PlantParameters& out);
void parsePidGains(const JsonCursor& c, rths::PidGains& out);
void parseLead(const JsonCursor& c, rths::LeadSettings& out);
void parseActuatorLimits(const JsonCursor& c, rths::ActuatorLimits& out);
/// A specimen's "actuator": {"type": "servoHydraulic", ...} (docs/configuration.md).
void parseServoActuator(const JsonCursor& c, rths::ServoActuatorSettings& out);

/// Parse a whole configuration document (with its "rths" object); file names the source.
RthsConfig parseRthsConfig(const nlohmann::json& document, const std::string& file);
/// Read and parse a configuration file.
RthsConfig loadRthsConfig(const std::string& path);
/// The run's ground motion: file ("" = the configuration's) in the configuration's unit, times
/// scale [m/s^2]. Throws std::runtime_error naming the file when it is missing or unreadable.
GroundMotion loadRthsGroundMotion(const RthsConfig& cfg, const std::string& file, double scale);
/// The generated benchmark configuration's JSON for "rths-benchmark-case-N", nullopt for
/// another name.
std::optional<nlohmann::json> rthsBenchmarkDocument(const std::string& name);

} // namespace hsmu
