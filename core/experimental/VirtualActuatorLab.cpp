#include "core/experimental/VirtualActuatorLab.h"

#include <cmath>
#include <stdexcept>

namespace hsmu {

VirtualActuatorLab::VirtualActuatorLab(std::vector<VirtualActuator> actuators)
    : m_act(std::move(actuators))
{
    if (m_act.empty())
        throw std::invalid_argument("virtual actuator lab: no actuator");
    for (const auto& a : m_act)
        if (!a.law)
            throw std::invalid_argument("virtual actuator lab: actuator '" + a.name +
                                        "' has no material");
}

std::string VirtualActuatorLab::description() const
{
    std::string s = "virtual actuator lab (";
    for (std::size_t i = 0; i < m_act.size(); ++i)
        s += (i ? ", " : "") + m_act[i].name + ": " + m_act[i].law->lawName() + ", " +
             actuatorModeName(m_act[i].mode);
    return s + ")";
}

ControlResult VirtualActuatorLab::prepare(double dt)
{
    for (auto& a : m_act)
        a.law->setTimeIncrement(dt);
    return ControlResult::success();
}

ControlResult VirtualActuatorLab::setTarget(double d)
{
    if (m_act.size() != 1)
        return ControlResult::fault(description() + ": " + std::to_string(m_act.size()) +
                                    " actuator channels, one target given");
    return setTargets(Eigen::VectorXd::Constant(1, d));
}

ControlResult VirtualActuatorLab::forceTrial(VirtualActuator& a, double force)
{
    double s = a.law->committedDeformation();
    const double tol = 1e-12 * std::max(1.0, std::abs(force));
    for (int it = 0; it < 50; ++it) {
        if (a.law->setTrialDeformation(s) != LawStatus::Ok)
            break;
        const double r = a.law->trialForce() - force;
        if (std::abs(r) <= tol)
            return ControlResult::success();
        const double k = a.law->trialTangent();
        if (!(std::abs(k) > 0.0) || !std::isfinite(k))
            break;
        s -= r / k;
    }
    a.law->revert();
    return ControlResult::fault("actuator '" + a.name + "': no stroke gives the commanded force " +
                                std::to_string(force));
}

ControlResult VirtualActuatorLab::setTargets(const Eigen::VectorXd& commands)
{
    if (m_holding)
        return ControlResult::fault("lab holding: " + m_holdReason);
    if (commands.size() != channelCount())
        return ControlResult::fault(description() + ": " + std::to_string(channelCount()) +
                                    " channels, " + std::to_string(commands.size()) + " commands");
    for (int i = 0; i < channelCount(); ++i) {
        VirtualActuator& a = m_act[i];
        ControlResult r = ControlResult::success();
        if (a.mode == ActuatorMode::Force)
            r = forceTrial(a, commands[i]);
        else if (a.law->setTrialDeformation(commands[i]) != LawStatus::Ok)
            r = ControlResult::fault("actuator '" + a.name + "': material refused the stroke");
        if (!r.ok) { // nothing moves on a fault
            for (auto& b : m_act)
                b.law->revert();
            return r;
        }
    }
    return ControlResult::success();
}

ControlResult VirtualActuatorLab::measureChannels(Eigen::VectorXd& strokes, Eigen::VectorXd& forces)
{
    strokes.resize(channelCount());
    forces.resize(channelCount());
    for (int i = 0; i < channelCount(); ++i) {
        strokes[i] = m_act[i].law->trialDeformation();
        forces[i] = m_act[i].law->trialForce();
    }
    return ControlResult::success();
}

ControlResult VirtualActuatorLab::measure(ControlMeasurement& out)
{
    out.deformation = m_act[0].law->trialDeformation();
    out.force = m_act[0].law->trialForce();
    return ControlResult::success();
}

ControlResult VirtualActuatorLab::commit()
{
    if (m_holding)
        return ControlResult::fault("lab holding: " + m_holdReason);
    for (auto& a : m_act)
        a.law->commit();
    return ControlResult::success();
}

void VirtualActuatorLab::hold(const std::string& reason)
{
    for (auto& a : m_act) // every actuator back to (and kept at) its committed stroke
        a.law->revert();
    m_holding = true;
    m_holdReason = reason;
}

void VirtualActuatorLab::resume()
{
    m_holding = false;
    m_holdReason.clear();
}

} // namespace hsmu
