#pragma once
// Tests address a law's parameters by name, as configurations do: the name resolved once with
// parameterIndex(), then the law's by-position access (HysteresisLaw.h).

#include "core/hysteresis/HysteresisLaw.h"

#include <optional>
#include <string>

namespace hsmu::test {

/// The parameter named `name`; nullopt if the law has none.
inline std::optional<double> parameterNamed(const HysteresisLaw& law, const std::string& name)
{
    const int i = law.parameterIndex(name);
    return i < 0 ? std::nullopt : std::optional<double>(law.parameterValue(i));
}

/// Set the parameter named `name`; false if the law has none or refuses the value.
inline bool setParameterNamed(HysteresisLaw& law, const std::string& name, double value)
{
    const int i = law.parameterIndex(name);
    return i >= 0 && law.setParameterValue(i, value);
}

} // namespace hsmu::test
