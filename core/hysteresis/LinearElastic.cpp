#include "core/hysteresis/LinearElastic.h"

#include <cmath>
#include <stdexcept>

namespace hsmu {

LinearElastic::LinearElastic(double k) : m_k(k) {
    if (!admissible(k)) {
        throw std::invalid_argument("LinearElastic: stiffness k must be finite and > 0");
    }
}

bool LinearElastic::admissible(double k) {
    return std::isfinite(k) && k > 0.0;
}

LawStatus LinearElastic::setTrialDeformation(double u) {
    if (!std::isfinite(u)) {
        revert();
        return LawStatus::InvalidInput;
    }
    m_uTrial = u;
    return LawStatus::Ok;
}

std::unique_ptr<HysteresisLaw> LinearElastic::clone() const {
    return std::make_unique<LinearElastic>(*this);
}

std::optional<double> LinearElastic::parameter(const std::string& name) const {
    if (name == "k") {
        return m_k;
    }
    return std::nullopt;
}

bool LinearElastic::setParameter(const std::string& name, double value) {
    if (name != "k" || !admissible(value)) {
        return false;
    }
    m_k = value;
    m_uTrial = m_uCommitted;
    return true;
}

} // namespace hsmu
