#pragma once
// ChannelRig: a specimen of N actuator channels on hsmu-controller (a link2d element's
// actuators, docs/setups.md "hsmu-controller"): core's VirtualActuatorLab, built as the
// console builds its in-process lab (buildVirtualSpecimen): each actuator a uniaxial material
// (as OpenFresco's expControl SimUniaxialMaterials), or the specimen as a whole behind its
// setup (SpecimenBehindSetup), behind the native protocol's Targets / Measurements frames
// (docs/protocol.md, "Several actuator channels").
// The rig's lab is ideal: each channel's actuator model (ideal, lag, delay, servoHydraulic)
// runs in the station's ActuatorLoop of that channel at the controller's loop rate, with its
// own predictor-corrector (SpecimenStation.h), and the lab is evaluated once per step at the
// values the actuators reached (a force-controlled channel finds the stroke that gives its
// reached force). With ideal actuators that is the lab evaluated at the targets, bit for bit.
// Each channel's limits (its ActuatorChannelSpec, units: stroke [m], force [kN]) are checked
// here too, whatever the console checked: a displacement command past maxDeformation or
// maxIncrement from the channel's committed stroke, a force command past maxForce, a measured
// stroke past maxDeformation (+5 %, also on a force-controlled channel) or a measured force
// past maxForce -> an Interlock error naming the channel; the station then holds, and
// hold() puts every actuator back at its committed stroke and force. (The value each actuator
// reaches at every tick is checked by its ActuatorLoop: bounds() gives each loop its limits.)
// Step indices and idempotent re-sends as SpecimenStation's (the caller passes the count).
// Thread rules: one thread (the controller's io thread).

#include "comms/protocol/Messages.h"
#include "core/config/TestConfig.h"
#include "core/experimental/VirtualActuatorLab.h"

#include <memory>
#include <optional>
#include <variant>
#include <vector>

namespace hsmu::comms {

class ChannelRig {
public:
    /// spec: a link2d element with its actuators. Throws ConfigError when a material cannot
    /// be built.
    explicit ChannelRig(const ElementSpec& spec);

    int channels() const { return static_cast<int>(m_spec.size()); }
    /// Channel i's configuration (name, mode, limits), 0 <= i < channels().
    const ActuatorChannelSpec& channel(int i) const {
        return m_spec.at(static_cast<std::size_t>(i));
    }
    /// "channel 2 'lateral'".
    std::string channelName(std::size_t i) const;
    /// Channel i's per-tick bound and increment limit (ActuatorLoop::setLimits): stroke and
    /// increment on a displacement channel, force (no increment) on a force channel.
    std::pair<double, double> bounds(int i) const;
    void prepare(double dt);
    /// The last committed command of each channel (0 before the first step).
    std::vector<double> committedCommands() const;
    /// The value each actuator reached at the last committed step (0 before the first).
    std::vector<double> committedAchieved() const;

    /// Targets for step m.step: the measurement to answer again (the committed step, or the
    /// measured trial re-sent: kFlagReplayed), an error (Interlock: the station must hold;
    /// other codes refuse the frame and nothing moves), or monostate: the step may run (the
    /// rig keeps its targets until measure()). committed: the specimen's step count.
    std::variant<std::monostate, MeasurementsMsg, ErrorMsg> admit(const TargetsMsg& m,
                                                                  std::uint64_t committed);
    /// The admitted step's targets (empty when none is admitted).
    const std::vector<ChannelTarget>& admitted() const { return m_pending.targets; }
    /// Evaluate the admitted step with what each actuator reached and its last command: a
    /// measurement, or an error (Interlock / SpecimenFault: the station must hold).
    std::variant<MeasurementsMsg, ErrorMsg> measure(const std::vector<double>& achieved,
                                                    const std::vector<double>& commands);
    /// The last committed step's measurement (channels empty before the first).
    const MeasurementsMsg& committedMeasurement() const { return m_last.measurement; }
    /// Whether step is the measured, uncommitted trial (commit() may take it).
    bool hasTrial(std::uint64_t step) const { return m_trial.valid && m_trial.step == step; }
    /// Commit the trial; a fault's reason otherwise.
    ControlResult commit();
    /// Every actuator back at its committed stroke and force; the trial dropped.
    void hold(const std::string& reason);
    void resume();
    /// Re-apply a journaled step (targets, reached values, measured strokes and forces);
    /// "" or why the lab does not measure what was recorded.
    std::string replay(std::uint64_t step, const std::vector<double>& targets,
                       const std::vector<double>& achieved, const std::vector<double>& strokes,
                       const std::vector<double>& forces);
    const VirtualActuatorLab& lab() const { return *m_lab; }

private:
    struct Step {
        bool valid = false;
        std::uint64_t step = 0;
        std::vector<ChannelTarget> targets;
        std::vector<double> achieved;
        MeasurementsMsg measurement;
    };
    std::optional<ErrorMsg> refusal(const TargetsMsg& m) const;
    std::optional<ErrorMsg> measuredViolation(const Eigen::VectorXd& s,
                                              const Eigen::VectorXd& f) const;

    std::string m_name;
    std::vector<ActuatorChannelSpec> m_spec;
    std::unique_ptr<VirtualActuatorLab> m_lab;
    Step m_pending, m_trial, m_last;
};

} // namespace hsmu::comms
