// OpenFrescoControl's N actuator channels (OpenFrescoControl.h; docs/openfresco.md "Several
// actuator channels"): OpenFresco's sizes for a setup of N actuators, one trial frame and one
// daq reply per step, each channel's command in the entry of its control mode.
#include "comms/openfresco/OpenFrescoControl.h"

#include <cmath>

namespace hsmu::comms::of {

int OpenFrescoControl::channelCount() const {
    return m_opt.channelModes.empty() ? 1 : static_cast<int>(m_opt.channelModes.size());
}

std::optional<std::string> OpenFrescoControl::channelProblem() const {
    if (m_opt.channelModes.empty())
        return std::nullopt;
    const int n = channelCount();
    const std::string N = std::to_string(n);
    const OfSizes& s = m_opt.sizes;
    const std::string sizes = " (" + s.describe() + ")";
    if (m_protocol == OfProtocol::Adapter)
        return N + " actuator channels cannot travel over OpenSees' adapter element, which "
                   "carries one DOF: use simapp:// or generictcp://";
    if (s.ctrlSize(Resp::Disp) != n || s.daqSize(Resp::Disp) != n || s.daqSize(Resp::Force) != n)
        return N + " actuator channels need ctrl disp, daq disp and daq force of " + N +
               " (one per actuator, as OpenFresco's setup of " + N + " actuators)" + sizes;
    for (std::size_t i = 0; i < m_opt.channelModes.size(); ++i)
        if (m_opt.channelModes[i] == ActuatorMode::Force && s.ctrlSize(Resp::Force) != n)
            return "channel " + std::to_string(i + 1) +
                   " is force-controlled: its command travels in the ctrl force entries, so "
                   "ctrl force must be " +
                   N + sizes;
    return std::nullopt;
}

ControlResult OpenFrescoControl::setTargets(const Eigen::VectorXd& commands) {
    if (m_opt.channelModes.empty())
        return ExperimentalControl::setTargets(commands);
    if (commands.size() != channelCount())
        return ControlResult::fault(where() + ": specimen '" + m_element + "' has " +
                                    std::to_string(channelCount()) + " actuator channels, " +
                                    std::to_string(commands.size()) + " commands given");
    if (ControlResult r = trialAllowed(); !r.ok)
        return r;
    const OfSizes& s = m_opt.sizes;
    std::vector<double> ctrl(static_cast<std::size_t>(s.ctrlTotal()), 0.0);
    const auto disp = static_cast<std::size_t>(s.ctrlIndex(Resp::Disp) - 1);
    const auto force = static_cast<std::size_t>(s.ctrlIndex(Resp::Force) - 1);
    for (std::size_t i = 0; i < m_opt.channelModes.size(); ++i) {
        const double c = commands[static_cast<Eigen::Index>(i)];
        if (!std::isfinite(c))
            return ControlResult::fault(where() + ": the command of channel " +
                                        std::to_string(i + 1) + " is not finite");
        ctrl[(m_opt.channelModes[i] == ActuatorMode::Force ? force : disp) + i] = c;
    }
    if (ControlResult r = sendTrial(ctrl); !r.ok)
        return r;
    m_targets = commands;
    return ControlResult::success();
}

ControlResult OpenFrescoControl::measureChannels(Eigen::VectorXd& strokes,
                                                 Eigen::VectorXd& forces) {
    if (m_opt.channelModes.empty())
        return ExperimentalControl::measureChannels(strokes, forces);
    if (ControlResult r = readReply(); !r.ok)
        return r;
    const auto n = static_cast<Eigen::Index>(channelCount());
    const auto disp = static_cast<std::size_t>(m_opt.sizes.daqIndex(Resp::Disp));
    const auto force = static_cast<std::size_t>(m_opt.sizes.daqIndex(Resp::Force));
    strokes.resize(n);
    forces.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        strokes[i] = m_values[disp + static_cast<std::size_t>(i)];
        forces[i] = m_values[force + static_cast<std::size_t>(i)];
        if (!std::isfinite(strokes[i]) || !std::isfinite(forces[i]))
            return linkFault("the measured response of channel " + std::to_string(i + 1) +
                             " at step " + std::to_string(m_committed + 1) + " is not finite");
    }
    ActuatorChannels c;
    c.commanded = m_targets[0];
    c.measured = strokes[0];
    m_channels = c;
    m_measuredUncommitted = true;
    return ControlResult::success();
}

} // namespace hsmu::comms::of
