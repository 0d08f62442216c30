#include "core/util/Alarm.h"

namespace hsmu {

const char* alarmSeverityName(AlarmSeverity s)
{
    switch (s) {
    case AlarmSeverity::Info: return "info";
    case AlarmSeverity::Warning: return "warning";
    case AlarmSeverity::Critical: return "critical";
    }
    return "?";
}

const char* alarmKindName(AlarmKind k)
{
    switch (k) {
    case AlarmKind::LimitExceeded: return "limit exceeded";
    case AlarmKind::ControlFault: return "control fault";
    case AlarmKind::ElementFault: return "element fault";
    case AlarmKind::IntegratorFault: return "integrator fault";
    case AlarmKind::OperatorHold: return "operator hold";
    case AlarmKind::Stability: return "stability";
    case AlarmKind::FitError: return "model error";
    case AlarmKind::Fracture: return "fracture";
    case AlarmKind::EstimatorRejected: return "estimator rejected";
    case AlarmKind::ParameterPinned: return "parameter at bound";
    case AlarmKind::TrackingError: return "tracking error";
    case AlarmKind::ModelUpdate: return "model update";
    }
    return "?";
}

} // namespace hsmu
