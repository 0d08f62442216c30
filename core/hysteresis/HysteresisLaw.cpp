#include "core/hysteresis/HysteresisLaw.h"

#include <cstddef>
#include <limits>

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

double historyTimeIncrement(std::span<const double> time, std::size_t k) {
    if (k >= time.size())
        return std::numeric_limits<double>::quiet_NaN();
    return k == 0 ? std::numeric_limits<double>::infinity() : time[k] - time[k - 1];
}

double HysteresisLaw::timeIncrement() const {
    return std::numeric_limits<double>::quiet_NaN();
}

bool HysteresisLaw::setParameterValue(int index, double value) {
    return setParameterValues(std::span<const int>(&index, 1), std::span<const double>(&value, 1),
                              true) == -1;
}

} // namespace hsmu
