#pragma once
// PinchingUkf: joint state-parameter estimation of one Bouc-Wen-Baber-Noori element with
// pinching (BoucWenPinching.h, Eqs P1-P4; docs/method.md, "The pinching UKF") by the generic
// UnscentedKalmanFilter, driven each step by the specimen's measured deformation and force.
//
// State (L = 15, the law's normalized units):
//   x = [ z, e, k0, alpha, n, beta, gamma, deltaNu, deltaEta, zetaS, p, q, psi, deltaPsi,
//         lambda ]
// A0, deltaA, uRef and fRef are fixed at their initial values.
// One step, for the measured (u, F) (physical units), dx = u / uRef - previous u / uRef:
//   process:     (z, e) <- BoucWenPinching::integrate(parameters of the sigma point, (z, e),
//                dx); parameters follow a random walk (unchanged, plus Q)
//   measurement: h(x) = alpha k0 (u / uRef) + (1 - alpha) k0 z, compared with F / fRef
// Unscented transform a = 1, kappa = 0, b = 2 (positive weights: the mean of admissible
// points is admissible in every convex constraint).
// Admissibility of every point the law integrates: the parameters' box (sigma points in the
// box, means boundMargin of the width inside it; UnscentedKalmanFilter.h, Bounds; the box must
// keep zetaS < 1, psi > 0, lambda > 0, q < 1, k0 > 0, n > 0, rates >= 0, e >= 0) and
// beta + gamma >= 1e-3: a sigma point below it is moved along (1, 1) onto it before the law
// integrates it (its propagated value is the moved one), and so is a posterior mean.
// Noise: R = forceNoise^2 (normalized force), Q diagonal: z, e zNoise^2, eNoise^2, each
// parameter (parameterNoise x box width)^2.
// Faults: a sigma point the law cannot integrate, or anything the UKF guards, rejects the
// step (status not ok, with a reason); after a rejected prediction z and e are advanced with
// the estimate's own parameters so that the filter stays in step with the deformation.
// Thread rules: none; an instance is used by one thread at a time.

#include "core/hysteresis/BoucWenPinching.h"
#include "core/identification/ParameterSet.h"
#include "core/identification/UnscentedKalmanFilter.h"

#include <array>
#include <string>
#include <vector>

namespace hsmu {

inline constexpr int kPinchingUkfParameters = 13;
inline constexpr int kPinchingUkfSize = 2 + kPinchingUkfParameters;

/// The identified parameters, in state order (state index = 2 + position).
const std::array<const char*, kPinchingUkfParameters>& pinchingUkfParameterNames();
/// The position of `name` in pinchingUkfParameterNames(); -1 if it is not identified.
int pinchingUkfParameterIndex(const std::string& name);

struct PinchingUkfSettings {
    UkfSettings ukf{1.0, 2.0, 0.0};
    double forceNoise = 0.01;     ///< R std (normalized force)
    double zNoise = 1e-4;         ///< Q std of z per step (normalized)
    double eNoise = 1e-4;         ///< Q std of e per step (normalized)
    double parameterNoise = 1e-5; ///< Q std per step, fraction of the box width
    double boundMargin = 1e-3;    ///< means kept this fraction of the width inside the box
};

struct PinchingUkfStep {
    UkfStatus status;
    double predictedForce = 0.0; ///< a-priori prediction of F (physical units)
};

class PinchingUkf {
public:
    using Box = std::array<ParameterBounds, kPinchingUkfParameters>;

    /// box: finite lower <= upper per parameter (pinchingUkfParameterNames() order) keeping
    /// the law admissible apart from beta + gamma; throws std::invalid_argument otherwise.
    PinchingUkf(const BoucWenPinchingParameters& initial, const Box& box,
                const PinchingUkfSettings& settings = {});

    /// Restart at `estimate` with the law's state `state` at the deformation u (physical),
    /// parameter standard deviations sd (z and e: 1e-3), the settings' Q and R.
    void restart(const BoucWenPinchingParameters& estimate, const BoucWenState& state, double u,
                 const std::array<double, kPinchingUkfParameters>& sd);
    void setSettings(const PinchingUkfSettings& s) { m_settings = s; }
    const PinchingUkfSettings& settings() const { return m_settings; }

    PinchingUkfStep step(double deformation, double force);

    /// The estimate (fixed parameters included).
    BoucWenPinchingParameters estimate() const;
    std::array<double, kPinchingUkfParameters> standardDeviation() const;
    BoucWenState state() const;
    const Box& box() const { return m_box; }

    /// Value of parameter j (pinchingUkfParameterNames() order) of p, by reference.
    static double& field(BoucWenPinchingParameters& p, int j);
    static double field(const BoucWenPinchingParameters& p, int j);

private:
    void applyNoiseAndBounds();
    BoucWenPinchingParameters fromState(const Eigen::Ref<const Eigen::VectorXd>& x) const;

    BoucWenPinchingParameters m_fixed; ///< A0, deltaA, uRef, fRef (and the initial values)
    Box m_box;
    PinchingUkfSettings m_settings;
    UnscentedKalmanFilter m_ukf;
    double m_x = 0.0; ///< last normalized deformation
};

} // namespace hsmu
