#pragma once
// VirtualActuatorLab: an in-process lab of N actuators behind an experimental setup, each
// simulated as a uniaxial material (as OpenFresco's expControl SimUniaxialMaterials): the
// actuator's stroke is the material's deformation, its measured force the material's force
// (docs/setups.md, "Virtual lab"). A displacement-controlled channel takes its command as the
// stroke; a force-controlled channel finds the stroke at which its material gives the
// commanded force (Newton on the law's tangent from the committed stroke, to
// |F - F_cmd| <= 1e-12 max(1, |F_cmd|), at most 50 iterations, else a fault naming the channel).
// Units: strokes [m], forces [kN] (the laws' own).
// Or the specimen as a whole behind the setup (SpecimenBehindSetup: e.g. a cantilever column
// with a Bouc-Wen hinge, elastic axial and P-Delta): the actuators carry no material then, and
// each step solves the specimen's equilibrium with the actuators' achieved commands (eq. W4).
// Each channel tracks its command with its actuator model (ActuatorTracker: ideal, lag,
// delay, servoHydraulic), once per step: the law or the specimen gets the achieved value.
// Hold: every channel keeps its committed stroke and force (trials are dropped) and new
// targets are refused until resume().

#include "core/experimental/ActuatorChannel.h"
#include "core/experimental/ActuatorTracker.h"
#include "core/experimental/SpecimenBehindSetup.h"
#include "core/experimental/ExperimentalControl.h"
#include "core/hysteresis/HysteresisLaw.h"

#include <memory>
#include <vector>

namespace hsmu {

struct VirtualActuator {
    std::string name;
    ActuatorMode mode = ActuatorMode::Displacement;
    /// The actuator-and-specimen material; null (and only then) with a whole specimen.
    std::unique_ptr<HysteresisLaw> law;
    ActuatorModel model; ///< how the actuator tracks its command (ideal by default)
};

class VirtualActuatorLab final : public ExperimentalControl {
public:
    /// Throws std::invalid_argument when empty, a law is null without a whole specimen or set
    /// with one, the whole specimen's actuator count or modes differ, a servoHydraulic model on
    /// a force-controlled channel.
    explicit VirtualActuatorLab(std::vector<VirtualActuator> actuators,
                                std::unique_ptr<SpecimenBehindSetup> whole = nullptr);

    std::string description() const override;
    ControlResult prepare(double dt) override;
    /// One-channel labs only (else a fault): setTargets({d}).
    ControlResult setTarget(double d) override;
    ControlResult measure(ControlMeasurement& out) override;
    ControlResult commit() override;
    void hold(const std::string& reason) override;
    void resume() override;

    int channelCount() const override { return static_cast<int>(m_act.size()); }
    ControlResult setTargets(const Eigen::VectorXd& commands) override;
    ControlResult measureChannels(Eigen::VectorXd& strokes, Eigen::VectorXd& forces) override;

    bool holding() const { return m_holding; }
    const std::string& holdReason() const { return m_holdReason; }
    /// Committed stroke [m] and force [kN] of channel i (where a holding actuator stands).
    double committedStroke(int i) const;
    double committedForce(int i) const;
    const VirtualActuator& actuator(int i) const { return m_act[i]; }
    /// The stiffness channel i sees [kN/m]: its law's initial or algorithmic tangent, or the
    /// whole specimen's SpecimenBehindSetup::channelStiffness.
    double channelStiffness(int i, bool initial) const;
    /// The whole specimen, or nullptr (one material per actuator).
    const SpecimenBehindSetup* wholeSpecimen() const { return m_whole.get(); }

private:
    ControlResult forceTrial(VirtualActuator& a, double force);
    void revertAll();
    std::vector<VirtualActuator> m_act;
    std::vector<ActuatorTracker> m_track;
    std::unique_ptr<SpecimenBehindSetup> m_whole;
    bool m_holding = false;
    std::string m_holdReason;
};

} // namespace hsmu
