#pragma once
// BoucWenUkf: joint state-parameter estimation of one Bouc-Wen element by the UKF
// (docs/method.md, The paper's UKF; paper Eqs 7-15), driven each step by the specimen's
// measured deformation and force.
//
// State (paper Eq. 8, indices BoucWenUkfIndex): x = [z, e, k0, alpha, beta, gamma, n,
// deltaNu, deltaEta], in the law's normalized units: deformation x = u / uRef, force
// f = F / fRef, k0 normalized (physical stiffness k0 fRef / uRef). A0, deltaA, uRef and fRef
// are fixed at their initial values (the paper updates all but A0 and deltaA).
//
// One step, for the measured (u, F) of a committed integration step (physical units):
//   process (Eq. 11): (z, e) <- BoucWen::integrate(parameters of the sigma point, (z, e),
//                     dx = u / uRef - previous u / uRef) (BoucWen.h, Eqs 2-6); parameters
//                     follow a random walk (unchanged, plus Q). All sigma points at once by
//                     BoucWen::integrateStates(BatchMath::Fast): |z|^n within 1 ulp of
//                     std::pow on processors with AVX2, so results can differ between
//                     machines in the last digits (about 1e-6 relative over a whole run)
//   measurement (Eq. 7): h(x) = alpha k0 (u / uRef) + (1 - alpha) k0 z, compared with F / fRef
// The element starts virgin (z = e = 0, known exactly) at u = 0.
//
// Defaults (all editable between steps, effective on the next step):
//   UKF      the paper's a = 1e-4, kappa = 3 - L, b = 2
//   R        forceNoise^2 with forceNoise = 0.01: a measured-force noise of 1 % of fRef
//   Q        diagonal, std per step: z 1e-3, e 1e-3 (normalized), each parameter 1e-3 of its
//            bound width (a random walk of 5 % of the width over 2500 steps). Tuned on the
//            synthetic recovery test (8 random starts in Table III, 0 and 1 % force noise):
//            half this parameter noise, or 1e-4 on z and e, lets the estimate lock early
//            on wrong values from some starts (force NRMSE up to 20 %); 1e-3 to 2e-3 recovers
//            the force to < 1 % from all of them.
//   P0       z, e: 0 (the virgin state is known); each parameter (initialStdFraction = 0.25
//            of its bound width)^2, uncorrelated
//   bounds   Table III (k0 0.7-1.4, alpha 0.001-0.05, beta 2.5-5, gamma 0-2.5, n 1-3,
//            deltaNu 0.001-0.1, deltaEta 0.001-0.1); z and e unbounded
// Bounds: sigma points are held in [lower, upper]; the predicted and posterior means
// boundMargin (1e-3) of the width inside, so that a parameter that reached a bound can
// still leave it (see UnscentedKalmanFilter.h, Bounds). Bounds must be finite with
// lower <= upper, k0 > 0, 0 <= alpha <= 1, n > 0, deltaNu and deltaEta >= 0, and leave some
// admissible (beta, gamma): upper beta + upper gamma > 1e-3. The box need not be admissible
// as a whole: every sigma point and every posterior mean with beta + gamma below 1e-3 is
// moved along (1, 1) onto beta + gamma = 1e-3 (docs/method.md, "Admissibility"); with the
// paper's Table III (lower sum 2.5) this never happens.
// A locked parameter keeps its value: zero variance, zero Q, both bounds at its value.
//
// Faults: a sigma point whose integration fails (LawStatus not Ok), and everything the UKF
// guards, reject the step (status.ok false, with a reason). If the prediction was rejected,
// z and e of the last estimate are advanced with its own parameters by a plain integration
// (the parameters and P are kept) so that the estimator stays in step with the deformation;
// if even that fails the step is skipped (the next increment starts from the last deformation
// z and e belong to). If the update was rejected the prediction is kept.
// Thread rules: none; an instance is used by one thread at a time.

#include "core/hysteresis/BoucWen.h"
#include "core/identification/UnscentedKalmanFilter.h"

#include <array>
#include <limits>
#include <vector>

namespace hsmu {

/// Indices of the estimator state (paper Eq. 8).
enum class BoucWenUkfIndex : int { Z = 0, E, K0, Alpha, Beta, Gamma, N, DeltaNu, DeltaEta };
inline constexpr int kBoucWenUkfSize = 9;

/// "z", "e" and the law's parameter names ("k0", "alpha", ..., "deltaEta").
const char* boucWenUkfIndexName(BoucWenUkfIndex index);

struct BoucWenUkfSettings {
    UkfSettings ukf;                  ///< a, b, kappa: the paper's by default
    double forceNoise = 0.01;         ///< expected noise std of F / fRef; R = forceNoise^2
    double zNoise = 1e-3;             ///< process noise std of z per step (normalized)
    double eNoise = 1e-3;             ///< process noise std of e per step (normalized)
    double parameterNoise = 1e-3;     ///< process noise std per step, fraction of bound width
    double initialStdFraction = 0.25; ///< initial std, fraction of bound width (reset only)
    double boundMargin = 1e-3;        ///< means kept this fraction of the width inside
};

/// The outcome of one step.
struct BoucWenUkfStep {
    UkfStatus status;           ///< ok, or the fault of the rejected phase and why
    BoucWenParameters estimate; ///< k0 ... deltaEta estimated; A0, deltaA, uRef, fRef fixed
    BoucWenState state;         ///< estimated z, e (normalized)
    std::array<double, kBoucWenUkfSize> standardDeviation{};          ///< sqrt(diag P), normalized
    double predictedForce = std::numeric_limits<double>::quiet_NaN(); ///< a priori [F units]
    double filteredForce = std::numeric_limits<double>::quiet_NaN();  ///< a posteriori
};

class BoucWenUkf {
public:
    struct Bounds {
        double lower = -std::numeric_limits<double>::infinity();
        double upper = std::numeric_limits<double>::infinity();
    };
    using BoundsArray = std::array<Bounds, kBoucWenUkfSize>;

