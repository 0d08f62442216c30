#include "core/groundmotion/AccelerationUnit.h"

#include "core/groundmotion/GroundMotion.h"

#include <cctype>
#include <string>

namespace hsmu {

std::optional<AccelerationUnit> parseAccelerationUnit(std::string_view text) {
    std::string key;
    for (char c : text) {
        if (!std::isspace(static_cast<unsigned char>(c)))
            key += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    if (key == "g")
        return AccelerationUnit::G;
    if (key == "m/s^2" || key == "m/s2" || key == "m/s/s" || key == "m/s**2")
        return AccelerationUnit::MetersPerSecond2;
    if (key == "cm/s^2" || key == "cm/s2" || key == "cm/s/s" || key == "cm/s**2" || key == "gal")
        return AccelerationUnit::CentimetersPerSecond2;
    return std::nullopt;
}

double toMetersPerSecond2(AccelerationUnit unit) {
    switch (unit) {
    case AccelerationUnit::G:
        return kStandardGravity;
    case AccelerationUnit::MetersPerSecond2:
        return 1.0;
    case AccelerationUnit::CentimetersPerSecond2:
        return 0.01;
    }
    return 1.0;
}

std::string_view unitSymbol(AccelerationUnit unit) {
    switch (unit) {
    case AccelerationUnit::G:
        return "g";
    case AccelerationUnit::MetersPerSecond2:
        return "m/s^2";
    case AccelerationUnit::CentimetersPerSecond2:
        return "cm/s^2";
    }
    return "m/s^2";
}

} // namespace hsmu
