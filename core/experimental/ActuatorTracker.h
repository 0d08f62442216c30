#pragma once
// ActuatorTracker: one actuator channel's tracking of its command, evaluated once per
// integration step of dt seconds (docs/setups.md, "Actuator models per channel"), in the
// channel's own units (a stroke [m] on a displacement-controlled channel, a force [kN] on a
// force-controlled one, whose force loop lags or waits the same way):
//   ideal:          a = c
//   lag:            a = a_c + (c - a_c) (1 - exp(-dt / tau))   (a_c the committed achieved value;
//                   the exact step of da/dt = (c - a) / tau with c held over the step)
//   delay:          a = the command of D = round(delay / dt) steps before (the committed
//                   position before the first D steps)
//   servoHydraulic: rths::ServoActuator advanced by dt toward c (its own loop ticks; a stroke,
//                   force or velocity limit of its plant is a fault naming the channel);
//                   displacement-controlled channels only.
// The same model, run at hsmu-controller's loop rate with the command held over a step, gives
// the same lag (exp(-dt/tau) = exp(-h/tau)^(dt/h)) and the same delay when delay / dt is whole.
// trial() starts from the committed state every time; commit() takes the last trial, revert()
// drops it (a hold keeps the committed position).

#include "core/experimental/VirtualSpecimen.h"

#include <deque>
#include <optional>
#include <string>

namespace hsmu {

class ActuatorTracker {
public:
    explicit ActuatorTracker(const ActuatorModel& model = {});

    /// Start stepping with dt [s] from the committed position; "" or why it cannot.
    std::string prepare(double dt);
    /// The value the actuator reaches this step for command c; "" in why, or the plant's
    /// limit it crossed (servoHydraulic).
    double trial(double command, std::string& why);
    void commit();
    void revert();
    double committed() const { return m_committed; }
    const ActuatorModel& model() const { return m_model; }
    bool ideal() const { return m_model.type == ActuatorModel::Type::Ideal; }

private:
    ActuatorModel m_model;
    double m_dt = 0.0;
    double m_committed = 0.0, m_trial = 0.0, m_trialCommand = 0.0;
    bool m_hasTrial = false;
    std::deque<double> m_line; // the last D commands, oldest first (delay)
    std::optional<rths::ServoActuator> m_servo, m_servoTrial;
};

/// "ideal", "lag", "delay" or "servoHydraulic".
const char* actuatorModelName(const ActuatorModel& m);

} // namespace hsmu
