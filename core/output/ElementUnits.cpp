#include "core/output/ElementUnits.h"

#include <algorithm>

namespace hsmu {

ElementUnits elementUnits(const std::string& typeName) {
    if (typeName == "rotationalBaseSpring")
        return {"rad", "kN m"};
    return {"m", "kN"};
}

std::string compactUnit(const std::string& unit) {
    std::string out = unit;
    out.erase(std::remove(out.begin(), out.end(), ' '), out.end());
    return out;
}

} // namespace hsmu
