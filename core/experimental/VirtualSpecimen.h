#pragma once
// VirtualSpecimen: an in-process stand-in for a physical specimen and its actuator, behind
// the ExperimentalControl seam. It has its *own* true law (different from the numerical
// model's), and optionally:
//   - Gaussian measurement noise on force and deformation (seeded, portable);
//   - actuator tracking error: first-order lag  d_a[n+1] = d_a[n] + (d_t - d_a[n]) (1 - e^{-dt/tau}),
//     a pure delay of round(delay / dt) steps, or a servo-hydraulic actuator (rths::ServoActuator:
//     round(dt rate) ticks of its controller's loop toward the target per step; a stroke,
//     force or velocity limit of the plant holds the specimen naming the channel);
//   - a fracture event: from the first step at which the cumulative deformation sum |dd|
//     or the test time reaches its threshold, the force is multiplied by (1 - strengthLoss);
//   - its own interlock limits (like a lab controller): a target past them is refused and the
//     specimen holds.
// Time advances by dt at each commit().

#include "core/experimental/ExperimentalControl.h"
#include "core/experimental/SafetyLimits.h"
#include "core/rths/ServoActuator.h"
#include "core/hysteresis/HysteresisLaw.h"
#include "core/util/PortableRandom.h"

#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <optional>

namespace hsmu {

struct ActuatorModel {
    enum class Type { Ideal, Lag, Delay, ServoHydraulic };
    Type type = Type::Ideal;
    double timeConstant = 0.0; ///< first-order lag tau [s]
    double delay = 0.0;        ///< pure delay [s]
    /// ServoHydraulic: the plant under its servo-controller at its loop rate (docs/rths.md).
    rths::ServoActuatorSettings servo;
};

struct FractureEvent {
    double atCumulativeDeformation = std::numeric_limits<double>::infinity(); ///< sum |dd|
    double atTime = std::numeric_limits<double>::infinity();                  ///< [s]
    double strengthLoss = 0.5; ///< fraction of the force lost, in [0, 1]
    bool enabled() const
    {
        return atCumulativeDeformation < std::numeric_limits<double>::infinity() ||
               atTime < std::numeric_limits<double>::infinity();
    }
};

struct VirtualSpecimenOptions {
    double forceNoiseStd = 0.0;       ///< standard deviation of force noise (force units)
    double deformationNoiseStd = 0.0; ///< standard deviation of deformation noise
    std::uint64_t seed = 1;
    ActuatorModel actuator;
    FractureEvent fracture;
    SafetyLimits interlock;
};

class VirtualSpecimen final : public ExperimentalControl {
public:
    VirtualSpecimen(std::unique_ptr<HysteresisLaw> trueLaw, const VirtualSpecimenOptions& options);

    std::string description() const override;
    ControlResult prepare(double dt) override;
    ControlResult setTarget(double d) override;
    ControlResult measure(ControlMeasurement& out) override;
    ControlResult commit() override;
    void hold(const std::string& reason) override;
    void resume() override;
    /// commanded = the last target, measured = the measured deformation (with its noise),
    /// flags bit 0 = fractured (as hsmu-controller reports it); no held ticks (-1).
    std::optional<ActuatorChannels> actuatorChannels() const override;

    bool holding() const { return m_holding; }
    const std::string& holdReason() const { return m_holdReason; }
    bool fractured() const { return m_fractured; }
    double fractureTime() const { return m_fractureTime; }
    double time() const { return double(m_steps) * m_dt; } ///< [s] at the last commit
    /// Deformation the actuator actually reached at the last target (noise-free).
    double achievedDeformation() const { return m_achieved; }
    const HysteresisLaw& trueLaw() const { return *m_law; }

private:
    double actuatorResponse(double target);
    std::unique_ptr<HysteresisLaw> m_law;
    VirtualSpecimenOptions m_opt;
    PortableRandom m_random;
    double m_dt = 0.0;
    long m_steps = 0; // committed steps
    double m_lastTarget = 0.0;
    double m_achieved = 0.0, m_committedAchieved = 0.0;
    double m_cumulative = 0.0;
    std::deque<double> m_delayLine;
    std::optional<rths::ServoActuator> m_servo, m_servoTrial; // committed and trial (ServoHydraulic)
    bool m_holding = false;
    std::string m_holdReason;
    bool m_fractured = false;
    bool m_trialFractured = false;
    double m_fractureTime = std::numeric_limits<double>::quiet_NaN();
    std::optional<ActuatorChannels> m_channels;
};

} // namespace hsmu
