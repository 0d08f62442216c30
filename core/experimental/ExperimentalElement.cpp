#include "core/experimental/ExperimentalElement.h"

namespace hsmu {

ExperimentalElement::ExperimentalElement(std::string name, std::string typeName,
                                         std::vector<DofTerm> terms,
                                         std::unique_ptr<ExperimentalControl> control,
                                         const SafetyLimits& limits, double initialStiffness)
    : Element(std::move(name), std::move(terms)), m_typeName(std::move(typeName)),
      m_control(std::move(control)), m_limits(limits), m_k0(initialStiffness)
{
}

std::optional<std::string> ExperimentalElement::targetViolation(const Eigen::VectorXd& uFull) const
{
    if (auto why = m_limits.violationOfTarget(kinematicDeformation(uFull), m_lastCommitted))
        return name() + ": " + *why;
    return std::nullopt;
}

ElementStatus ExperimentalElement::setTrial(const Eigen::VectorXd& uFull)
{
    // Defence in depth: the test checks every target before sending any, and so do we.
    if (auto why = targetViolation(uFull))
        return ElementStatus::limitReached(*why);
    const double target = kinematicDeformation(uFull);
    if (ControlResult r = m_control->setTarget(target); !r.ok)
        return ElementStatus::failure(name() + ": " + r.reason);
    m_commanded = target;
    ControlMeasurement m;
    if (ControlResult r = m_control->measure(m); !r.ok)
        return ElementStatus::failure(name() + ": " + r.reason);
    m_measured = m;
    // The console believes no impossible measurement: past a limit the test holds (critical
    // alarm), the step is not committed, so no update is computed from the sample.
    if (auto why = m_limits.violationOfMeasuredDeformation(m.deformation))
        return ElementStatus::limitReached(name() + ": " + *why);
    if (auto why = m_limits.violationOfForce(m.force))
        return ElementStatus::limitReached(name() + ": " + *why);
    return ElementStatus::success();
}

ElementStatus ExperimentalElement::commit()
{
    if (ControlResult r = m_control->commit(); !r.ok)
        return ElementStatus::failure(name() + ": " + r.reason);
    m_lastCommitted = m_commanded;
    m_committedMeasured = m_measured;
    return ElementStatus::success();
}

void ExperimentalElement::revert()
{
    // A specimen cannot be un-deformed; reverting only forgets the unaccepted reading.
    m_commanded = m_lastCommitted;
    m_measured = m_committedMeasured;
}

} // namespace hsmu
