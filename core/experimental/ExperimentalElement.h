#pragma once
// ExperimentalElement: an element whose force comes from an ExperimentalControl (a specimen).
// Its generalized deformation q = sum c_k u_k (e.g. rotation u / L of a base spring under a
// rigid column) is the *target* sent to the control; the measured force closes the equation
// of motion (docs/method.md, Hybrid simulation). Safety limits are checked before anything
// is sent: a target past them is never issued; a measurement past them (deformation beyond
// the limit plus SafetyLimits::kMeasuredDeformationTolerance, force beyond the limit, or not
// finite) fails the trial as a limit, so the test holds and nothing is committed or updated
// from it.
// Two phases (sites, docs/configuration.md): sendTrial() checks the limits and sends the
// target; setTrial() then awaits the measurement (it sends first when sendTrial() was not
// called). beginCommit() / commit() likewise. Each element belongs to a site (site()): its
// round trip (target sent -> measurement received) and its control faults are kept for the
// site's health (SiteStatus.h).

#include "core/experimental/ExperimentalControl.h"
#include "core/experimental/SafetyLimits.h"
#include "core/structure/Element.h"

#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>

namespace hsmu {

class ExperimentalElement : public Element {
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
    virtual std::optional<std::string> targetViolation(const Eigen::VectorXd& uFull) const;
    // setTargetTime (Element.h): HybridTest calls it before targetViolation; a scheduled
    // command (a force-controlled actuator following a schedule, ActuatorChannel.h) is taken
    // at it.

    /// Check limits and send the target (no wait).
    ElementStatus sendTrial(const Eigen::VectorXd& uFull) override;
    /// Send the target unless sendTrial() did, then read the measurement.
    ElementStatus setTrial(const Eigen::VectorXd& uFull) override;
    ElementStatus beginCommit() override;
    double deformation() const override { return m_measured.deformation; }
    double force() const override { return m_measured.force; }
    double initialGeneralizedStiffness() const override { return m_k0; }
    ElementStatus commit() override;
    void revert() override;

    double commandedDeformation() const { return m_commanded; }
    const ControlMeasurement& measurement() const { return m_measured; }
    /// Basic DOF k's measured deformation and force (0 <= k < basicDofCount(); for a
    /// multi-DOF element recovered through its setup, docs/setups.md eq. S3-S4) and its
    /// commanded deformation: what online updating identifies on a chosen basic DOF
    /// (docs/configuration.md, updating.basicDof). One-DOF: measurement(), commandedDeformation().
    virtual ControlMeasurement basicMeasurement(int /*k*/) const { return m_measured; }
    virtual double commandedBasicDeformation(int /*k*/) const { return m_commanded; }
    ExperimentalControl& control() { return *m_control; }
    const ExperimentalControl& control() const { return *m_control; }

    std::string site() const override { return m_site; }
    const std::string& siteName() const { return m_site; }
    void setSite(std::string site) { m_site = std::move(site); }
    /// [s] target sent -> measurement received, of the last measured trial; NaN before.
    double lastRoundTrip() const { return m_roundTrip; }
    /// Control faults so far (send, measure or commit refused or lost) and the last one's text.
    int faults() const { return m_faults; }
    const std::string& lastFault() const { return m_lastFault; }
    const SafetyLimits& limits() const { return m_limits; }
    void setLimits(const SafetyLimits& limits) { m_limits = limits; }

protected:
    // For elements with several actuator channels (ExperimentalLink2d): the same fault count,
    // round-trip timing and committed bookkeeping as the one-channel path.
    ElementStatus fault(const ControlResult& r);
    void markSent() { m_sentAt = std::chrono::steady_clock::now().time_since_epoch().count(); }
    /// After a measurement: the round trip from markSent() (or the control's reply latency).
    void markMeasured();
    /// The reported (primary) commanded deformation and measurement.
    void setReported(double commanded, const ControlMeasurement& measured)
    {
        m_commanded = commanded;
        m_measured = measured;
    }

private:

    std::string m_typeName;
    std::string m_site = "controller";
    bool m_sent = false, m_commitSent = false;
    std::int64_t m_sentAt = 0; // steady_clock ticks [ns]
    double m_roundTrip = std::numeric_limits<double>::quiet_NaN();
    int m_faults = 0;
    std::string m_lastFault;
    std::unique_ptr<ExperimentalControl> m_control;
    SafetyLimits m_limits;
    double m_k0;
    double m_commanded = 0.0, m_lastCommitted = 0.0;
    ControlMeasurement m_measured, m_committedMeasured;
};

} // namespace hsmu