    /// Table III of the paper; z and e unbounded.
    static BoundsArray tableIIIBounds();

    /// Starts from `initial` (normalized parameters; uRef and fRef give the scales) clamped
    /// into the bounds. Invalid bounds (see the header) are replaced by Table III's; check
    /// with boundsAdmissible() first if that matters.
    explicit BoucWenUkf(const BoucWenParameters& initial, const BoucWenUkfSettings& settings = {},
                        const BoundsArray& bounds = tableIIIBounds());

    /// Restart from `initial` in the virgin state with the initial covariance; bounds, locks
    /// and settings are kept.
    void reset(const BoucWenParameters& initial);

    /// Restart at a known point of a history: the estimate (its uRef and fRef become the
    /// filter's scales), the law's state (z, e) at physical deformation `deformation`, and
    /// the standard deviations of each state entry (normalized; NaN counts as 0). Bounds,
    /// locks and settings are kept; a locked parameter takes the estimate's value.
    void restart(const BoucWenParameters& estimate, const BoucWenState& state, double deformation,
                 const std::array<double, kBoucWenUkfSize>& stddev);

    /// One committed step: measured deformation u and force F (physical units).
    BoucWenUkfStep step(double deformation, double force);

    const BoucWenUkfSettings& settings() const { return m_settings; }
    /// Effective on the next step (initialStdFraction only on reset()).
    void setSettings(const BoucWenUkfSettings& settings) {
        m_settings = settings;
        m_refreshNeeded = true;
    }

    const BoundsArray& bounds() const { return m_bounds; }
    /// Change one parameter's bounds (effective next step). False, and nothing changes, for
    /// z or e or if the law would not stay admissible. A locked parameter stays locked (its
    /// value is clamped into the new bounds).
    bool setBounds(BoucWenUkfIndex index, double lower, double upper);
    static bool boundsAdmissible(const BoundsArray& bounds);

    /// Lock (hold at its current estimate) or unlock a parameter; false for z or e. Unlocking
    /// restores the initial variance of the parameter.
    bool setLocked(BoucWenUkfIndex index, bool locked);
    bool locked(BoucWenUkfIndex index) const;

    /// The current estimate as parameters (A0, deltaA, uRef, fRef carried over).
    BoucWenParameters estimate() const;
    BoucWenState state() const;
    const UnscentedKalmanFilter& filter() const { return m_ukf; }
    /// The last deformation seen, normalized (u / uRef).
    double lastDeformation() const { return m_lastX; }

private:
    BoucWenParameters parametersOf(const Eigen::Ref<const Eigen::VectorXd>& x) const;
    void project(Eigen::Ref<Eigen::VectorXd> x, bool mean) const;
    // The boxes (sigma points and means) from bounds, margin and locks, also given to the
    // filter.
    void refreshBoxes();
    // Boxes, Q, R and the UKF settings from the current settings, bounds and locks (on the
    // first step after any of them changed).
    void refresh();
    BoucWenUkfStep result(UkfStatus status, double predicted) const;
    double initialVariance(int i) const;

    BoucWenParameters m_fixed; ///< A0, deltaA, uRef, fRef (and the initial values)
    BoucWenUkfSettings m_settings;
    BoundsArray m_bounds;
    std::array<bool, kBoucWenUkfSize> m_locked{};
    std::array<double, kBoucWenUkfSize> m_lockedValue{};
    std::array<double, kBoucWenUkfSize> m_sigmaLower{}, m_sigmaUpper{}, m_meanLower{},
        m_meanUpper{};
    UnscentedKalmanFilter m_ukf;
    Eigen::MatrixXd m_Q, m_R;
    // The sigma points as the law's parameters and states, and their integrations (kept: no
    // allocation per step).
    std::vector<BoucWenParameters> m_sigmaParameters;
    std::vector<BoucWenState> m_sigmaStates;
    std::vector<BoucWenIncrement> m_sigmaIncrements;
    Eigen::VectorXd m_measured;  ///< F / fRef of the step (kept: no allocation per step)
    bool m_refreshNeeded = true; ///< settings, bounds or locks changed since refresh()
    double m_lastX = 0.0;        ///< normalized deformation of the last step
    double m_x = 0.0;            ///< normalized deformation of the step being processed
};

} // namespace hsmu
