#pragma once
// MrDamperUkf: joint state-parameter estimation of an MR damper (MrDamper.h, Spencer et al.'s
// modified Bouc-Wen model) by the generic UnscentedKalmanFilter, driven each step by the
// specimen's measured deformation and force (docs/method.md, "The MR damper UKF").
//
// State (L = 11, the law's normalized units):
//   x = [ w, z, c0, c1, k0, k1, f0, alpha, beta, gamma, n ]
// A, uRef and fRef are fixed. One step of duration dt (the samples' step), for the measured
// (u, F):
//   process:     (w, z) <- the law's integration over the step (MrDamper::setTrialDeformation
//                from the committed (w, z) at the previous u, with the sigma point's
//                parameters); the parameters follow a random walk (unchanged, plus Q)
//   measurement: h(x) = c0 c1 / c xd + c1 / c (alpha z + k0 w) + k1 x + f0 (the law's force at
//                the end of the step, c = c0 + c1, x = u / uRef, xd = (u - u_previous) /
//                (uRef dt)), compared with F / fRef
// Unscented transform a = 1, kappa = 0, b = 2 (positive weights, as the pinching UKF).
// Admissibility of every point the law integrates: the parameters' box (sigma points in the
// box, means boundMargin of the width inside it; the box must keep c1 > 0, c0, k0, k1,
// alpha >= 0, n > 0) and beta + gamma >= 1e-3 (a point below is moved along (1, 1) onto it).
// Noise: R = forceNoise^2, Q diagonal: w, z stateNoise^2, each parameter (parameterNoise x box
// width)^2. Faults: a sigma point the law cannot integrate, or anything the UKF guards,
// rejects the step (status not ok); after a rejected prediction (w, z) are advanced with the
// estimate's own parameters, so that the filter stays in step with the deformation.
// Thread rules: none; an instance is used by one thread at a time.

#include "core/hysteresis/MrDamper.h"
#include "core/identification/ParameterSet.h"
#include "core/identification/UnscentedKalmanFilter.h"

#include <array>
#include <string>

namespace hsmu {

inline constexpr int kMrDamperUkfParameters = 9;
inline constexpr int kMrDamperUkfSize = 2 + kMrDamperUkfParameters;

/// The identified parameters, in state order (state index = 2 + position): c0, c1, k0, k1, f0,
/// alpha, beta, gamma, n.
const std::array<const char*, kMrDamperUkfParameters>& mrDamperUkfParameterNames();
/// The position of `name` in mrDamperUkfParameterNames(); -1 if it is not identified.
int mrDamperUkfParameterIndex(const std::string& name);

struct MrDamperUkfSettings {
    UkfSettings ukf{1.0, 2.0, 0.0};
    double forceNoise = 0.01;     ///< R std (normalized force)
    double stateNoise = 1e-4;     ///< Q std of w and z per step (normalized)
    double parameterNoise = 1e-5; ///< Q std per step, fraction of the box width
    double boundMargin = 1e-3;    ///< means kept this fraction of the width inside the box
};

struct MrDamperUkfStep {
    UkfStatus status;
    double predictedForce = 0.0; ///< a-priori prediction of F (physical units)
};

class MrDamperUkf {
public:
    using Box = std::array<ParameterBounds, kMrDamperUkfParameters>;
    using Values = std::array<double, kMrDamperUkfParameters>;

    /// box: finite lower <= upper per parameter keeping the law admissible apart from beta +
    /// gamma; dt > 0: the samples' step [s]. Throws std::invalid_argument otherwise.
    MrDamperUkf(const MrDamperParameters& initial, const Box& box, double dt,
                const MrDamperUkfSettings& settings = {});

    /// Restart at `estimate` with the law's internal state `state` at the deformation u
    /// (physical), parameter standard deviations sd (w and z: 1e-3), the settings' Q and R.
    void restart(const MrDamperParameters& estimate, const MrDamperState& state, double u,
                 const Values& sd);
    void setSettings(const MrDamperUkfSettings& s) { m_settings = s; }
    const MrDamperUkfSettings& settings() const { return m_settings; }

    MrDamperUkfStep step(double deformation, double force);

    /// The estimate (fixed parameters included).
    MrDamperParameters estimate() const;
    Values standardDeviation() const;
    MrDamperState state() const;
    const Box& box() const { return m_box; }

    /// Value of parameter j (mrDamperUkfParameterNames() order) of p, by reference.
    static double& field(MrDamperParameters& p, int j);
    static double field(const MrDamperParameters& p, int j);

private:
    void applyNoiseAndBounds();
    MrDamperParameters fromState(const Eigen::Ref<const Eigen::VectorXd>& x) const;
    /// (w, z) after the step to u from the state's (w, z) at m_u with its parameters.
    bool advance(Eigen::Ref<Eigen::VectorXd> x, double u);

    MrDamperParameters m_fixed; ///< A, uRef, fRef (and the initial values)
    Box m_box;
    double m_dt;
    MrDamperUkfSettings m_settings;
    UnscentedKalmanFilter m_ukf;
    MrDamper m_law;   ///< integrates the sigma points (parameters and state set per point)
    double m_u = 0.0; ///< last deformation (physical)
};

} // namespace hsmu
