#pragma once
// OffsetLaw: a law with a deformation offset u0 and a force offset F0 (docs/hysteresis-laws.md,
// "Offsets"): the specimen's measured force is the inner law's force at the deformation it
// really has plus the force the load cell reads at rest,
//   F(u) = F_inner(u - u0) + F0,   dF/du = dF_inner/du,
// for a load cell zeroed under load, a friction device's bias or an actuator whose
// displacement transducer was zeroed off the specimen's neutral position.
// u0 is in the caller's deformation units, F0 in its force units (physical, whatever the inner
// law's normalization: a Bouc-Wen law with uRef / fRef keeps its own normalized parameters).
// Parameters: the inner law's, then "deformationOffset" (u0) and "forceOffset" (F0), both any
// finite number. The law's name is the inner law's (LawFactory builds an OffsetLaw when either
// offset is given). Its virgin state is the inner law's at u = u0 with force F0: a replay from
// rest starts the inner law at its own zero, whatever u0.
// Thread rules: none (as every law).

#include "core/hysteresis/HysteresisLaw.h"

namespace hsmu {

class OffsetLaw final : public HysteresisLaw {
public:
    /// The names of the two trailing parameters.
    static constexpr const char* kDeformationOffset = "deformationOffset";
    static constexpr const char* kForceOffset = "forceOffset";

    /// inner: not null. Throws std::invalid_argument for a null inner law or a non-finite
    /// offset.
    OffsetLaw(std::unique_ptr<HysteresisLaw> inner, double deformationOffset, double forceOffset);

    const HysteresisLaw& inner() const { return *m_inner; }
    double deformationOffset() const { return m_u0; }
    double forceOffset() const { return m_f0; }

    // HysteresisLaw
    std::string lawName() const override { return m_inner->lawName(); }
    LawStatus setTrialDeformation(double u) override;
    double trialDeformation() const override { return m_inner->trialDeformation() + m_u0; }
    double trialForce() const override { return m_inner->trialForce() + m_f0; }
    double trialTangent() const override { return m_inner->trialTangent(); }
    double algorithmicTangent() const override { return m_inner->algorithmicTangent(); }
    bool isRateDependent() const override { return m_inner->isRateDependent(); }
    void setTimeIncrement(double dt) override { m_inner->setTimeIncrement(dt); }
    double timeIncrement() const override { return m_inner->timeIncrement(); }
    std::string failureReason() const override { return m_inner->failureReason(); }
    double committedDeformation() const override { return m_inner->committedDeformation() + m_u0; }
    double committedForce() const override { return m_inner->committedForce() + m_f0; }
    double initialTangent() const override { return m_inner->initialTangent(); }
    void commit() override { m_inner->commit(); }
    void revert() override { m_inner->revert(); }
    void revertToStart() override { m_inner->revertToStart(); }
    std::unique_ptr<HysteresisLaw> clone() const override;
    /// The inner law's names, then deformationOffset, forceOffset.
    std::vector<std::string> parameterNames() const override;
    double parameterValue(int index) const override;
    /// The inner law's values are judged by the inner law (all together with allOrNothing);
    /// an offset is admissible when finite. Changing u0 moves the law along u: the committed
    /// inner state is kept, so the next trial sees the deformation u - u0 with the new u0.
    int setParameterValues(std::span<const int> indices, std::span<const double> values,
                           bool allOrNothing) override;

private:
    std::unique_ptr<HysteresisLaw> m_inner;
    int m_innerCount = 0; ///< the inner law's parameters (the offsets follow)
    double m_u0 = 0.0, m_f0 = 0.0;
};

} // namespace hsmu
