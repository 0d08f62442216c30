#pragma once
// ChannelRig: a specimen of N actuator channels on hsmu-controller (a link2d element's
// actuators, docs/setups.md "hsmu-controller"): core's VirtualActuatorLab, built as the
// console builds its in-process lab (buildVirtualSpecimen): each actuator a uniaxial material
// (as OpenFresco's expControl SimUniaxialMaterials), or the specimen as a whole behind its
// setup (SpecimenBehindSetup), behind the native protocol's Targets / Measurements frames
// (docs/protocol.md, "Several actuator channels").
// Each channel tracks its command with its configured actuator model (ActuatorTracker: ideal,
// lag, delay, servoHydraulic), evaluated once per step as in the console's lab, so both give
// the same measurements; a force-controlled channel finds the stroke that gives its (tracked)
// force.
// Each channel's limits (its ActuatorChannelSpec, units: stroke [m], force [kN]) are checked
// here too, whatever the console checked: a displacement command past maxDeformation or
// maxIncrement from the channel's committed stroke, a force command past maxForce, a measured
// stroke past maxDeformation (+5 %, also on a force-controlled channel) or a measured force
// past maxForce -> an Interlock error naming the channel; the station then holds, and
// hold() puts every actuator back at its committed stroke and force.
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
    void prepare(double dt);
    /// The last committed command of each channel (0 before the first step).
    std::vector<double> committedCommands() const;
    /// A measurement, or an error: Interlock / SpecimenFault mean the station must hold (trip);
    /// other codes refuse the frame and nothing moves. committed: the specimen's step count.
    std::variant<MeasurementsMsg, ErrorMsg> target(const TargetsMsg& m, std::uint64_t committed);
    /// Whether step is the measured, uncommitted trial (commit() may take it).
    bool hasTrial(std::uint64_t step) const { return m_trial.valid && m_trial.step == step; }
    /// Commit the trial; a fault's reason otherwise.
    ControlResult commit();
    /// Every actuator back at its committed stroke and force; the trial dropped.
    void hold(const std::string& reason);
    void resume();
    const VirtualActuatorLab& lab() const { return *m_lab; }

private:
    struct Step {
        bool valid = false;
        std::uint64_t step = 0;
        std::vector<ChannelTarget> targets;
        MeasurementsMsg measurement;
    };
    std::optional<ErrorMsg> refusal(const TargetsMsg& m) const;
    std::optional<ErrorMsg> measuredViolation(const Eigen::VectorXd& s, const Eigen::VectorXd& f) const;
    std::string channelName(std::size_t i) const;

    std::string m_name;
    std::vector<ActuatorChannelSpec> m_spec;
    std::unique_ptr<VirtualActuatorLab> m_lab;
    Step m_trial, m_last;
};

} // namespace hsmu::comms
