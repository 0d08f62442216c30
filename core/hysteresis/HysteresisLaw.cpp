#include "core/hysteresis/HysteresisLaw.h"

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

} // namespace hsmu
