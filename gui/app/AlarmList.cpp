#include "gui/app/AlarmList.h"

namespace hsmu::gui {

AlarmList::AlarmList(QWidget* parent) : QListWidget(parent) {
    setObjectName(QStringLiteral("alarmList"));
    setAlternatingRowColors(true);
}

QString AlarmList::describe(AlarmKind kind) {
    switch (kind) {
    case AlarmKind::LimitExceeded:
        return tr("limit exceeded");
    case AlarmKind::ControlFault:
        return tr("control fault");
    case AlarmKind::ElementFault:
        return tr("element fault");
    case AlarmKind::IntegratorFault:
        return tr("integrator fault");
    case AlarmKind::OperatorHold:
        return tr("operator");
    case AlarmKind::Stability:
        return tr("stability");
    case AlarmKind::FitError:
        return tr("model fit error");
    case AlarmKind::Fracture:
        return tr("fracture");
    case AlarmKind::EstimatorRejected:
        return tr("estimator rejected");
    case AlarmKind::ParameterPinned:
        return tr("parameter at a bound");
    case AlarmKind::TrackingError:
        return tr("actuator tracking");
    case AlarmKind::ModelUpdate:
        return tr("model update");
    }
    return QString::fromLatin1(alarmKindName(kind));
}

QString AlarmList::describe(AlarmSeverity severity) {
    switch (severity) {
    case AlarmSeverity::Info:
        return tr("info");
    case AlarmSeverity::Warning:
        return tr("warning");
    case AlarmSeverity::Critical:
        return tr("critical");
    }
    return {};
}

void AlarmList::addAlarm(const Alarm& alarm) {
    addMessage(tr("t = %1 s (step %2) %3: %4")
                   .arg(QString::number(alarm.time, 'f', 2))
                   .arg(alarm.step)
                   .arg(describe(alarm.kind), QString::fromStdString(alarm.message)),
               alarm.severity);
}

void AlarmList::addMessage(const QString& text, AlarmSeverity severity) {
    auto* item = new QListWidgetItem(QStringLiteral("[%1] %2").arg(describe(severity), text));
    if (severity == AlarmSeverity::Critical)
        item->setForeground(QColor(198, 40, 40));
    else if (severity == AlarmSeverity::Warning)
        item->setForeground(QColor(200, 120, 0));
    addItem(item);
    scrollToBottom();
}

} // namespace hsmu::gui
