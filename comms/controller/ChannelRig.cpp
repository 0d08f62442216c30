#include "comms/controller/ChannelRig.h"

#include "core/config/TestFactory.h"

#include <cmath>

namespace hsmu::comms {

namespace {

bool sameTargets(const std::vector<ChannelTarget>& a, const std::vector<ChannelTarget>& b) {
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].mode != b[i].mode || a[i].command != b[i].command)
            return false;
    return true;
}

std::uint8_t modeByte(ActuatorMode m) {
    return m == ActuatorMode::Force ? kChannelForce : kChannelDisplacement;
}

} // namespace

ChannelRig::ChannelRig(const ElementSpec& spec) : m_name(spec.name) {
    ElementSpec ideal = spec; // the actuator models run at the loop rate (ActuatorLoop)
    if (Link2dSpec* link = ideal.link2d ? &*ideal.link2d : nullptr)
        for (ActuatorSpec& a : link->actuators) {
            m_spec.push_back(a.channel);
            a.model = ActuatorModel{};
        }
    auto lab = buildVirtualSpecimen(ideal); // a VirtualActuatorLab for a link2d element
    m_lab.reset(static_cast<VirtualActuatorLab*>(lab.release()));
}

void ChannelRig::prepare(double dt) {
    m_lab->prepare(dt);
}

std::pair<double, double> ChannelRig::bounds(int i) const {
    const ActuatorChannelSpec& c = channel(i);
    if (c.mode == ActuatorMode::Force)
        return {c.limits.maxForce, 0.0};
    return {c.limits.maxDeformation, c.limits.maxIncrement};
}

std::string ChannelRig::channelName(std::size_t i) const {
    return "channel " + std::to_string(i + 1) + " '" + m_spec[i].name + "'";
}

std::vector<double> ChannelRig::committedCommands() const {
    std::vector<double> c(m_spec.size(), 0.0);
    if (m_last.valid)
        for (std::size_t i = 0; i < c.size(); ++i)
            c[i] = m_last.targets[i].command;
    return c;
}

std::vector<double> ChannelRig::committedAchieved() const {
    return m_last.valid ? m_last.achieved : std::vector<double>(m_spec.size(), 0.0);
}

std::optional<ErrorMsg> ChannelRig::refusal(const TargetsMsg& m) const {
    if (m.channels.size() != m_spec.size())
        return ErrorMsg{ErrorCode::ProtocolViolation, "specimen '" + m_name + "' has " +
                                                          std::to_string(m_spec.size()) +
                                                          " actuator channels, the targets carry " +
                                                          std::to_string(m.channels.size())};
    for (std::size_t i = 0; i < m_spec.size(); ++i) {
        const ChannelTarget& t = m.channels[i];
        const ActuatorChannelSpec& c = m_spec[i];
        if (t.mode != modeByte(c.mode))
            return ErrorMsg{ErrorCode::ProtocolViolation,
                            channelName(i) + " is under " + actuatorModeName(c.mode) +
                                " here; the console commands it in the other mode"};
        std::optional<std::string> why;
        if (!std::isfinite(t.command))
            why = "command is not a finite number";
        else if (c.mode == ActuatorMode::Force)
            why = c.limits.violationOfForce(t.command);
        else
            why =
                c.limits.violationOfTarget(t.command, m_lab->committedStroke(static_cast<int>(i)));
        if (why)
            return ErrorMsg{ErrorCode::Interlock, channelName(i) + ": " + *why};
    }
    return std::nullopt;
}

std::optional<ErrorMsg> ChannelRig::measuredViolation(const Eigen::VectorXd& s,
                                                      const Eigen::VectorXd& f) const {
    for (std::size_t i = 0; i < m_spec.size(); ++i) {
        const auto k = static_cast<Eigen::Index>(i);
        auto why = m_spec[i].limits.violationOfMeasuredDeformation(s[k]);
        if (!why)
            why = m_spec[i].limits.violationOfForce(f[k]);
        if (why)
            return ErrorMsg{ErrorCode::Interlock, channelName(i) + ": measured " + *why};
    }
    return std::nullopt;
}

