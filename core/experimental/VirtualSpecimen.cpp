#include "core/experimental/VirtualSpecimen.h"

#include <cmath>
#include <cstdio>

namespace hsmu {

VirtualSpecimen::VirtualSpecimen(std::unique_ptr<HysteresisLaw> trueLaw,
                                 const VirtualSpecimenOptions& options)
    : m_law(std::move(trueLaw)), m_opt(options), m_random(options.seed)
{
}

std::string VirtualSpecimen::description() const
{
    char buf[200];
    const char* act = m_opt.actuator.type == ActuatorModel::Type::Lag     ? "lag"
                      : m_opt.actuator.type == ActuatorModel::Type::Delay ? "delay"
                      : m_opt.actuator.type == ActuatorModel::Type::ServoHydraulic
                          ? "servo-hydraulic"
                          : "ideal";
    std::snprintf(buf, sizeof buf, "virtual specimen (%s law, force noise std %.3g, %s actuator%s)",
                  m_law->lawName().c_str(), m_opt.forceNoiseStd, act,
                  m_opt.fracture.enabled() ? ", fracture event" : "");
    return buf;
}

ControlResult VirtualSpecimen::prepare(double dt)
{
    if (!(dt > 0.0))
        return ControlResult::fault("virtual specimen: dt must be > 0");
    m_dt = dt;
    m_law->setTimeIncrement(dt); // a rate-dependent true law steps with the test
    m_delayLine.clear();
    if (m_opt.actuator.type == ActuatorModel::Type::Delay) {
        const auto steps = static_cast<std::size_t>(std::lround(m_opt.actuator.delay / dt));
        m_delayLine.assign(steps, m_committedAchieved);
    }
    if (m_opt.actuator.type == ActuatorModel::Type::ServoHydraulic) {
        try {
            m_servo.emplace(m_opt.actuator.servo);
        } catch (const std::exception& e) {
            return ControlResult::fault(std::string("virtual specimen: ") + e.what());
        }
        m_servo->reset(m_committedAchieved);
    }
    return ControlResult::success();
}

void VirtualSpecimen::hold(const std::string& reason)
{
    m_holding = true;
    m_holdReason = reason;
    m_law->revert();
    m_achieved = m_committedAchieved;
}

void VirtualSpecimen::resume()
{
    m_holding = false;
    m_holdReason.clear();
}

double VirtualSpecimen::actuatorResponse(double target)
{
    switch (m_opt.actuator.type) {
    case ActuatorModel::Type::Lag: {
        if (!(m_opt.actuator.timeConstant > 0.0))
            return target;
        const double k = 1.0 - std::exp(-m_dt / m_opt.actuator.timeConstant);
        return m_committedAchieved + (target - m_committedAchieved) * k;
    }
    case ActuatorModel::Type::Delay:
        return m_delayLine.empty() ? target : m_delayLine.front();
    case ActuatorModel::Type::ServoHydraulic:
        if (!m_servo)
            return target;
        m_servoTrial = *m_servo;
        return m_servoTrial->advance(target, m_dt);
    case ActuatorModel::Type::Ideal:
        break;
    }
    return target;
}

ControlResult VirtualSpecimen::setTarget(double d)
{
    if (m_holding)
        return ControlResult::fault("virtual specimen is holding: " + m_holdReason);
    if (auto why = m_opt.interlock.violationOfTarget(d, m_lastTarget)) {
        hold("interlock: " + *why);
        return ControlResult::fault(m_holdReason);
    }
    m_lastTarget = d;
    m_achieved = actuatorResponse(d);
    if (m_servoTrial) {
        if (const std::string why = m_servoTrial->limitBreach(); !why.empty()) {
            hold(why);
            return ControlResult::fault(m_holdReason);
        }
    }
    if (m_law->setTrialDeformation(m_achieved) != LawStatus::Ok) {
        hold("specimen law did not converge at deformation " + std::to_string(m_achieved));
        return ControlResult::fault(m_holdReason);
    }
    const double cumulative = m_cumulative + std::abs(m_achieved - m_committedAchieved);
    // Time from a step count (not a running sum) so that atTime = 0.1 with dt = 0.01 fires at
    // step 10, not 11; the 1e-9 dt slack absorbs the rounding of the product.
    const double trialTime = double(m_steps + 1) * m_dt;
    m_trialFractured = m_fractured || cumulative >= m_opt.fracture.atCumulativeDeformation ||
                       trialTime >= m_opt.fracture.atTime - 1e-9 * m_dt;
    return ControlResult::success();
}

ControlResult VirtualSpecimen::measure(ControlMeasurement& out)
{
    if (m_holding)
        return ControlResult::fault("virtual specimen is holding: " + m_holdReason);
    const double factor = m_trialFractured ? 1.0 - m_opt.fracture.strengthLoss : 1.0;
    out.deformation = m_achieved;
    out.force = m_law->trialForce() * factor;
    if (m_opt.deformationNoiseStd > 0.0)
        out.deformation += m_opt.deformationNoiseStd * m_random.normal();
    if (m_opt.forceNoiseStd > 0.0)
        out.force += m_opt.forceNoiseStd * m_random.normal();
    ActuatorChannels c;
    c.commanded = m_lastTarget;
    c.measured = out.deformation;
    c.flags = m_trialFractured ? 1 : 0;
    m_channels = c;
    if (auto why = m_opt.interlock.violationOfForce(out.force)) {
        hold("interlock: " + *why);
        return ControlResult::fault(m_holdReason);
    }
    return ControlResult::success();
}

std::optional<ActuatorChannels> VirtualSpecimen::actuatorChannels() const
{
    return m_channels;
}

ControlResult VirtualSpecimen::commit()
{
    if (m_holding)
        return ControlResult::fault("virtual specimen is holding: " + m_holdReason);
    m_law->commit();
    m_cumulative += std::abs(m_achieved - m_committedAchieved);
    m_committedAchieved = m_achieved;
    ++m_steps;
    if (m_trialFractured && !m_fractured) {
        m_fractured = true;
        m_fractureTime = time();
    }
    if (m_opt.actuator.type == ActuatorModel::Type::Delay && !m_delayLine.empty()) {
        m_delayLine.pop_front();
        m_delayLine.push_back(m_lastTarget);
    }
    if (m_servoTrial)
        m_servo = m_servoTrial;
    return ControlResult::success();
}

} // namespace hsmu
