#pragma once
// Alarm: something the operator must know, with the test time, a severity and a reason
// (in core/util: raised by updating, experiment and record alike, so below all of them).
// core returns enums and text in English; the GUI chooses how to show (and translate) kinds.
// A message made from a fixed template also carries the template's stable code and its
// arguments (as text, in order): the GUI shows its own translation of the code
// (gui/app/AlarmText), the record keeps the code and the English message (docs/recording.md).

#include <string>
#include <utility>
#include <vector>

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
    Alarm() = default;
    Alarm(double time, int step, AlarmSeverity severity, AlarmKind kind, std::string message,
          std::string code = {}, std::vector<std::string> args = {})
        : time(time), step(step), severity(severity), kind(kind), message(std::move(message)),
          code(std::move(code)), args(std::move(args)) {}

    double time = 0.0; ///< test time [s]
    int step = 0;
    AlarmSeverity severity = AlarmSeverity::Info;
    AlarmKind kind = AlarmKind::ElementFault;
    std::string message;            ///< English
    std::string code;               ///< the message's template, e.g. "fit-error" ("" = none)
    std::vector<std::string> args;  ///< the template's arguments, in order
};

const char* alarmSeverityName(AlarmSeverity s);
const char* alarmKindName(AlarmKind k);

} // namespace hsmu
