#pragma once
// VirtualActuatorLab: an in-process lab of N actuators behind an experimental setup, each
// simulated as a uniaxial material (as OpenFresco's expControl SimUniaxialMaterials): the
// actuator's stroke is the material's deformation, its measured force the material's force
// (docs/setups.md, "Virtual lab"). A displacement-controlled channel takes its command as the
// stroke; a force-controlled channel finds the stroke at which its material gives the
// commanded force (Newton on the law's tangent from the committed stroke, to
// |F - F_cmd| <= 1e-12 max(1, |F_cmd|), at most 50 iterations, else a fault naming the channel).
// Units: strokes [m], forces [kN] (the laws' own).
// Hold: every channel keeps its committed stroke and force (trials are dropped) and new
// targets are refused until resume().

#include "core/experimental/ActuatorChannel.h"
#include "core/experimental/ExperimentalControl.h"
#include "core/hysteresis/HysteresisLaw.h"

#include <memory>
#include <vector>

namespace hsmu {

struct VirtualActuator {
    std::string name;
    ActuatorMode mode = ActuatorMode::Displacement;
    std::unique_ptr<HysteresisLaw> law; ///< the actuator-and-specimen material, not null
};

class VirtualActuatorLab final : public ExperimentalControl {
public:
    /// Throws std::invalid_argument when empty or a law is null.
    explicit VirtualActuatorLab(std::vector<VirtualActuator> actuators);

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
    double committedStroke(int i) const { return m_act[i].law->committedDeformation(); }
    double committedForce(int i) const { return m_act[i].law->committedForce(); }
    const VirtualActuator& actuator(int i) const { return m_act[i]; }

private:
    ControlResult forceTrial(VirtualActuator& a, double force);
    std::vector<VirtualActuator> m_act;
    bool m_holding = false;
    std::string m_holdReason;
};

} // namespace hsmu
