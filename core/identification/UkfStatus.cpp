#include "core/identification/UkfStatus.h"

namespace hsmu {

const char* ukfFaultName(UkfFault fault) {
    switch (fault) {
    case UkfFault::None:
        return "none";
    case UkfFault::NotInitialized:
        return "not initialized";
    case UkfFault::InvalidSettings:
        return "invalid settings";
    case UkfFault::DimensionMismatch:
        return "dimension mismatch";
    case UkfFault::FunctionFailed:
        return "function failed";
    case UkfFault::NonFiniteValue:
        return "non-finite value";
    case UkfFault::NotPositiveDefinite:
        return "not positive definite";
    }
    return "unknown fault";
}

} // namespace hsmu
