#pragma once
// AccelerationUnit: the units a ground-motion file may be written in, and their factor to
// m/s^2 (the unit of GroundMotion::acceleration). g is standard gravity, 9.80665 m/s^2;
// 1 gal = 1 cm/s^2.

#include <optional>
#include <string_view>

namespace hsmu {

enum class AccelerationUnit {
    G,                    ///< standard gravity, 9.80665 m/s^2
    MetersPerSecond2,     ///< m/s^2
    CentimetersPerSecond2 ///< cm/s^2 = gal = 0.01 m/s^2
};

/// Parse a unit name, case-insensitive, surrounding blanks ignored:
/// "g"; "m/s^2", "m/s2", "m/s/s"; "cm/s^2", "cm/s2", "cm/s/s", "gal".
/// std::nullopt for anything else.
std::optional<AccelerationUnit> parseAccelerationUnit(std::string_view text);

/// Multiply a value in `unit` by this to get m/s^2.
double toMetersPerSecond2(AccelerationUnit unit);

/// Canonical short name: "g", "m/s^2", "cm/s^2" (parseAccelerationUnit accepts it back).
std::string_view unitSymbol(AccelerationUnit unit);

} // namespace hsmu
