#pragma once
// RthsLoop: one tick of real-time hybrid simulation at the loop period h = 1 / rate
// (docs/rths.md, "The loop"), the same code at the real-time thread's pace and at the simulated
// pace (fast, for CI and the benchmark). At tick k (t = k h):
//
//   1. sensors sample the plant: xm = Q_AD(x + n_x), fm = F + n_f                       (L1)
//   2. the numerical substructure's state at t gives the target (x, v, a at the specimen's DOF)
//   3. compensation: x* = comp(target); servo-controller: u = Q_DA(PID(x* - xm))          (L2)
//   4. the plant integrates [t, t + h] with u held (RK4)
//   5. the numerical substructure integrates [t, t + h] (RK4, ag interpolated) with fe = the
//      force measured forceDelay ticks earlier, held over the step (the benchmark: 1)     (L3)
//
// Limits (stroke, force, velocity of the plant; the command's stroke) are checked every tick:
// a breach stops the loop (holding()) with the channel, value and tick named.
// SI units: m, N, kg, s.

#include "core/groundmotion/GroundMotion.h"
#include "core/rths/Compensation.h"
#include "core/rths/DamperTwin.h"
#include "core/rths/DiscreteFilters.h"
#include "core/rths/Partition.h"
#include "core/rths/ServoHydraulicPlant.h"
#include "core/util/PortableRandom.h"

#include <Eigen/Core>

#include <cstdint>
#include <deque>
#include <optional>
#include <string>

namespace hsmu::rths {

struct SensorSettings {
    bool noise = true;
    double displacementNoise = 1.6e-5; ///< RMS [m]
    double forceNoise = 2.2;           ///< RMS [N]
    double quantum = 3.81e-6;          ///< A/D and D/A step of the displacement channels [m] (0: none)
    std::uint64_t seed = 1;
};

struct ActuatorLimits {
    double stroke = 7e-3;   ///< |x| and |command| [m]
    double force = 8900.0;  ///< |F| [N]
    double velocity = 0.3;  ///< |x'| [m/s]
};

struct RthsSettings {
    double rate = 4096.0; ///< loop rate [Hz]
    PlantParameters plant;
    PidGains pid;
    CompensationSettings compensation;
    SensorSettings sensors;
    ActuatorLimits limits;
    int forceDelay = 1; ///< ticks between measuring fe and its use (L3)
    DamperSettings damper; ///< an MR damper in the specimen and its twin (DamperTwin.h)
};

/// What one tick produced (all at t = k h).
struct RthsTick {
    double time = 0.0;
    double desired = 0.0;  ///< y: the numerical substructure's displacement at the specimen [m]
    double command = 0.0;  ///< x*: after compensation [m]
    double valve = 0.0;    ///< u: the servo-controller's output [m]
    double measured = 0.0; ///< xm [m]
    double force = 0.0;    ///< fm [N]
    Eigen::VectorXd floors; ///< the hybrid response: the numerical displacements, xm at the specimen
    double damperForce = 0.0; ///< the damper's load cell [N] (with a damper; else 0)
    double twinForce = 0.0;   ///< the twin's force over this tick [N] (with a damper; else 0)
};

class RthsLoop {
public:
    RthsLoop(const Partition& partition, const GroundMotion& groundMotion,
             const RthsSettings& settings);

    /// One tick (L1-L5); false once holding (nothing advanced).
    bool tick();
    bool holding() const { return !m_hold.empty(); }
    /// Clear the loop's own hold (a limit) when its channel is back inside the limits; "" when
    /// the next tick may run (also when not holding), else why not (docs/rths.md, "Hold and
    /// resume"): the plant's stroke, force and velocity re-checked now; a command beyond the
    /// stroke is never cleared (the state that gave it has not moved since).
    std::string resume();
    const std::string& holdReason() const { return m_hold; }
    const RthsTick& last() const { return m_last; }
    long ticks() const { return m_k; }
    double period() const { return m_h; }
    const Compensator& compensator() const { return m_comp; }
    const ServoHydraulicPlant& plant() const { return m_plant; }
    /// Apply a twin update now, between tick ticks() - 1 and ticks() (DamperTwin::apply; refused
    /// without a damper twin).
    UpdateEvent updateTwin(const TwinUpdate& u);
    /// The damper's twin (nullptr without a damper).
    const DamperTwin* twin() const { return m_twin ? &*m_twin : nullptr; }

private:
    double sense(double value, double rms);
    double quantize(double v) const;
    void checkCommand(double command); ///< the stroke limit, before the plant moves
    void checkPlant();                 ///< stroke, force and velocity, after it moved
    void holdAt(const std::string& why);
    Eigen::VectorXd accelerationOf(const Eigen::VectorXd& x, const Eigen::VectorXd& v, double ag,
                                   double fe) const;

    Partition m_p;
    GroundMotion m_ag;
    RthsSettings m_s;
    double m_h;
    ServoHydraulicPlant m_plant;
    Pid m_pid;
    Compensator m_comp;
    PortableRandom m_random;
    Eigen::MatrixXd m_mnInv;
    Eigen::VectorXd m_x, m_v; // numerical substructure
    std::deque<double> m_forces; // measured forces, newest last
    std::optional<MrDamper> m_damper;  // the physical damper in the specimen
    std::optional<DamperTwin> m_twin;  // its twin in the numerical substructure
    double m_twinForce = 0.0;          // held over the tick [N]
    long m_k = 0;
    RthsTick m_last;
    std::string m_hold;
    bool m_commandHold = false; // the hold is the command's stroke (before the plant moved)
};

/// The first limit the plant is past, as a sentence naming the channel and its value; "".
std::string plantLimitBreach(const ServoHydraulicPlant& plant, const ActuatorLimits& limits);

/// The reference structure's response at the loop's ticks (RK4 at h, as the loop): row k,
/// column i = floor i's displacement [m] at t = k h, for ticks 0 .. n-1.
Eigen::MatrixXd referenceResponse(const LinearStructure& reference, const GroundMotion& ag,
                                  double h, long n);

} // namespace hsmu::rths
