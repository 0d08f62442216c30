#pragma once
// ActuatorLimitText: the pre-flight check's line for one per-actuator limit
// (core/experimental/ActuatorLimitCheck.h) in the operator's language, e.g.
//   "PASS  Column L, actuator 'vertical' (force control): force |F| up to 500 kN (t = 0 s),
//    within the limit 1000 kN"
//   "FAIL  ...: force |F| reaches 1200 kN (t = 0 s), past the limit 1000 kN: the test will
//    hold at that step"
//   "Column L, actuator 'lateral' (displacement control): stroke |s| limit 0.2 m, checked at
//    every step (it depends on the specimen's response)"
// Units: stroke and increment [m], force [kN] (the channels' units).
// Thread rules: GUI thread only.

#include "core/experimental/ActuatorLimitCheck.h"

#include <QCoreApplication>
#include <QString>

namespace hsmu::gui {

class ActuatorLimitText {
    Q_DECLARE_TR_FUNCTIONS(ActuatorLimitText)

public:
    static QString line(const std::string& element, const ActuatorLimitLine& l);
};

} // namespace hsmu::gui
