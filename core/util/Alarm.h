#pragma once
// Alarm: something the operator must know, with the test time, a severity and a reason
// (in core/util: raised by updating, experiment and record alike, so below all of them).
// core returns enums and text in English; the GUI chooses how to show (and translate) kinds.

#include <string>

namespace hsmu {

enum class AlarmSeverity { Info, Warning, Critical };

enum class AlarmKind {
    LimitExceeded,   ///< a target or measured force past a safety limit: held, nothing sent
    ControlFault,    ///< the experimental control reported a fault
    ElementFault,    ///< a numerical element failed (e.g. law non-convergence)
    IntegratorFault, ///< non-finite response
    OperatorHold,    ///< the operator held the test
    Stability,       ///< explicit scheme forced past its stability limit
    FitError,        ///< the model's error above the inspector's threshold
    Fracture,        ///< sudden strength loss of a specimen
    EstimatorRejected, ///< the identifier rejected an update or diverged
    ParameterPinned, ///< an identified parameter stayed at a bound
    TrackingError,   ///< actuator tracking (J1-J3) out of tolerance
    ModelUpdate      ///< parameters applied to (or refused by) a numerical element
};

struct Alarm {
    double time = 0.0; ///< test time [s]
    int step = 0;
    AlarmSeverity severity = AlarmSeverity::Info;
    AlarmKind kind = AlarmKind::ElementFault;
    std::string message;
};

const char* alarmSeverityName(AlarmSeverity s);
const char* alarmKindName(AlarmKind k);

} // namespace hsmu
