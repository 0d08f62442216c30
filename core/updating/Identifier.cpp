#include "core/updating/Identifier.h"

#include <cmath>

namespace hsmu {

std::vector<std::string> Identifier::estimateNames() const {
    std::vector<std::string> names;
    for (const auto& [name, v] : estimate())
        names.push_back(name);
    return names;
}

void Identifier::estimateValues(std::vector<double>& out) const {
    out.clear();
    for (const auto& [name, v] : estimate())
        out.push_back(v);
}

void Identifier::standardDeviationValues(std::vector<double>& out) const {
    const ParameterValues sd = standardDeviation();
    out.clear();
    for (const auto& [name, v] : estimate()) {
        auto s = sd.find(name);
        out.push_back(s == sd.end() ? 0.0 : s->second);
    }
}

void Identifier::boundsValues(std::vector<ParameterBounds>& out) const {
    const ParameterBoundsMap& all = bounds();
    out.clear();
    for (const auto& [name, v] : estimate()) {
        auto b = all.find(name);
        out.push_back(b == all.end() ? ParameterBounds{NAN, NAN} : b->second);
    }
}

} // namespace hsmu
