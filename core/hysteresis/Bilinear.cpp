#include "core/hysteresis/Bilinear.h"

#include <limits>

#include <cmath>
#include <stdexcept>

namespace hsmu {

Bilinear::Bilinear(const BilinearParameters& p) : m_p(p) {
    if (!admissible(p)) {
        throw std::invalid_argument("Bilinear: parameters are not admissible");
    }
    revertToStart();
}

bool Bilinear::admissible(const BilinearParameters& p) {
    return std::isfinite(p.k0) && std::isfinite(p.fy) && std::isfinite(p.b) && p.k0 > 0.0 &&
           p.fy > 0.0 && p.b >= 0.0 && p.b < 1.0;
}

bool Bilinear::setParameters(const BilinearParameters& p) {
    if (!admissible(p)) {
        return false;
    }
    m_p = p;
    m_fCommitted = m_p.k0 * (m_uCommitted - m_committed.plasticDeformation);
    m_kCommitted = m_p.k0;
    revert();
    return true;
}

LawStatus Bilinear::setTrialDeformation(double u) {
    if (!std::isfinite(u)) {
        revert();
        return LawStatus::InvalidInput;
    }
    const double k0 = m_p.k0;
    const double hardening = m_p.b * k0 / (1.0 - m_p.b);
    const double fTrial = k0 * (u - m_committed.plasticDeformation);
    const double xi = fTrial - m_committed.backForce;
    const double excess = std::abs(xi) - m_p.fy;
    m_uTrial = u;
    m_trial = m_committed;
    if (excess <= 0.0) {
        m_fTrial = fTrial;
        m_kTrial = k0;
        return LawStatus::Ok;
    }
    const double direction = xi > 0.0 ? 1.0 : -1.0;
    const double plasticIncrement = excess / (k0 + hardening);
    m_trial.plasticDeformation += direction * plasticIncrement;
    m_trial.backForce += direction * hardening * plasticIncrement;
    m_fTrial = fTrial - direction * k0 * plasticIncrement;
    m_kTrial = m_p.b * k0;
    return LawStatus::Ok;
}

void Bilinear::commit() {
    m_committed = m_trial;
    m_uCommitted = m_uTrial;
    m_fCommitted = m_fTrial;
    m_kCommitted = m_kTrial;
}

void Bilinear::revert() {
    m_trial = m_committed;
    m_uTrial = m_uCommitted;
    m_fTrial = m_fCommitted;
    m_kTrial = m_kCommitted;
}

void Bilinear::revertToStart() {
    m_committed = BilinearState{};
    m_uCommitted = 0.0;
    m_fCommitted = 0.0;
    m_kCommitted = m_p.k0;
    revert();
}

std::unique_ptr<HysteresisLaw> Bilinear::clone() const {
    return std::make_unique<Bilinear>(*this);
}

std::vector<std::string> Bilinear::parameterNames() const {
    return {"k0", "fy", "b"};
}

namespace {
/// The field of p at position i of parameterNames(); nullptr if there is none.
double* fieldAt(BilinearParameters& p, int i) {
    switch (i) {
    case 0:
        return &p.k0;
    case 1:
        return &p.fy;
    case 2:
        return &p.b;
    default:
        return nullptr;
    }
}
} // namespace

double Bilinear::parameterValue(int index) const {
    BilinearParameters p = m_p;
    const double* field = fieldAt(p, index);
    return field ? *field : std::numeric_limits<double>::quiet_NaN();
}

int Bilinear::setParameterValues(std::span<const int> indices, std::span<const double> values,
                                 bool allOrNothing) {
    BilinearParameters p = m_p;
    int firstRefused = -1;
    for (std::size_t k = 0; k < indices.size(); ++k) {
        double* field = fieldAt(p, indices[k]);
        if (field != nullptr) {
            const double previous = *field;
            *field = values[k];
            BilinearParameters alone = m_p;
            *fieldAt(alone, indices[k]) = values[k];
            // Together: only values refused on their own count (the set is judged below).
            if (allOrNothing ? admissible(alone) : admissible(p)) {
                continue;
            }
            *field = previous;
        }
        if (firstRefused < 0) {
            firstRefused = static_cast<int>(k);
        }
    }
    if (allOrNothing && (firstRefused >= 0 || !admissible(p))) {
        return firstRefused >= 0 ? firstRefused : 0;
    }
    if (!indices.empty()) {
        setParameters(p);
    }
    return firstRefused;
}

} // namespace hsmu
