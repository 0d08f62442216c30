#include "comms/controller/SpecimenStation.h"

#include "core/config/TestFactory.h"
#include "core/hysteresis/HysteresisLaw.h"

#include <cmath>
#include <cstdio>

namespace hsmu::comms {

namespace {

double tighter(double a, double b) {
    const bool aOn = a > 0.0 && std::isfinite(a), bOn = b > 0.0 && std::isfinite(b);
    if (aOn && bOn)
        return std::min(a, b);
    return aOn ? a : bOn ? b : std::numeric_limits<double>::infinity();
}

/// The limits no client can loosen: the element's `limits` and the specimen's `interlock`,
/// each the tighter of the two.
SafetyLimits ownLimits(const ElementSpec& spec) {
    const SafetyLimits& a = spec.limits;
    const SafetyLimits& b = spec.specimen.options.interlock;
    SafetyLimits l;
    l.maxDeformation = tighter(a.maxDeformation, b.maxDeformation);
    l.maxForce = tighter(a.maxForce, b.maxForce);
    l.maxIncrement = tighter(a.maxIncrement, b.maxIncrement);
    return l;
}

ErrorMsg error(ErrorCode code, std::string reason) {
    return ErrorMsg{code, std::move(reason)};
}

} // namespace

SpecimenStation::SpecimenStation(int index, const ElementSpec& spec,
                                 const ControllerSettings& settings, Pace pace,
                                 StateJournal* journal)
    : m_index(index), m_spec(spec), m_settings(settings), m_pace(pace), m_journal(journal),
      m_limits(ownLimits(spec)) {
    makeSpecimen();
    makeLoops();
}

SpecimenStation::~SpecimenStation() = default;

void SpecimenStation::makeSpecimen() {
    if (m_spec.link2d) {
        m_rig = std::make_unique<ChannelRig>(m_spec);
        if (m_dt > 0.0)
            m_rig->prepare(m_dt);
        return;
    }
    // The station models the actuator (at the loop rate) and the interlock itself; the core
    // specimen contributes the law, the noise and the fracture event.
    VirtualSpecimenOptions o = m_spec.specimen.options;
    o.actuator = ActuatorModel{};
    o.interlock = SafetyLimits{};
    m_specimen = std::make_unique<VirtualSpecimen>(
        buildLaw(m_spec.specimen.trueMaterial, "element '" + m_spec.name + "' specimen"), o);
    if (m_dt > 0.0)
        m_specimen->prepare(m_dt);
}

void SpecimenStation::makeLoops() {
    if (!m_rig) {
        m_loops.emplace_back(m_spec.specimen.options.actuator, m_settings.rate);
        m_loops.back().setLimits(m_limits.maxDeformation, m_limits.maxIncrement);
        return;
    }
    for (int i = 0; i < m_rig->channels(); ++i) {
        const bool force = m_rig->channel(i).mode == ActuatorMode::Force;
        m_loops.emplace_back(m_spec.link2d->actuators[static_cast<std::size_t>(i)].model,
                             m_settings.rate,
                             m_rig->channelName(static_cast<std::size_t>(i)) +
                                 (force ? ": actuator force |F|" : ": actuator stroke |d|"));
        const auto [bound, increment] = m_rig->bounds(i);
        m_loops.back().setLimits(bound, increment);
    }
}

double SpecimenStation::initialStiffness() const {
    return m_rig ? m_rig->lab().channelStiffness(0, true) : m_specimen->trueLaw().initialTangent();
}

double SpecimenStation::tangentStiffness() const {
    return m_rig ? m_rig->lab().channelStiffness(0, false)
                 : m_specimen->trueLaw().algorithmicTangent();
}

HelloAckMsg SpecimenStation::status() const {
    HelloAckMsg a;
    a.committedSteps = m_committed;
    a.lastCommittedTarget = m_loops.front().committedTarget();
    a.holding = m_holding;
    a.element = m_spec.name;
    a.holdReason = m_holdReason;
    if (m_rig) {
        a.channelCommands = m_rig->committedCommands();
        // The deformation a one-channel view shows (the console's pre-flight): the first
        // displacement-controlled channel's stroke, not a held force.
        for (std::size_t i = 0; i < a.channelCommands.size(); ++i)
            if (m_spec.link2d->actuators[i].channel.mode == ActuatorMode::Displacement) {
                a.lastCommittedTarget = a.channelCommands[i];
                break;
            }
        a.description = "specimen '" + m_spec.name + "' on hsmu-controller (" +
                        std::to_string(m_rig->channels()) +
                        " actuator channels: " + m_rig->lab().description() + "), " +
                        std::to_string(m_committed) + " committed steps";
        return a;
    }
    const auto& o = m_spec.specimen.options;
    const char* act = o.actuator.type == ActuatorModel::Type::Lag     ? "lag"
                      : o.actuator.type == ActuatorModel::Type::Delay ? "delay"
                                                                      : "ideal";
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "specimen '%s' on hsmu-controller (%s law, force noise std %.3g, %s actuator, "
                  "%s pace, %.0f Hz predictor-corrector%s), %llu committed steps",
                  m_spec.name.c_str(), m_spec.specimen.trueMaterial.law.c_str(), o.forceNoiseStd,
                  act, m_pace == Pace::Fast ? "fast" : "real-time", m_settings.rate,
                  o.fracture.enabled() ? ", fracture event" : "",
                  static_cast<unsigned long long>(m_committed));
    a.description = buf;
    return a;
}

