#pragma once
// UkfStatus: the outcome of a step of UnscentedKalmanFilter (and of the estimators built on
// it): accepted, or rejected with a fault and a reason, the last good estimate being kept.

#include <string>

namespace hsmu {

/// Why a step was rejected (None when it was accepted).
enum class UkfFault {
    None,
    NotInitialized,     ///< init() has not succeeded
    InvalidSettings,    ///< a <= 0, L + kappa <= 0 or a non-finite setting
    DimensionMismatch,  ///< Q, R, z or a function's output has the wrong size
    FunctionFailed,     ///< the process or measurement function reported a failure
    NonFiniteValue,     ///< a function value, a mean or a covariance is not finite
    NotPositiveDefinite ///< a covariance cannot be factored even with the largest jitter
};

/// Words for a fault (for logs; the GUI translates its own). Not named toString (Qt Test ADL).
const char* ukfFaultName(UkfFault fault);

/// Outcome of init(), predict() or update().
struct UkfStatus {
    bool ok = true;
    UkfFault fault = UkfFault::None;
    std::string reason;  ///< empty when ok; otherwise a sentence naming the failing quantity
    double jitter = 0.0; ///< largest diagonal jitter added in this call (absolute)
};

} // namespace hsmu
