// TcpControl's step frames for any channel count, and its actuator channels (TcpControl.h):
// one channel sends Target and takes Measurement; a specimen of N >= 2 channels takes one
// Targets frame per step (each channel's mode and command) and answers one Measurements frame
// (each channel's stroke, force and command); docs/protocol.md, "Several actuator channels".
// Everything else (step indices, deadlines, holds, emergency holds, reconnection and the
// settling of a lost commit) is TcpControl's one path for any channel count.
#include "comms/link/TcpControl.h"

#include "comms/link/LinkClient.h"

#include <chrono>

namespace hsmu::comms {

ControlResult TcpControl::sendTarget() {
    std::string error;
    m_commitSent = false;
    m_targetSentAt = std::chrono::steady_clock::now();
    const bool sent = multiChannel()
                          ? m_link->send(TargetsMsg{m_committed + 1, m_sentTargets}, error)
                          : m_link->send(TargetMsg{m_committed + 1, m_sentTarget}, error);
    if (!sent)
        return linkFault(error);
    m_awaitingMeasurement = true;
    return ControlResult::success();
}

ControlResult TcpControl::receiveMeasurement() {
    if (!m_awaitingMeasurement)
        return ControlResult::fault("TCP link: measure() without a target");
    m_awaitingMeasurement = false;
    std::string error;
    std::chrono::steady_clock::time_point arrived{};
    const auto m = m_link->receive(m_opt.stepDeadline, error, &arrived);
    if (!m)
        return noReply("no measurement for step " + std::to_string(m_committed + 1), error);
    if (const auto* e = std::get_if<ErrorMsg>(&*m))
        return refused(*e);
    std::uint64_t step = 0;
    if (const auto* mm = std::get_if<MeasurementMsg>(&*m); mm && !multiChannel()) {
        step = mm->step;
        m_last = *mm;
    } else if (const auto* mn = std::get_if<MeasurementsMsg>(&*m);
               mn && multiChannel() && mn->channels.size() == m_sentTargets.size()) {
        step = mn->step;
        m_lastN = *mn;
    } else
        return linkFault(std::string("expected a measurement of ") +
                         std::to_string(channelCount()) + " channel(s), received " +
                         messageTypeName(messageTypeOf(*m)));
    if (step != m_committed + 1)
        return linkFault("measurement for step " + std::to_string(step) + ", expected " +
                         std::to_string(m_committed + 1));
    m_latency = std::chrono::duration<double>(arrived - m_targetSentAt).count();
    m_measured = true;
    return ControlResult::success();
}


int TcpControl::channelCount() const {
    return multiChannel() ? static_cast<int>(m_opt.channelModes.size()) : 1;
}

ControlResult TcpControl::checkChannels(const HelloAckMsg& ack) {
    const std::size_t theirs = ack.channelCommands.empty() ? 1 : ack.channelCommands.size();
    if (theirs == static_cast<std::size_t>(channelCount()))
        return ControlResult::success();
    m_link->close();
    m_linkError = "specimen '" + m_element + "' has " + std::to_string(theirs) +
                  " actuator channel(s) at the controller, the configuration gives it " +
                  std::to_string(channelCount()) + "; nothing was configured or moved";
    return ControlResult::fault("controller at " + where() + ": " + m_linkError);
}

ControlResult TcpControl::setTargets(const Eigen::VectorXd& commands) {
    if (!multiChannel())
        return ExperimentalControl::setTargets(commands);
    if (commands.size() != channelCount())
        return ControlResult::fault(where() + ": specimen '" + m_element + "' has " +
                                    std::to_string(channelCount()) + " actuator channels, " +
                                    std::to_string(commands.size()) + " commands given");
    if (auto refusal = targetRefusal())
        return *refusal;
    m_sentTargets.resize(m_opt.channelModes.size());
    for (std::size_t i = 0; i < m_sentTargets.size(); ++i)
        m_sentTargets[i] = {m_opt.channelModes[i] == ActuatorMode::Force ? kChannelForce
                                                                          : kChannelDisplacement,
                            commands[static_cast<Eigen::Index>(i)]};
    return sendTarget();
}

ControlResult TcpControl::measureChannels(Eigen::VectorXd& strokes, Eigen::VectorXd& forces) {
    if (!multiChannel())
        return ExperimentalControl::measureChannels(strokes, forces);
    if (ControlResult r = receiveMeasurement(); !r.ok)
        return r;
    const auto n = static_cast<Eigen::Index>(m_lastN.channels.size());
    strokes.resize(n);
    forces.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        strokes[i] = m_lastN.channels[static_cast<std::size_t>(i)].stroke;
        forces[i] = m_lastN.channels[static_cast<std::size_t>(i)].force;
    }
    return ControlResult::success();
}

std::optional<ActuatorChannels> TcpControl::actuatorChannels() const {
    if (!m_measured)
        return std::nullopt;
    ActuatorChannels c;
    if (multiChannel()) {
        // N actuators have no one command for the element: each is in the record's channels
        // (docs/recording.md), as with the built-in lab (VirtualActuatorLab reports none).
        c.flags = m_lastN.flags;
        return c;
    }
    c.commanded = m_last.commanded;
    c.measured = m_last.deformation;
    c.heldTicks = m_last.heldTicks;
    c.flags = m_last.flags;
    return c;
}

} // namespace hsmu::comms
