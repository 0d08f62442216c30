#include "core/experimental/VirtualActuatorLab.h"

#include <cmath>
#include <stdexcept>

namespace hsmu {

VirtualActuatorLab::VirtualActuatorLab(std::vector<VirtualActuator> actuators,
                                       std::unique_ptr<SpecimenBehindSetup> whole)
    : m_act(std::move(actuators)), m_whole(std::move(whole))
{
    if (m_act.empty())
        throw std::invalid_argument("virtual actuator lab: no actuator");
    if (m_whole && m_whole->actuatorCount() != channelCount())
        throw std::invalid_argument("virtual actuator lab: " + m_whole->description() + " has " +
                                    std::to_string(m_whole->actuatorCount()) + " actuators, " +
                                    std::to_string(channelCount()) + " channels");
    for (const auto& a : m_act) {
        const std::string who = "virtual actuator lab: actuator '" + a.name + "' ";
        if (!m_whole && !a.law)
            throw std::invalid_argument(who + "has no material");
        if (m_whole && a.law)
            throw std::invalid_argument(who + "has a material, but the lab simulates the "
                                              "whole specimen");
        if (a.mode == ActuatorMode::Force && a.model.type == ActuatorModel::Type::ServoHydraulic)
            throw std::invalid_argument(who + "is force-controlled: a servoHydraulic model is "
                                              "a displacement servo (use ideal, lag or delay)");
        m_track.emplace_back(a.model);
    }
}

std::string VirtualActuatorLab::description() const
{
    std::string s = "virtual actuator lab (";
    if (m_whole)
        s += m_whole->description() + "; ";
    for (std::size_t i = 0; i < m_act.size(); ++i)
        s += (i ? ", " : "") + m_act[i].name + ": " +
             (m_act[i].law ? m_act[i].law->lawName() + ", " : std::string()) +
             actuatorModeName(m_act[i].mode) +
             (m_track[i].ideal() ? "" : std::string(", ") + actuatorModelName(m_act[i].model));
    return s + ")";
}

ControlResult VirtualActuatorLab::prepare(double dt)
{
    for (std::size_t i = 0; i < m_act.size(); ++i) {
        if (m_act[i].law)
            m_act[i].law->setTimeIncrement(dt);
        if (std::string why = m_track[i].prepare(dt); !why.empty())
            return ControlResult::fault("actuator '" + m_act[i].name + "': " + why);
    }
    if (m_whole)
        m_whole->setTimeIncrement(dt);
    return ControlResult::success();
}

double VirtualActuatorLab::committedStroke(int i) const
{
    return m_whole ? m_whole->committedStroke(i) : m_act[i].law->committedDeformation();
}

double VirtualActuatorLab::committedForce(int i) const
{
    return m_whole ? m_whole->committedForce(i) : m_act[i].law->committedForce();
}

double VirtualActuatorLab::channelStiffness(int i, bool initial) const
{
    if (m_whole)
        return m_whole->channelStiffness(i, initial);
    return initial ? m_act[i].law->initialTangent() : m_act[i].law->algorithmicTangent();
}

void VirtualActuatorLab::revertAll()
{
    for (std::size_t i = 0; i < m_act.size(); ++i) {
        if (m_act[i].law)
            m_act[i].law->revert();
        m_track[i].revert();
    }
    if (m_whole)
        m_whole->revert();
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
    Eigen::VectorXd achieved(channelCount());
    for (int i = 0; i < channelCount(); ++i) {
        VirtualActuator& a = m_act[i];
        std::string why;
        achieved[i] = m_track[i].trial(commands[i], why);
        ControlResult r = ControlResult::success();
        if (!why.empty())
            r = ControlResult::fault("actuator '" + a.name + "': " + why);
        else if (m_whole)
            continue;
        else if (a.mode == ActuatorMode::Force)
            r = forceTrial(a, achieved[i]);
        else if (a.law->setTrialDeformation(achieved[i]) != LawStatus::Ok)
            r = ControlResult::fault("actuator '" + a.name + "': material refused the stroke");
        if (!r.ok) { // nothing moves on a fault
            revertAll();
            return r;
        }
    }
    if (m_whole)
        if (std::string why = m_whole->solve(achieved); !why.empty()) {
            revertAll();
            return ControlResult::fault(why);
        }
    return ControlResult::success();
}

ControlResult VirtualActuatorLab::measureChannels(Eigen::VectorXd& strokes, Eigen::VectorXd& forces)
{
    strokes.resize(channelCount());
    forces.resize(channelCount());
    if (m_whole) {
        strokes = m_whole->strokes();
        forces = m_whole->forces();
        return ControlResult::success();
    }
    for (int i = 0; i < channelCount(); ++i) {
        strokes[i] = m_act[i].law->trialDeformation();
        forces[i] = m_act[i].law->trialForce();
    }
    return ControlResult::success();
}

ControlResult VirtualActuatorLab::measure(ControlMeasurement& out)
{
    Eigen::VectorXd s, f;
    measureChannels(s, f);
    out.deformation = s[0];
    out.force = f[0];
    return ControlResult::success();
}

ControlResult VirtualActuatorLab::commit()
{
    if (m_holding)
        return ControlResult::fault("lab holding: " + m_holdReason);
    for (std::size_t i = 0; i < m_act.size(); ++i) {
        if (m_act[i].law)
            m_act[i].law->commit();
        m_track[i].commit();
    }
    if (m_whole)
        m_whole->commit();
    return ControlResult::success();
}

void VirtualActuatorLab::hold(const std::string& reason)
{
    revertAll(); // every actuator back to (and kept at) its committed stroke and force
    m_holding = true;
    m_holdReason = reason;
}

void VirtualActuatorLab::resume()
{
    m_holding = false;
    m_holdReason.clear();
}

} // namespace hsmu
