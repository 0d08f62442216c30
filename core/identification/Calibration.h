#pragma once
// Calibration: the global-then-local least-squares fit of a hysteresis law to a measured
// history (docs/method.md, "Offline calibration"). It minimizes, over the fitted parameters
// p inside their box (and the law's admissible set),
//   J(p) = 1/2 sum_k ((F_law(u_0 .. u_k; p) - F_k) / rms(F))^2
// with the law replayed from its virgin state along the measured deformations (the force of
// a hysteretic law depends on the whole path), so that sqrt(2 J / N) is the NRMSE.
//
// 1. Global: Levenberg-Marquardt (LevenbergMarquardt.h) from every start of the spec on a
//    reduced history (ReducedHistory: the turning points and about `reducedSamples` samples
//    spread along the deformation path; a rate-independent law sees the same path).
// 2. Local: the `polished` best starts are refined by Levenberg-Marquardt on the whole
//    history; the best is the result.
// 3. Statistics at the result, on the free parameters (those not on a bound): the Gauss-
//    Newton covariance s^2 (J^T J)^-1 with s^2 = sum r^2 / (N - p) (in the law's units), its
//    standard deviations, 95 % intervals (+-1.96 sd) and correlations. Residuals of a
//    hysteresis fit are strongly correlated in time, so the intervals are optimistic: read
//    them as the local conditioning of the fit (the beta-gamma trade-off shows as a
//    correlation near +-1), not as a confidence level.
// Parameters are in the law's own units (normalized for Bouc-Wen laws: uRef / fRef are
// fixed parameters of the spec). Cost: one replay of the history per residual evaluation.
// Thread rules: none; calibrate() may run on any thread with its own inputs.

#include "core/identification/LevenbergMarquardt.h"

#include <Eigen/Core>

