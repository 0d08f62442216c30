#pragma once
// ServoActuator: the virtual lab's servo-hydraulic actuator under its servo-controller's inner
// loop (docs/rths.md, "The actuator in the virtual lab"): per tick of the controller's loop
// (h = 1 / rate), the position command passes the optional phase lead, the PID closes the loop
// on the measured (quantized) position, and the plant (ServoHydraulicPlant, eqs. P1-P3) moves.
// A value type: a trial can be run on a copy and adopted (VirtualSpecimen's setTarget/commit).
// Positions in metres at the plant; callers in specimen units convert with `metresPerUnit`.

#include "core/rths/Compensation.h"
#include "core/rths/DiscreteFilters.h"
#include "core/rths/RthsLoop.h"
#include "core/rths/ServoHydraulicPlant.h"

#include <string>

namespace hsmu::rths {

struct ServoActuatorSettings {
    double rate = 1024.0;        ///< the controller's loop rate [Hz]
    PlantParameters plant;
    PidGains pid;
    LeadSettings lead;           ///< a phase lead on the command (disabled by default)
    double quantum = 0.0;        ///< A/D step of the position feedback [m] (0: none)
    ActuatorLimits limits;       ///< stroke [m], force [N], velocity [m/s]
    double metresPerUnit = 1.0;  ///< actuator metres per unit of specimen deformation
};

class ServoActuator {
public:
    explicit ServoActuator(const ServoActuatorSettings& s = {});

    /// At rest at position x [specimen units], the controller's integrator holding it.
    void reset(double x);
    /// One loop tick toward command c [specimen units]; returns the position [specimen units].
    double tick(double command);
    /// Ticks until t has advanced by dt [s] (round(dt rate), at least 1) toward command c.
    double advance(double command, double dt);
    double position() const { return m_plant.displacement() / m_s.metresPerUnit; }
    /// The first limit the plant is past, as a sentence naming the channel; "" when none.
    std::string limitBreach() const;
    const ServoActuatorSettings& settings() const { return m_s; }

private:
    ServoActuatorSettings m_s;
    ServoHydraulicPlant m_plant;
    Pid m_pid;
    FirstOrderSection m_lead;
    double m_h;
};

} // namespace hsmu::rths
