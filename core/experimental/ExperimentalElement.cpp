#include "core/experimental/ExperimentalElement.h"

#include <chrono>
#include <cmath>

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

ElementStatus ExperimentalElement::fault(const ControlResult& r)
{
    ++m_faults;
    m_lastFault = r.reason;
    return ElementStatus::failure(name() + ": " + r.reason);
}

ElementStatus ExperimentalElement::sendTrial(const Eigen::VectorXd& uFull)
{
    m_sent = false;
    // Defence in depth: the test checks every target before sending any, and so do we.
    if (auto why = targetViolation(uFull))
        return ElementStatus::limitReached(*why);
    const double target = kinematicDeformation(uFull);
    markSent();
    if (ControlResult r = m_control->setTarget(target); !r.ok)
        return fault(r);
    m_commanded = target;
    m_sent = true;
    return ElementStatus::success();
}

ElementStatus ExperimentalElement::setTrial(const Eigen::VectorXd& uFull)
{
    if (!m_sent)
        if (ElementStatus s = sendTrial(uFull); !s.ok)
            return s;
    m_sent = false;
    ControlMeasurement m;
    if (ControlResult r = m_control->measure(m); !r.ok)
        return fault(r);
    markMeasured();
    m_measured = m;
    // The console believes no impossible measurement: past a limit the test holds (critical
    // alarm), the step is not committed, so no update is computed from the sample.
    if (auto why = m_limits.violationOfMeasuredDeformation(m.deformation))
        return ElementStatus::limitReached(name() + ": " + *why);
    if (auto why = m_limits.violationOfForce(m.force))
        return ElementStatus::limitReached(name() + ": " + *why);
    return ElementStatus::success();
}

void ExperimentalElement::markMeasured()
{
    const double latency = m_control->replyLatency();
    m_roundTrip = std::isfinite(latency)
                      ? latency
                      : 1e-9 * double(std::chrono::steady_clock::now().time_since_epoch().count() -
                                      m_sentAt);
}

ElementStatus ExperimentalElement::beginCommit()
{
    m_commitSent = false;
    if (ControlResult r = m_control->beginCommit(); !r.ok)
        return fault(r);
    m_commitSent = true;
    return ElementStatus::success();
}

ElementStatus ExperimentalElement::commit()
{
    m_commitSent = false;
    if (ControlResult r = m_control->commit(); !r.ok)
        return fault(r);
    m_lastCommitted = m_commanded;
    m_committedMeasured = m_measured;
    return ElementStatus::success();
}

void ExperimentalElement::revert()
{
    // A specimen cannot be un-deformed; reverting only forgets the unaccepted reading.
    m_sent = m_commitSent = false;
    m_commanded = m_lastCommitted;
    m_measured = m_committedMeasured;
}

} // namespace hsmu
