#pragma once
// ExperimentalElement: an element whose force comes from an ExperimentalControl (a specimen).
// Its generalized deformation q = sum c_k u_k (e.g. rotation u / L of a base spring under a
// rigid column) is the *target* sent to the control; the measured force closes the equation
// of motion (docs/method.md, Hybrid simulation). Safety limits are checked before anything
// is sent: a target past them is never issued; a measurement past them (deformation beyond
// the limit plus SafetyLimits::kMeasuredDeformationTolerance, force beyond the limit, or not
// finite) fails the trial as a limit, so the test holds and nothing is committed or updated
// from it.

#include "core/experimental/ExperimentalControl.h"
#include "core/experimental/SafetyLimits.h"
#include "core/structure/Element.h"

#include <memory>
#include <optional>

namespace hsmu {

class ExperimentalElement final : public Element {
public:
    /// typeName: the geometry it stands for ("rotationalBaseSpring", "lateralSpring", ...).
    /// initialStiffness: dP/dq of the specimen's initial model (for K0, damping and the
    /// stability check) in force per deformation units.
    ExperimentalElement(std::string name, std::string typeName, std::vector<DofTerm> terms,
                        std::unique_ptr<ExperimentalControl> control, const SafetyLimits& limits,
                        double initialStiffness);

    std::string typeName() const override { return m_typeName; }
    bool isExperimental() const override { return true; }

    /// Why the target for full displacements u must not be sent, if it must not.
    std::optional<std::string> targetViolation(const Eigen::VectorXd& uFull) const;

    /// Check limits, send the target, read the measurement.
    ElementStatus setTrial(const Eigen::VectorXd& uFull) override;
    double deformation() const override { return m_measured.deformation; }
    double force() const override { return m_measured.force; }
    double initialGeneralizedStiffness() const override { return m_k0; }
    ElementStatus commit() override;
    void revert() override;

    double commandedDeformation() const { return m_commanded; }
    const ControlMeasurement& measurement() const { return m_measured; }
    ExperimentalControl& control() { return *m_control; }
    const ExperimentalControl& control() const { return *m_control; }
    const SafetyLimits& limits() const { return m_limits; }
    void setLimits(const SafetyLimits& limits) { m_limits = limits; }

private:
    std::string m_typeName;
    std::unique_ptr<ExperimentalControl> m_control;
    SafetyLimits m_limits;
    double m_k0;
    double m_commanded = 0.0, m_lastCommitted = 0.0;
    ControlMeasurement m_measured, m_committedMeasured;
};

} // namespace hsmu
