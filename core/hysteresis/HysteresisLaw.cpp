#include "core/hysteresis/HysteresisLaw.h"

#include <cstddef>
#include <map>

namespace hsmu {

const char* lawStatusName(LawStatus status) {
    switch (status) {
    case LawStatus::Ok:
        return "ok";
    case LawStatus::NoConvergence:
        return "no convergence";
    case LawStatus::InvalidInput:
        return "invalid input";
    }
    return "unknown status";
}

int HysteresisLaw::parameterIndex(const std::string& name) const {
    const std::vector<std::string> names = parameterNames();
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

int HysteresisLaw::setParameterValues(std::span<const int> indices, std::span<const double> values,
                                      bool allOrNothing) {
    const std::vector<std::string> names = parameterNames();
    const auto nameAt = [&](int i) -> const std::string* {
        return i >= 0 && static_cast<std::size_t>(i) < names.size() ? &names[std::size_t(i)]
                                                                     : nullptr;
    };
    std::map<std::string, double> old;
    if (allOrNothing) {
        for (std::size_t k = 0; k < indices.size(); ++k) {
            if (const std::string* name = nameAt(indices[k])) {
                old.emplace(*name, parameter(*name).value_or(values[k]));
            }
        }
    }
    int firstRefused = -1;
    for (std::size_t k = 0; k < indices.size(); ++k) {
        const std::string* name = nameAt(indices[k]);
        if (name && setParameter(*name, values[k])) {
            continue;
        }
        if (firstRefused < 0) {
            firstRefused = static_cast<int>(k);
        }
        if (allOrNothing) {
            for (const auto& [n, o] : old) {
                setParameter(n, o);
            }
            return firstRefused;
        }
    }
    return firstRefused;
}

} // namespace hsmu
