#pragma once
// AlarmMetaType: lets core's hsmu::Alarm travel through queued signals (worker -> GUI).
// Include before any header that declares a signal with an Alarm argument.

#include "core/util/Alarm.h"

#include <QMetaType>

Q_DECLARE_METATYPE(hsmu::Alarm)