std::variant<std::monostate, MeasurementsMsg, ErrorMsg> ChannelRig::admit(const TargetsMsg& m,
                                                                          std::uint64_t committed) {
    if (m.step == committed && m_last.valid) {
        if (!sameTargets(m.channels, m_last.targets))
            return ErrorMsg{ErrorCode::StateMismatch,
                            "step " + std::to_string(m.step) + " is committed with other targets"};
        MeasurementsMsg mm = m_last.measurement;
        mm.flags |= kFlagReplayed;
        return mm;
    }
    if (m.step != committed + 1)
        return ErrorMsg{ErrorCode::ProtocolViolation, "targets for step " + std::to_string(m.step) +
                                                          ", expected step " +
                                                          std::to_string(committed + 1)};
    if (m_trial.valid && m_trial.step == m.step && sameTargets(m.channels, m_trial.targets)) {
        MeasurementsMsg mm = m_trial.measurement;
        mm.flags |= kFlagReplayed;
        return mm;
    }
    m_trial.valid = false;
    m_pending = Step{};
    if (auto e = refusal(m))
        return *e;
    m_pending.step = m.step;
    m_pending.targets = m.channels;
    return std::monostate{};
}

std::variant<MeasurementsMsg, ErrorMsg> ChannelRig::measure(const std::vector<double>& achieved,
                                                            const std::vector<double>& commands) {
    Step step = std::move(m_pending);
    m_pending = Step{};
    Eigen::VectorXd a(channels()), s, f;
    for (int i = 0; i < channels(); ++i)
        a[i] = achieved.at(static_cast<std::size_t>(i));
    if (ControlResult r = m_lab->setTargets(a); !r.ok)
        return ErrorMsg{ErrorCode::SpecimenFault, "specimen '" + m_name + "': " + r.reason};
    m_lab->measureChannels(s, f);
    if (auto e = measuredViolation(s, f))
        return *e;
    step.valid = true;
    step.achieved = achieved;
    step.measurement = MeasurementsMsg{step.step, 0, {}};
    for (int i = 0; i < channels(); ++i)
        step.measurement.channels.push_back({s[i], f[i], commands.at(static_cast<std::size_t>(i))});
    m_trial = std::move(step);
    return m_trial.measurement;
}

std::string ChannelRig::replay(std::uint64_t step, const std::vector<double>& targets,
                               const std::vector<double>& achieved,
                               const std::vector<double>& strokes,
                               const std::vector<double>& forces) {
    const std::size_t n = m_spec.size();
    if (targets.size() != n || achieved.size() != n || strokes.size() != n || forces.size() != n)
        return "journaled step " + std::to_string(step) + " has " + std::to_string(targets.size()) +
               " channels, the specimen " + std::to_string(n);
    m_pending = Step{};
    m_pending.step = step;
    for (std::size_t i = 0; i < n; ++i)
        m_pending.targets.push_back({modeByte(m_spec[i].mode), targets[i]});
    const auto r = measure(achieved, targets);
    const auto* mm = std::get_if<MeasurementsMsg>(&r);
    bool same = mm != nullptr;
    for (std::size_t i = 0; same && i < n; ++i)
        same = mm->channels[i].stroke == strokes[i] && mm->channels[i].force == forces[i];
    if (!same || !commit().ok)
        return "replaying step " + std::to_string(step) +
               " does not give the recorded measurement (was the configuration changed?)";
    return {};
}

ControlResult ChannelRig::commit() {
    if (ControlResult r = m_lab->commit(); !r.ok)
        return r;
    m_last = m_trial;
    m_trial = Step{};
    return ControlResult::success();
}

void ChannelRig::hold(const std::string& reason) {
    m_trial = m_pending = Step{};
    m_lab->hold(reason);
}

void ChannelRig::resume() {
    m_lab->resume();
}

} // namespace hsmu::comms