Message SpecimenStation::configure(const ConfigureMsg& m) {
    if (!(m.dt > 0.0) || !std::isfinite(m.dt))
        return error(ErrorCode::ProtocolViolation, "configure: dt must be a positive number");
    // A client may only tighten the configuration's limits: a limit of 0, a negative, NaN or
    // infinite one leaves the configuration's in force.
    const SafetyLimits own = ownLimits(m_spec);
    m_limits.maxDeformation = tighter(own.maxDeformation, m.maxDeformation);
    m_limits.maxForce = tighter(own.maxForce, m.maxForce);
    m_limits.maxIncrement = tighter(own.maxIncrement, m.maxIncrement);
    if (m.dt != m_dt) {
        m_dt = m.dt;
        if (m_rig)
            m_rig->prepare(m_dt);
        else
            m_specimen->prepare(m_dt);
        if (m_journal) {
            JournalRecord r;
            r.kind = JournalRecord::Kind::Configure;
            r.element = m_index;
            r.dt = m_dt;
            if (Message e = journal(r); std::holds_alternative<ErrorMsg>(e))
                return e;
        }
    }
    for (ActuatorLoop& l : m_loops)
        l.setTiming(m_settings.ticksPerStep(m_dt), m_settings.predictTicks(m_dt),
                    m_settings.holdRampTicks());
    if (!m_rig) // the rig's channels keep their own limits (ChannelRig::bounds)
        m_loops.front().setLimits(m_limits.maxDeformation, m_limits.maxIncrement);
    if (!m_configured) {
        m_configured = true;
        if (!m_trial.valid)
            beginStep();
    }
    return AckMsg{MessageType::Configure, m_committed};
}

void SpecimenStation::beginStep() {
    for (ActuatorLoop& l : m_loops)
        l.beginStep();
}

std::optional<Message> SpecimenStation::advance() {
    std::optional<std::string> why;
    for (ActuatorLoop& l : m_loops)
        if (auto w = l.tick(); w && !why)
            why = std::move(w);
    if (why)
        return trip(ErrorCode::Interlock, *why);
    return std::nullopt;
}

std::optional<Message> SpecimenStation::startStep(std::uint64_t step,
                                                  const std::vector<double>& targets) {
    using P = PredictorCorrector::Phase;
    m_trial.valid = false;
    m_pendingStep = step;
    ActuatorLoop& clock = m_loops.front(); // every loop keeps the same step clock
    if (m_pace == Pace::RealTime) {
        for (std::size_t i = 0; i < m_loops.size(); ++i)
            m_loops[i].setTarget(targets[i]);
        m_pending = true;
        return std::nullopt;
    }
    // Fast pace, simulated clock: the targets are taken to arrive when prediction ends.
    while (clock.phase() == P::Predicting)
        if (auto e = advance())
            return e;
    for (std::size_t i = 0; i < m_loops.size(); ++i)
        m_loops[i].setTarget(targets[i]);
    while (clock.phase() == P::Correcting)
        if (auto e = advance())
            return e;
    return finishStep();
}

Message SpecimenStation::trip(ErrorCode code, const std::string& reason) {
    m_holding = true;
    m_consoleHold = false;
    m_holdReason = (code == ErrorCode::Interlock       ? "interlock: "
                    : code == ErrorCode::SpecimenFault ? "specimen fault: "
                                                       : "controller fault: ") +
                   reason;
    m_pending = false;
    if (m_rig) // every actuator back at its committed stroke and force
        holdLoops();
    else
        m_loops.front().stop();
    ++m_trips;
    return error(code, "specimen '" + m_spec.name + "' holds: " + m_holdReason);
}

Message SpecimenStation::finishStep() {
    if (m_rig)
        return finishChannels();
    const ActuatorLoop& loop = m_loops.front();
    const double achieved = loop.achieved();
    if (ControlResult r = m_specimen->setTarget(achieved); !r.ok) {
        m_specimen->resume();
        return trip(ErrorCode::SpecimenFault, r.reason);
    }
    ControlMeasurement cm;
    if (ControlResult r = m_specimen->measure(cm); !r.ok)
        return trip(ErrorCode::SpecimenFault, r.reason);
    if (auto why = m_limits.violationOfForce(cm.force))
        return trip(ErrorCode::Interlock, *why);
    m_trial.valid = true;
    m_trial.step = m_pendingStep;
    m_trial.target = loop.target();
    m_trial.achieved = achieved;
    MeasurementMsg& mm = m_trial.measurement;
    mm.step = m_pendingStep;
    mm.deformation = cm.deformation;
    mm.force = cm.force;
    mm.commanded = loop.command();
    mm.heldTicks = static_cast<std::uint32_t>(loop.heldTicks());
    mm.flags = m_specimen->fractured() ? kFlagFractured : 0u;
    m_totalHeld += loop.heldTicks();
    m_pending = false;
    return mm;
}