#include <atomic>
#include <functional>

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace hsmu {

struct CalibrationSpec {
    std::string law = "boucWen";               ///< LawFactory name
    std::map<std::string, double> fixed;       ///< the other parameters (e.g. A0, uRef, fRef)
    struct Parameter {
        std::string name;
        double lower = 0.0, upper = 0.0; ///< the box (finite)
        double typical = 1.0;            ///< scale for difference steps and tolerances (> 0)
        /// The part of the box the global phase searches (NaN: the whole box); the local
        /// phase always uses the whole box. Narrower where the wanted basin is known to lie
        /// (e.g. the pinching search keeps pinching on until the polish).
        double searchLower = std::numeric_limits<double>::quiet_NaN();
        double searchUpper = std::numeric_limits<double>::quiet_NaN();
    };
    std::vector<Parameter> fitted;
    /// The samples' times [s], needed by a rate-dependent law (HysteresisLaw.h; mrDamper) and
    /// ignored by the others: each replayed sample k gets the time increment
    /// historyTimeIncrement(time, k), the first quasi-static; both phases then replay every
    /// sample (a reduced history would change the velocities).
    std::vector<double> time;
    /// Starting points (values of the fitted parameters, in `fitted` order); clamped into
    /// the box and made admissible.
    std::vector<std::vector<double>> starts;
    std::size_t reducedSamples = 800; ///< target size of the reduced history (global phase)
    /// A screening before the global phase (empty: none): each point (values of the fitted
    /// parameters, clamped into the search range and made admissible) costs one replay of a
    /// reduced history of screenSamples samples, and the screenKept best join the starts
    /// (e.g. a space-filling design over a box too wide for a minimization per point). A
    /// point's replay stops as soon as its running squared error passes the worst of the
    /// screenKept best so far (it cannot be kept then): the same points are kept.
    std::vector<std::vector<double>> screened;
    std::size_t screenSamples = 300;
    int screenKept = 8;
    /// Score only the last `window` samples (0 = all): the law is still replayed from the
    /// first sample (its force depends on the whole path), J and the NRMSE sum over the last
    /// `window` samples and are scaled by their RMS force (the online refits of
    /// NelderMeadIdentifier that follow a degrading specimen).
    std::size_t window = 0;
    int polished = 1;                 ///< best starts refined on the whole history
    /// A budget for the local phase (0 = none): on a history longer than this it runs on the
    /// reduced history of this many samples (reducedHistory) instead of the whole one (its
    /// NRMSE and statistics are then over those samples). Not with a window.
    std::size_t polishSamples = 0;
    LevenbergMarquardtSettings global{30, 1e-6, 1e-8, 1e-6, 1e-2};
    LevenbergMarquardtSettings local{20, 1e-6, 1e-10, 1e-6, 1e-3};
    /// Set by another thread: the calibration stops before its next Levenberg-Marquardt
    /// iteration or start and returns not ok, `cancelled`. May be null.
    const std::atomic<bool>* cancel = nullptr;
    /// Called on the calling thread after each start of the global phase and each polish,
    /// with how many of the two phases' minimizations are done and their total (a long
    /// calibration's progress, `hsmu replay`). May be empty.
    std::function<void(int done, int total)> progress;
};

struct CalibrationResult {
    bool ok = false;
    bool cancelled = false;                   ///< stopped by spec.cancel (then not ok)
    std::string reason;                       ///< why not, when !ok
    std::map<std::string, double> parameters; ///< every parameter of the law at the optimum
    std::vector<std::string> names;           ///< the fitted parameters, in spec order
    Eigen::VectorXd estimate;                 ///< [p] fitted values
    Eigen::VectorXd standardDeviation;        ///< [p] NaN on a bound (not free)
    Eigen::MatrixXd correlation;              ///< [p x p] NaN rows / columns on a bound
    std::vector<bool> onBound;                ///< [p] the value sits on its box
    double rmsError = 0.0;                    ///< RMS(F_law - F) [force units] (scored samples)
    double nrmse = 0.0;                       ///< rmsError / RMS(F) [-] (scored samples)
    int startsTried = 0;
    int residualEvaluations = 0;
    double computeSeconds = 0.0; ///< wall time [s]
    /// The offset test of calibrateHistory (CalibrationDefaults.h, "Offsets"), when it ran.
    struct OffsetTest {
        bool ran = false;      ///< a fit with offsets was made (offsets on or auto)
        bool used = false;     ///< the result is that fit (its parameters hold the offsets)
        double nrmseWithout = 0.0, nrmseWith = 0.0; ///< the two fits' NRMSE [-]
        int branches = 0;      ///< N_eff: the history's branches (reversals + 1)
        double criterion = 0.0; ///< N_eff ln(RSS_with / RSS_without) + 2 ln N_eff (< 0: kept)
        /// The fit without offsets' parameters on a bound (the reference of an identifier that
        /// fits none, e.g. the online filters, when the offsets are kept).
        std::vector<std::string> onBoundWithout;
    } offsetTest;
};

/// The fit of spec.law to the history (equal sizes >= 3, finite). Not ok, with a reason, for
/// an unknown law or parameter, an empty or inverted box, or if no start can be replayed.
CalibrationResult calibrate(const std::vector<double>& deformation,
                            const std::vector<double>& force, const CalibrationSpec& spec);

/// Samples kept for the global phase: the first and last, every turning point (dead band 1 %
/// of the range) and, between them, a sample each time the deformation has moved a further
/// (path length / target) since the last kept one. All samples if there are fewer than
/// target.
std::vector<std::size_t> reducedHistory(const std::vector<double>& deformation,
                                        std::size_t target);

/// The admissible set of the Bouc-Wen-class laws used by the fits: beta + gamma >= a small
/// margin (the law needs beta + gamma > 0); x is moved along (1, 1) in (beta, gamma) when
/// it is outside. iBeta, iGamma: positions in x (-1 if not fitted: then nothing to do).
void projectBetaGamma(Eigen::VectorXd& x, int iBeta, int iGamma, double fixedBeta,
                      double fixedGamma);

} // namespace hsmu
