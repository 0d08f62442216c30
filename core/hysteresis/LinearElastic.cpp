#include "core/hysteresis/LinearElastic.h"

#include <limits>

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

double LinearElastic::parameterValue(int index) const {
    return index == 0 ? m_k : std::numeric_limits<double>::quiet_NaN();
}

int LinearElastic::setParameterValues(std::span<const int> indices,
                                      std::span<const double> values, bool allOrNothing) {
    double k = m_k;
    int firstRefused = -1;
    for (std::size_t i = 0; i < indices.size(); ++i) {
        if (indices[i] == 0 && admissible(values[i])) {
            k = values[i];
        } else if (firstRefused < 0) {
            firstRefused = static_cast<int>(i);
        }
    }
    if (allOrNothing && firstRefused >= 0) {
        return firstRefused;
    }
    if (!indices.empty()) {
        m_k = k;
        m_uTrial = m_uCommitted;
    }
    return firstRefused;
}

} // namespace hsmu
