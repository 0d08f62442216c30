// OfServer's DOFs for any channel count (OfServer.h): one-channel stations through the
// OfDofMap, or the N actuator channels of a link2d specimen served alone, with OpenFresco's
// sizes for a setup of N actuators (docs/openfresco.md "Several actuator channels").
#include "comms/controller/OfServer.h"

#include <cmath>
#include <cstdio>

namespace hsmu::comms {

using namespace of;

const ChannelRig* OfServer::channelRig() const {
    return m_stations.size() == 1 ? m_stations[0]->rig() : nullptr;
}

int OfServer::dofCount() const {
    const ChannelRig* rig = channelRig();
    return rig ? rig->channels() : m_opt.dofs.dofs();
}

std::optional<std::string> OfServer::channelSizesProblem(const OfSizes& s) const {
    const ChannelRig& rig = *channelRig();
    const int n = rig.channels();
    const std::string N = std::to_string(n);
    const std::string who =
        "specimen '" + m_stations[0]->name() + "' has " + N + " actuator channels, ";
    if (s.ctrlSize(Resp::Disp) != n)
        return who + "so ctrl disp must be " + N + " (one stroke per actuator, as OpenFresco's " +
               "setup of " + N + " actuators), not " + std::to_string(s.ctrlSize(Resp::Disp));
    std::string forced;
    for (int i = 0; i < n; ++i)
        if (rig.channel(i).mode == ActuatorMode::Force)
            forced += (forced.empty() ? "" : ", ") + std::to_string(i + 1) + " '" +
                      rig.channel(i).name + "'";
    const int f = s.ctrlSize(Resp::Force);
    if (!forced.empty() && f != n)
        return who + "of which channel(s) " + forced +
               " are force-controlled: their commands travel in the ctrl force entries, so "
               "ctrl force must be " +
               N + ", not " + std::to_string(f);
    if (f != 0 && f != n)
        return who + "so ctrl force must be 0 or " + N + ", not " + std::to_string(f);
    return std::nullopt;
}

bool OfServer::trialChannels(const std::vector<double>& frame, std::string& why) {
    const ChannelRig& rig = *channelRig();
    SpecimenStation& st = *m_stations[0];
    const std::size_t n = static_cast<std::size_t>(rig.channels());
    const auto disp = static_cast<std::size_t>(m_sizes.ctrlIndex(Resp::Disp));
    const auto force = static_cast<std::size_t>(m_sizes.ctrlIndex(Resp::Force));
    TargetsMsg t{st.committedSteps() + 1, std::vector<ChannelTarget>(n)};
    for (std::size_t i = 0; i < n; ++i) {
        const bool byForce = rig.channel(static_cast<int>(i)).mode == ActuatorMode::Force;
        t.channels[i].mode = byForce ? kChannelForce : kChannelDisplacement;
        t.channels[i].command = frame[(byForce ? force : disp) + i];
        m_ctrl[i] = frame[disp + i];
        if (!std::isfinite(t.channels[i].command)) {
            why = "the trial " + std::string(byForce ? "force" : "stroke") + " of channel " +
                  std::to_string(i + 1) + " '" + rig.channel(static_cast<int>(i)).name +
                  "' is not finite";
            return false;
        }
    }
    std::vector<std::optional<Message>> result{st.targets(t)};
    if (!tickUntilMeasured(result, why)) // real time: each channel's loop at the loop rate
        return false;
    const auto* mm = result[0] ? std::get_if<MeasurementsMsg>(&*result[0]) : nullptr;
    if (!mm) {
        const auto* e = result[0] ? std::get_if<ErrorMsg>(&*result[0]) : nullptr;
        why = e ? e->reason : "specimen '" + st.name() + "' gave no measurements";
        return false;
    }
    m_measuredN = *mm;
    m_haveTrial = true;
    return true;
}

void OfServer::measuredDofs(std::vector<double>& disp, std::vector<double>& force) const {
    if (channelRig()) {
        const std::size_t n = static_cast<std::size_t>(dofCount());
        disp.assign(n, 0.0);
        force.assign(n, 0.0);
        for (std::size_t i = 0; i < n && i < m_measuredN.channels.size(); ++i) {
            disp[i] = m_measuredN.channels[i].stroke;
            force[i] = m_measuredN.channels[i].force;
        }
        return;
    }
    std::vector<double> dm(m_stations.size()), fm(m_stations.size());
    for (std::size_t s = 0; s < m_stations.size(); ++s) {
        dm[s] = m_measured[s].deformation;
        fm[s] = m_measured[s].force;
    }
    disp = m_opt.dofs.measuredDisp(m_ctrl, dm, m_commanded);
    force = m_opt.dofs.forces(fm);
}

void OfServer::holdAfterSession(const std::string& why) {
    m_haveTrial = false; // an uncommitted trial is dropped
    for (auto& st : m_stations) {
        st->hold(why);
        std::string at = "step " + std::to_string(st->committedSteps());
        if (const ChannelRig* rig = st->rig()) {
            const std::vector<double> c = rig->committedCommands();
            for (std::size_t i = 0; i < c.size(); ++i) {
                char v[40];
                std::snprintf(v, sizeof v, "%.17g", c[i]);
                at += std::string(i == 0 ? ", channel commands [" : ", ") + v;
            }
            at += "]";
        }
        log("specimen '" + st->name() + "' holds at its committed " + at + " (" + why + ")");
    }
}

} // namespace hsmu::comms
