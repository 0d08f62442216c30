#pragma once
// Tests read an identifier's estimate and bounds by name: the name resolved with its layout
// (Identifier.h; an unknown name throws std::invalid_argument naming it).

#include "core/updating/Identifier.h"

#include <map>
#include <string>
#include <vector>

namespace hsmu::test {

inline double estimateOf(const Identifier& id, const std::string& name)
{
    return id.estimate()[id.layout().indexOf(name, "test")];
}

inline const ParameterBounds& boundsOf(const Identifier& id, const std::string& name)
{
    return id.bounds()[id.layout().indexOf(name, "test")];
}

inline bool setBoundsOf(Identifier& id, const std::string& name, const ParameterBounds& b)
{
    const auto i = id.layout().find(name);
    return i && id.setBounds(*i, b);
}

/// The estimate as a vector (layout order).
inline std::vector<double> estimateVector(const Identifier& id)
{
    return {id.estimate().begin(), id.estimate().end()};
}

} // namespace hsmu::test

namespace hsmu::test {

/// The estimate by name (for assertions that pick parameters by name).
inline std::map<std::string, double> estimateByName(const Identifier& id)
{
    std::map<std::string, double> out;
    for (std::size_t k = 0; k < id.layout().size(); ++k)
        out[id.layout().name(k)] = id.estimate()[k];
    return out;
}

} // namespace hsmu::test