std::optional<Message> SpecimenStation::target(const TargetMsg& m) {
    if (m_rig)
        return error(ErrorCode::ProtocolViolation,
                     "specimen '" + m_spec.name + "' has " + std::to_string(m_rig->channels()) +
                         " actuator channels: send targets, not one target");
    if (!m_configured)
        return error(ErrorCode::NotConfigured, "target before configure");
    if (m_holding)
        return error(ErrorCode::Holding, "specimen '" + m_spec.name + "' holds: " + m_holdReason);
    const double d = m.deformation;
    if (m.step == m_committed && m_last.valid) {
        if (d != m_last.target)
            return error(ErrorCode::StateMismatch,
                         "step " + std::to_string(m.step) + " is committed with another target");
        MeasurementMsg mm = m_last.measurement;
        mm.flags |= kFlagReplayed;
        return mm;
    }
    if (m.step != m_committed + 1)
        return error(ErrorCode::ProtocolViolation, "target for step " + std::to_string(m.step) +
                                                       ", expected step " +
                                                       std::to_string(m_committed + 1));
    if (m_trial.valid && m_trial.step == m.step && m_trial.target == d) {
        MeasurementMsg mm = m_trial.measurement;
        mm.flags |= kFlagReplayed;
        return mm;
    }
    if (m_pending && m_pendingStep == m.step && m_loops.front().target() == d)
        return std::nullopt; // already on its way
    if (auto why = m_limits.violationOfTarget(d, m_loops.front().committedTarget()))
        return trip(ErrorCode::Interlock, *why);
    return startStep(m.step, {d});
}

std::optional<Message> SpecimenStation::tick() {
    if (!needsTicks())
        return std::nullopt;
    if (auto e = advance())
        return e;
    if (m_pending && m_loops.front().phase() == PredictorCorrector::Phase::Arrived)
        return finishStep();
    return std::nullopt;
}

bool SpecimenStation::needsTicks() const {
    using P = PredictorCorrector::Phase;
    const P p = m_loops.front().phase();
    return m_pace == Pace::RealTime && m_configured && !m_holding &&
           (p == P::Predicting || p == P::Late || p == P::Correcting);
}

Message SpecimenStation::commit(const CommitMsg& m) {
    if (m_holding)
        return error(ErrorCode::Holding, "specimen '" + m_spec.name + "' holds: " + m_holdReason);
    if (m.step == m_committed && m_last.valid)
        return AckMsg{MessageType::Commit, m_committed};
    if (m_rig)
        return commitChannels(m);
    if (m.step != m_committed + 1 || !m_trial.valid || m_trial.step != m.step)
        return error(ErrorCode::ProtocolViolation,
                     "commit of step " + std::to_string(m.step) + " without its measurement");
    if (ControlResult r = m_specimen->commit(); !r.ok)
        return trip(ErrorCode::SpecimenFault, r.reason);
    m_last = m_trial;
    m_trial = Trial{};
    m_committed = m.step;
    m_loops.front().commit(m_last.target);
    if (m_journal) {
        JournalRecord r;
        r.element = m_index;
        r.step = m_committed;
        r.target = m_last.target;
        r.achieved = m_last.achieved;
        r.deformation = m_last.measurement.deformation;
        r.force = m_last.measurement.force;
        if (Message e = journal(r); std::holds_alternative<ErrorMsg>(e))
            return e;
    }
    return AckMsg{MessageType::Commit, m_committed};
}

Message SpecimenStation::hold(const std::string& reason) {
    if (!m_holding || m_consoleHold) { // a trip's reason is kept: it is the reason to look
        m_consoleHold = true;
        m_holdReason = reason.empty() ? "console hold" : reason;
    }
    m_holding = true;
    m_pending = false;
    if (m_rig)
        holdLoops();
    else
        m_loops.front().stop();
    return AckMsg{MessageType::Hold, m_committed};
}

Message SpecimenStation::resume() {
    m_holding = false;
    m_consoleHold = false;
    m_holdReason.clear();
    if (m_rig)
        m_rig->resume();
    else
        m_specimen->resume();
    return AckMsg{MessageType::Resume, m_committed};
}

bool SpecimenStation::releaseConsoleHold() {
    if (!m_holding || !m_consoleHold)
        return false;
    resume();
    return true;
}

Message SpecimenStation::reset() {
    makeSpecimen();
    m_committed = 0;
    m_last = m_trial = Trial{};
    m_pending = false;
    m_holding = false;
    m_consoleHold = false;
    m_holdReason.clear();
    for (ActuatorLoop& l : m_loops)
        l.restore(0.0, 0.0, 0.0, 0.0);
    if (m_journal) {
        JournalRecord r;
        r.kind = JournalRecord::Kind::Reset;
        r.element = m_index;
        if (Message e = journal(r); std::holds_alternative<ErrorMsg>(e))
            return e;
    }
    return AckMsg{MessageType::Reset, 0};
}

} // namespace hsmu::comms
