#include "core/hysteresis/OffsetLaw.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hsmu {

OffsetLaw::OffsetLaw(std::unique_ptr<HysteresisLaw> inner, double deformationOffset,
                     double forceOffset)
    : m_inner(std::move(inner)), m_u0(deformationOffset), m_f0(forceOffset) {
    if (!m_inner)
        throw std::invalid_argument("offset law: no inner law");
    if (!std::isfinite(m_u0) || !std::isfinite(m_f0))
        throw std::invalid_argument(m_inner->lawName() +
                                    ": the deformation and force offsets must be finite");
    m_innerCount = int(m_inner->parameterNames().size());
}

LawStatus OffsetLaw::setTrialDeformation(double u) {
    if (!std::isfinite(u))
        return LawStatus::InvalidInput;
    return m_inner->setTrialDeformation(u - m_u0);
}

std::unique_ptr<HysteresisLaw> OffsetLaw::clone() const {
    return std::make_unique<OffsetLaw>(m_inner->clone(), m_u0, m_f0);
}

std::vector<std::string> OffsetLaw::parameterNames() const {
    std::vector<std::string> names = m_inner->parameterNames();
    names.emplace_back(kDeformationOffset);
    names.emplace_back(kForceOffset);
    return names;
}

double OffsetLaw::parameterValue(int index) const {
    if (index == m_innerCount)
        return m_u0;
    if (index == m_innerCount + 1)
        return m_f0;
    return m_inner->parameterValue(index);
}

int OffsetLaw::setParameterValues(std::span<const int> indices, std::span<const double> values,
                                  bool allOrNothing) {
    // The inner law's share, in order, with the offsets apart.
    std::vector<int> innerIndices;
    std::vector<double> innerValues;
    std::vector<std::size_t> innerAt; // positions in `indices` of the inner law's share
    double u0 = m_u0, f0 = m_f0;
    int firstRefused = -1;
    for (std::size_t k = 0; k < indices.size(); ++k) {
        const int i = indices[k];
        if (i == m_innerCount || i == m_innerCount + 1) {
            if (!std::isfinite(values[k])) {
                if (firstRefused < 0)
                    firstRefused = int(k);
                continue;
            }
            (i == m_innerCount ? u0 : f0) = values[k];
        } else if (i >= 0 && i < m_innerCount) {
            innerIndices.push_back(i);
            innerValues.push_back(values[k]);
            innerAt.push_back(k);
        } else if (firstRefused < 0) {
            firstRefused = int(k);
        }
    }
    if (allOrNothing && firstRefused >= 0) {
        // the inner share may hold an earlier refusal: ask it without changing it
        if (!innerIndices.empty()) {
            std::unique_ptr<HysteresisLaw> probe = m_inner->clone();
            const int r = probe->setParameterValues(innerIndices, innerValues, true);
            if (r >= 0 && innerAt[std::size_t(r)] < std::size_t(firstRefused))
                return int(innerAt[std::size_t(r)]);
        }
        return firstRefused;
    }
    const int r = innerIndices.empty() ? -1
                                       : m_inner->setParameterValues(innerIndices, innerValues,
                                                                     allOrNothing);
    if (allOrNothing && r >= 0)
        return int(innerAt[std::size_t(r)]);
    if (u0 != m_u0 || f0 != m_f0)
        m_inner->revert(); // a pending trial is dropped, as the inner law drops its own
    m_u0 = u0;
    m_f0 = f0;
    if (!allOrNothing) {
        const int innerRefused = r >= 0 ? int(innerAt[std::size_t(r)]) : -1;
        if (firstRefused >= 0 || innerRefused >= 0)
            return firstRefused < 0 ? innerRefused
                                    : (innerRefused < 0 ? firstRefused
                                                        : std::min(firstRefused, innerRefused));
    }
    return -1;
}

} // namespace hsmu
