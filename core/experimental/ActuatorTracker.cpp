#include "core/experimental/ActuatorTracker.h"

#include <cmath>

namespace hsmu {

const char* actuatorModelName(const ActuatorModel& m) {
    switch (m.type) {
    case ActuatorModel::Type::Lag:
        return "lag";
    case ActuatorModel::Type::Delay:
        return "delay";
    case ActuatorModel::Type::ServoHydraulic:
        return "servoHydraulic";
    case ActuatorModel::Type::Ideal:
        break;
    }
    return "ideal";
}

ActuatorTracker::ActuatorTracker(const ActuatorModel& model) : m_model(model) {}

std::string ActuatorTracker::prepare(double dt) {
    if (!(dt > 0.0))
        return "dt must be > 0";
    m_dt = dt;
    m_hasTrial = false;
    m_line.clear();
    if (m_model.type == ActuatorModel::Type::Delay)
        m_line.assign(static_cast<std::size_t>(std::lround(m_model.delay / dt)), m_committed);
    if (m_model.type == ActuatorModel::Type::ServoHydraulic) {
        try {
            m_servo.emplace(m_model.servo);
        } catch (const std::exception& e) {
            return e.what();
        }
        m_servo->reset(m_committed);
    }
    return {};
}

double ActuatorTracker::trial(double command, std::string& why) {
    why.clear();
    m_trialCommand = command;
    m_hasTrial = true;
    switch (m_model.type) {
    case ActuatorModel::Type::Lag:
        m_trial = m_model.timeConstant > 0.0 && m_dt > 0.0
                      ? m_committed +
                            (command - m_committed) * (1.0 - std::exp(-m_dt / m_model.timeConstant))
                      : command;
        break;
    case ActuatorModel::Type::Delay:
        m_trial = m_line.empty() ? command : m_line.front();
        break;
    case ActuatorModel::Type::ServoHydraulic:
        if (!m_servo) {
            m_trial = command;
            break;
        }
        m_servoTrial = *m_servo;
        m_trial = m_servoTrial->advance(command, m_dt);
        why = m_servoTrial->limitBreach();
        break;
    case ActuatorModel::Type::Ideal:
        m_trial = command;
        break;
    }
    return m_trial;
}

void ActuatorTracker::commit() {
    if (!m_hasTrial)
        return;
    m_committed = m_trial;
    if (!m_line.empty()) {
        m_line.pop_front();
        m_line.push_back(m_trialCommand);
    }
    if (m_servoTrial)
        m_servo = m_servoTrial;
    m_hasTrial = false;
}

void ActuatorTracker::revert() {
    m_hasTrial = false;
    m_trial = m_committed;
    m_servoTrial.reset();
}

} // namespace hsmu
