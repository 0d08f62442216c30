#pragma once
// AlarmList: the alarms and operator events of the current test, newest last, with test time,
// step, severity and a translated kind. Thread rules: GUI thread only.

#include "core/test/Alarm.h"

#include <QListWidget>

namespace hsmu::gui {

class AlarmList : public QListWidget {
    Q_OBJECT
public:
    explicit AlarmList(QWidget* parent = nullptr);

    void addAlarm(const Alarm& alarm);
    /// A console message that is not a test alarm (e.g. a configuration error).
    void addMessage(const QString& text, AlarmSeverity severity);

    static QString describe(AlarmKind kind);
    static QString describe(AlarmSeverity severity);
};

} // namespace hsmu::gui
