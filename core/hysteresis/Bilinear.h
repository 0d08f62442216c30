#pragma once
// Bilinear: elastic - linear-hardening law with kinematic hardening (docs/method.md, Bilinear
// law: the law of the paper's first example, its Figures 1-2).
//
// With initial stiffness k0, yield force fy and post-yield stiffness ratio b:
//   F = k0 (u - up)                                 elastic stiffness k0
//   |F - q| <= fy                                   yield surface, q = back force
//   kinematic hardening modulus H = b k0 / (1 - b)  so that the post-yield tangent is b k0
// The trial is evaluated by the classic return mapping from the committed (up, q), which is
// exact for this piecewise-linear law: the yield surface moves with the back force, so after
// yielding in one direction reverse yielding starts after a force change of 2 fy.
// Units are the caller's (k0 in force per deformation, fy in force).

#include "core/hysteresis/HysteresisLaw.h"

namespace hsmu {

struct BilinearParameters {
    double k0 = 1.0; ///< initial (elastic) stiffness [force / deformation], > 0
    double fy = 1.0; ///< initial yield force [force], > 0
    double b = 0.1;  ///< post-yield to initial stiffness ratio [-], 0 <= b < 1
};

/// Internal state of the bilinear law (caller's units).
struct BilinearState {
    double plasticDeformation = 0.0; ///< up [deformation]
    double backForce = 0.0;          ///< q, centre of the yield surface [force]
};

class Bilinear final : public HysteresisLaw {
public:
    /// Throws std::invalid_argument if p is not admissible.
    explicit Bilinear(const BilinearParameters& p = {});

    /// All finite, k0 > 0, fy > 0, 0 <= b < 1.
    static bool admissible(const BilinearParameters& p);
    const BilinearParameters& parameters() const { return m_p; }
    /// Replace all parameters; the committed (up, q) is kept and the committed force is
    /// re-evaluated as k0 (u - up); a pending trial is dropped. False if inadmissible.
    bool setParameters(const BilinearParameters& p);
    BilinearState committedState() const { return m_committed; }

    // HysteresisLaw
    std::string lawName() const override { return "bilinear"; }
    LawStatus setTrialDeformation(double u) override;
    double trialDeformation() const override { return m_uTrial; }
    double trialForce() const override { return m_fTrial; }
    double trialTangent() const override { return m_kTrial; }
    double committedDeformation() const override { return m_uCommitted; }
    double committedForce() const override { return m_fCommitted; }
    double initialTangent() const override { return m_p.k0; }
    void commit() override;
    void revert() override;
    void revertToStart() override;
    std::unique_ptr<HysteresisLaw> clone() const override;
    /// k0, fy, b.
    std::vector<std::string> parameterNames() const override;
    double parameterValue(int index) const override;
    int setParameterValues(std::span<const int> indices, std::span<const double> values,
                           bool allOrNothing) override;

private:
    BilinearParameters m_p;
    BilinearState m_committed, m_trial;
    double m_uCommitted = 0.0, m_uTrial = 0.0;
    double m_fCommitted = 0.0, m_fTrial = 0.0;
    double m_kCommitted = 0.0, m_kTrial = 0.0;
};

} // namespace hsmu
