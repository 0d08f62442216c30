#include "core/experimental/setup/Aggregator.h"

namespace hsmu {

Aggregator::Aggregator(std::vector<std::unique_ptr<ExperimentalSetup>> parts)
    : m_parts(std::move(parts)) {
    for (const auto& p : m_parts) {
        m_basic += p->basicSize();
        m_actuators += p->actuatorCount();
    }
}

std::unique_ptr<Aggregator>
Aggregator::create(std::vector<std::unique_ptr<ExperimentalSetup>> parts, std::string& error) {
    if (parts.empty()) {
        error = "Aggregator: -setup: at least one setup wanted";
        return nullptr;
    }
    for (std::size_t k = 0; k < parts.size(); ++k)
        if (!parts[k]) {
            error = "Aggregator: -setup: setup " + std::to_string(k + 1) + " is missing";
            return nullptr;
        }
    error.clear();
    return std::unique_ptr<Aggregator>(new Aggregator(std::move(parts)));
}

SetupResult Aggregator::sizes(Eigen::Index basic, Eigen::Index actuators) const {
    if (basic == m_basic && actuators == m_actuators)
        return SetupResult::success();
    return SetupResult::fault("Aggregator: " + std::to_string(m_basic) + " basic values and " +
                              std::to_string(m_actuators) + " actuator values wanted, got " +
                              std::to_string(basic) + " and " + std::to_string(actuators));
}

SetupResult Aggregator::strokes(const Eigen::VectorXd& d, Eigen::VectorXd& s) const {
    if (SetupResult r = sizes(d.size(), m_actuators); !r.ok)
        return r;
    s.resize(m_actuators);
    int b = 0, a = 0;
    Eigen::VectorXd sp;
    for (const auto& p : m_parts) {
        if (SetupResult r = p->strokes(d.segment(b, p->basicSize()), sp); !r.ok)
            return SetupResult::fault("Aggregator > " + r.reason);
        s.segment(a, p->actuatorCount()) = sp;
        b += p->basicSize();
        a += p->actuatorCount();
    }
    return SetupResult::success();
}

SetupResult Aggregator::jacobian(const Eigen::VectorXd& d, Eigen::MatrixXd& J) const {
    if (SetupResult r = sizes(d.size(), m_actuators); !r.ok)
        return r;
    J.setZero(m_actuators, m_basic);
    int b = 0, a = 0;
    Eigen::MatrixXd Jp;
    for (const auto& p : m_parts) {
        if (SetupResult r = p->jacobian(d.segment(b, p->basicSize()), Jp); !r.ok)
            return SetupResult::fault("Aggregator > " + r.reason);
        J.block(a, b, p->actuatorCount(), p->basicSize()) = Jp;
        b += p->basicSize();
        a += p->actuatorCount();
    }
    return SetupResult::success();
}

SetupResult Aggregator::basicDisplacements(const Eigen::VectorXd& s, const Eigen::VectorXd& given,
                                           Eigen::VectorXd& d) const {
    if (SetupResult r = sizes(given.size(), s.size()); !r.ok)
        return r;
    d.resize(m_basic);
    int b = 0, a = 0;
    Eigen::VectorXd dp;
    for (const auto& p : m_parts) {
        if (SetupResult r = p->basicDisplacements(s.segment(a, p->actuatorCount()),
                                                  given.segment(b, p->basicSize()), dp);
            !r.ok)
            return SetupResult::fault("Aggregator > " + r.reason);
        d.segment(b, p->basicSize()) = dp;
        b += p->basicSize();
        a += p->actuatorCount();
    }
    return SetupResult::success();
}

} // namespace hsmu
