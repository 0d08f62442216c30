#pragma once
// LinearElastic: F = k u, tangent k (no internal state). Units are the caller's.

#include "core/hysteresis/HysteresisLaw.h"

namespace hsmu {

class LinearElastic final : public HysteresisLaw {
public:
    /// k: stiffness [force / deformation], finite and > 0; throws std::invalid_argument
    /// otherwise.
    explicit LinearElastic(double k = 1.0);

    /// k finite and > 0.
    static bool admissible(double k);
    double stiffness() const { return m_k; }

    // HysteresisLaw
    std::string lawName() const override { return "elastic"; }
    LawStatus setTrialDeformation(double u) override;
    double trialDeformation() const override { return m_uTrial; }
    double trialForce() const override { return m_k * m_uTrial; }
    double trialTangent() const override { return m_k; }
    double committedDeformation() const override { return m_uCommitted; }
    double committedForce() const override { return m_k * m_uCommitted; }
    double initialTangent() const override { return m_k; }
    void commit() override { m_uCommitted = m_uTrial; }
    void revert() override { m_uTrial = m_uCommitted; }
    void revertToStart() override { m_uCommitted = m_uTrial = 0.0; }
    std::unique_ptr<HysteresisLaw> clone() const override;
    /// k.
    std::vector<std::string> parameterNames() const override { return {"k"}; }
    double parameterValue(int index) const override;
    int setParameterValues(std::span<const int> indices, std::span<const double> values,
                           bool allOrNothing) override;

private:
    double m_k;
    double m_uCommitted = 0.0, m_uTrial = 0.0;
};

} // namespace hsmu
