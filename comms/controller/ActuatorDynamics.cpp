#include "comms/controller/ActuatorDynamics.h"

#include <algorithm>
#include <cmath>

namespace hsmu::comms {

ActuatorDynamics::ActuatorDynamics(const ActuatorModel& model, double rate) : m_model(model) {
    const double h = 1.0 / rate;
    if (model.type == ActuatorModel::Type::Lag && model.timeConstant > 0.0)
        m_lagFactor = 1.0 - std::exp(-h / model.timeConstant);
    if (model.type == ActuatorModel::Type::Delay) {
        const long d = std::lround(model.delay / h);
        m_line.assign(static_cast<std::size_t>(d > 0 ? d : 0), 0.0);
    }
    if (model.type == ActuatorModel::Type::ServoHydraulic) {
        rths::ServoActuatorSettings s = model.servo;
        s.rate = rate; // the controller's own loop rate
        m_servo.emplace(s);
    }
}

void ActuatorDynamics::reset(double position) {
    m_position = position;
    if (m_servo)
        m_servo->reset(position);
    std::fill(m_line.begin(), m_line.end(), position);
    m_head = 0;
}

double ActuatorDynamics::tick(double command) {
    switch (m_model.type) {
    case ActuatorModel::Type::Ideal:
        m_position = command;
        break;
    case ActuatorModel::Type::ServoHydraulic:
        m_position = m_servo->tick(command);
        break;
    case ActuatorModel::Type::Lag:
        m_position += (command - m_position) * m_lagFactor;
        break;
    case ActuatorModel::Type::Delay:
        if (m_line.empty()) {
            m_position = command;
        } else {
            m_position = m_line[m_head];
            m_line[m_head] = command;
            m_head = (m_head + 1) % m_line.size();
        }
        break;
    }
    return m_position;
}

} // namespace hsmu::comms
