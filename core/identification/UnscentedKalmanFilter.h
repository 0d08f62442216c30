#pragma once
// UnscentedKalmanFilter: a generic, dynamic-size unscented Kalman filter (docs/method.md, The
// paper's UKF; paper Eqs 7-15) with guarded numerics. API after mherb/kalman: predict(f) then
// update(h, z).
//
// Scaled unscented transform, L = state size, 2L + 1 sigma points (paper Eqs 9, 10, 13):
//   lambda = a^2 (L + kappa) - L,   c = sqrt(L + lambda)
//   chi_0 = x,  chi_i = x + c S_i,  chi_{L+i} = x - c S_i     (S_i = column i of chol(P))
//   Wm_0 = lambda / (L + lambda),  Wc_0 = Wm_0 + (1 - a^2 + b),  W_i = 1 / (2 (L + lambda))
// The paper's a = 1e-4, kappa = 3 - L gives Wm_0 ~ -3e8 and W_i ~ 1.7e7: the textbook sums
// sum_i Wm_i Y_i and sum_i Wc_i (Y_i - ybar)(Y_i - ybar)^T cancel catastrophically. Both are
// therefore evaluated in deviation form, with d_i = Y_i - Y_0 (i >= 1) and sum_{i>=1} W_i =
// 1 - Wm_0, which is algebraically identical:
//   mu   = sum_{i>=1} W_i d_i,                      ybar = Y_0 + mu              (Eqs 12, 14)
//   P_yy = sum_{i>=1} W_i d_i d_i^T + (b - a^2) mu mu^T (+ Q or R)              (Eqs 12, 14)
//   P_xy = sum_{i>=1} W_i dx_i dy_i^T + (b - a^2) mux muy^T                          (Eq. 15)
// Only positive weights and a modest (b - a^2) multiply the outer products. Two roundings
// would still be multiplied by W_i in the means: that of x in x +- d (the pair is built as
// x + d and x - ((x + d) - x), exactly opposite) and that of f itself in the second
// difference d_i+ + d_i- of a pair, which is set to zero where it is below 8 eps times the
// three function values (it is noise there: ~1e-8 relative offsets for a linear f otherwise).
// Update (Eq. 15; its "y-" in the mean update is a typo for x-): K = P_xy P_yy^-1,
// x+ = xbar + K (z - ybar), P+ = P - K P_yy K^T. Sigma points are redrawn from the predicted
// (x, P) in update(), so the filter equals the Kalman filter exactly on a linear-Gaussian
// problem; being exactly symmetric about the centre, they give mux = 0.
//
// Guarded numerics. P is symmetrized; a component with exactly zero variance is known (e.g. a
// locked parameter): it is left out of the Cholesky factor and its sigma points carry no
// spread along it. The factor of the rest is a Cholesky LLT (UkfKernels.h; kept with an
// accepted covariance for the next draw), retried with P + delta I for delta =
// jitterStart * mean variance, growing tenfold up to jitterMax * mean variance. A step
// whose function values, mean or covariance are not finite, or whose covariance cannot be
// factored even with the largest jitter, is rejected: x and P keep their last good values and
// the status gives the fault and a reason. A covariance accepted with jitter is stored
// repaired (with the jitter added).
//
// Bounds: optional boxes, one for sigma points and one for means (the predicted and the
// posterior mean; the centre sigma point is held in it too); a point is projected into a box
// by clamping each component (std::clamp). Because W_i ~ 1e7, moving one point of a pair by delta
// would shift the mean by W_i delta; a pair that leaves the set is therefore shrunk as a
// whole, to chi = x +- t c S_i with the largest t in (0, 1] keeping both points admissible,
// and weighted W_i / t^2. Any pair +-t c S_i with weight 1 / (2 t^2 c^2) reproduces the
// mean and the covariance S_i S_i^T along its direction, so the transform stays exact to
// second order (only the fourth moments change). t is read off the clamped points component
// by component, which is exact for a box. A pair with no room at all (t = 0: the centre on the
// boundary, the direction pointing out) is dropped: the update leaves its variance untouched,
// the prediction loses it (it grows again by Q). Estimators therefore keep their means a
// margin inside the bounds (the mean box) while sigma points may use the whole box.
//
// Functions: process f and measurement h are callables in one of three forms,
//   Eigen::VectorXd f(const Eigen::VectorXd& x)                                  or
//   R f(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> out)  or
//   AllSigmaPoints{g}: Eigen::Index g(const Eigen::MatrixXd& x, Eigen::MatrixXd& out)
// with R void or bool (false = the function failed at that point: the step is rejected).
// The second form writes into preallocated storage (no allocation per sigma point); the third
// evaluates all sigma points (the columns of x; out is preallocated) in one call and returns
// the first column at which it failed, or -1: for functions that gain from seeing all points
// at once (the Bouc-Wen estimator interleaves their integrations).
// Thread rules: none; an instance is used by one thread at a time.

#include "core/identification/UkfKernels.h"
#include "core/identification/UkfStatus.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace hsmu {

/// Marks a function that evaluates all sigma points in one call (see the header comment).
template <class G> struct AllSigmaPoints { G function; };
template <class G> AllSigmaPoints(G) -> AllSigmaPoints<G>;

template <class T> inline constexpr bool isAllSigmaPoints = false;
template <class G> inline constexpr bool isAllSigmaPoints<AllSigmaPoints<G>> = true;

/// Unscented-transform settings; all editable between steps (effective on the next call).
struct UkfSettings {
    double a = 1e-4;             ///< spread of the sigma points, > 0 (paper: 1e-4)
    double b = 2.0;              ///< prior-distribution term (2 = Gaussian; paper: 2)
    std::optional<double> kappa; ///< secondary scaling; unset = 3 - L (paper); L + kappa > 0
    double jitterStart = 1e-12;  ///< first jitter, relative to the mean variance
    double jitterMax = 1e-6;     ///< largest jitter, relative to the mean variance
};

class UnscentedKalmanFilter {
public:
    using Vector = Eigen::VectorXd;
    using Matrix = Eigen::MatrixXd;

    UnscentedKalmanFilter() = default;
    explicit UnscentedKalmanFilter(const UkfSettings& settings) : m_settings(settings) {}

    /// Set the state. Rejected (nothing changes) if sizes differ, a value is not finite or P
    /// is not positive semi-definite. Q is reset to zero (L x L).
    UkfStatus init(const Vector& x0, const Matrix& P0);
    bool initialized() const { return m_initialized; }

    void setSettings(const UkfSettings& settings) { m_settings = settings; }
    const UkfSettings& settings() const { return m_settings; }
    /// Process noise (L x L, added to the predicted covariance). Its definiteness is checked
    /// through the predicted covariance: a slightly indefinite Q is absorbed by the jitter, a
    /// clearly indefinite one makes predict() fail with NotPositiveDefinite.
    UkfStatus setProcessNoise(const Matrix& Q);
    /// Measurement noise (m x m); fixes the measurement size m expected by update().
    UkfStatus setMeasurementNoise(const Matrix& R);
    /// Bounds (see the header comment), component-wise, +-infinity where a component is
    /// unbounded: sigma points in [sigmaLower, sigmaUpper], means in [meanLower, meanUpper]
    /// (e.g. held a margin inside the box the sigma points may use). Effective on the next
    /// call. Rejected (nothing changes) unless the four have one size (the state's, once it
    /// is set; checked again at each step) and lower <= upper everywhere (no NaN).
    UkfStatus setBounds(const Vector& sigmaLower, const Vector& sigmaUpper, const Vector& meanLower,
                        const Vector& meanUpper);
    /// One box for sigma points and means.
    UkfStatus setBounds(const Vector& lower, const Vector& upper) {
        return setBounds(lower, upper, lower, upper);
    }
    void clearBounds();
    bool bounded() const { return m_bounded; }

    /// Directly overwrite the state (e.g. lock a component). Same checks as init().
    UkfStatus setState(const Vector& x, const Matrix& P);

    /// Time update with the process function (see the header comment for its forms).
    template <class F> UkfStatus predict(F&& f);
    /// Measurement update with measurement function h and measurement z (size m).
    template <class H> UkfStatus update(H&& h, const Vector& z);

    const Vector& state() const { return m_x; }
    const Matrix& covariance() const { return m_P; }
    /// sqrt(diag P).
    Vector standardDeviations() const;
    /// Predicted measurement ybar and innovation covariance P_yy computed by the last update()
    /// (those of the accepted step after an accepted update).
    const Vector& predictedMeasurement() const { return m_yHat; }
    const Matrix& innovationCovariance() const { return m_Pyy; }

private:
    struct Weights {
        double other = 0.0, spread = 0.0; // W_i and c
    };
    UkfStatus computeWeights(Weights& w) const;
    // Adds the jitter to the variances of the components factor() last found active.
    void addJitter(Matrix& P, double jitter) const;
    // Cholesky factor of P (zero columns for zero-variance components) into m_sqrt.
    UkfStatus factor(const Matrix& P, const char* what);
    // Weights, factor of m_P (reused when m_sqrt is already its factor), the sigma points
    // m_sigma (L x 2L+1), their deviations m_dx (L x 2L) and the weights m_weight (2L).
    UkfStatus drawSigmaPoints();
    // Shrinks pair j of m_sigma (plus point only; see the header), where the box moved it.
    void shrinkPair(Eigen::Index j);
    // Clamps n values at v into [lower, upper] (the sigma-point or the mean box).
    static void clampInto(double* v, const Vector& lower, const Vector& upper);
    UkfStatus finishPredict(double jitter);
    UkfStatus acceptCandidate(const char* phase, double jitter);
    UkfStatus finishUpdate(const Vector& z, double jitter);

    template <class F>
    bool evaluate(F& f, const Matrix& in, Matrix& out, Eigen::Index rows, UkfStatus& status,
                  const char* what);

    UkfSettings m_settings;
    bool m_bounded = false;
    Vector m_sigmaLower, m_sigmaUpper, m_meanLower, m_meanUpper;
    bool m_initialized = false;
    Vector m_x;
    Matrix m_P, m_Q, m_R;
    Vector m_yHat;
    Matrix m_Pyy;

    // Workspace (kept to avoid allocations per step; the process (f) and the measurement (h)
    // have their own, of their own sizes).
    Weights m_w;
    bool m_sqrtIsOfP = false; ///< m_sqrt is the factor of the current m_P
    Matrix m_sqrt, m_sub, m_sigma, m_dx, m_newP, m_Pxy, m_gain, m_lowerYy;
    Matrix m_fOut, m_fDev, m_hOut, m_hDev; // function values, deviations from the centre's
    Vector m_fMu, m_hMu;                   // their mean offsets
    Vector m_centre, m_step, m_plus, m_minus, m_weight, m_newX, m_innovation;
    std::vector<int> m_active;
};

template <class F>
bool UnscentedKalmanFilter::evaluate(F& f, const Matrix& in, Matrix& out, Eigen::Index rows,
                                     UkfStatus& status, const char* what) {
    using ConstRef = const Eigen::Ref<const Vector>&;
    using OutRef = Eigen::Ref<Vector>;
    out.resize(rows, in.cols());
    if constexpr (isAllSigmaPoints<std::remove_cvref_t<F>>) {
        const Eigen::Index failed = f.function(in, out);
        if (failed >= 0) {
            status = {false, UkfFault::FunctionFailed,
                      std::string(what) + " failed at sigma point " + std::to_string(failed)};
            return false;
        }
    } else {
        for (Eigen::Index i = 0; i < in.cols(); ++i) {
            bool good = true;
            if constexpr (std::is_invocable_v<F&, ConstRef, OutRef>) {
                OutRef column = out.col(i);
                if constexpr (std::is_same_v<std::invoke_result_t<F&, ConstRef, OutRef>, bool>) {
                    good = f(in.col(i), column);
                } else {
                    f(in.col(i), column);
                }
            } else {
                const Vector y = f(Vector(in.col(i)));
                if (y.size() != rows) {
                    status = {false, UkfFault::DimensionMismatch,
                              std::string(what) + " returned a vector of size " +
                                  std::to_string(y.size()) + ", expected " + std::to_string(rows)};
                    return false;
                }
                out.col(i) = y;
            }
            if (!good) {
                status = {false, UkfFault::FunctionFailed,
                          std::string(what) + " failed at sigma point " + std::to_string(i)};
                return false;
            }
        }
    }
    if (!ukfkernels::allFinite(out)) {
        Eigen::Index i = 0;
        while (i + 1 < out.cols() && out.col(i).allFinite()) {
            ++i;
        }
        status = {false, UkfFault::NonFiniteValue,
                  std::string(what) + " returned a non-finite value at sigma point " +
                      std::to_string(i)};
        return false;
    }
    return true;
}

template <class F> UkfStatus UnscentedKalmanFilter::predict(F&& f) {
    UkfStatus status = drawSigmaPoints();
    if (!status.ok) {
        return status;
    }
    if (!evaluate(f, m_sigma, m_fOut, m_x.size(), status, "the process function")) {
        return status;
    }
    return finishPredict(status.jitter);
}

template <class H> UkfStatus UnscentedKalmanFilter::update(H&& h, const Vector& z) {
    if (m_initialized && z.size() != m_R.rows()) {
        return {false, UkfFault::DimensionMismatch,
                "measurement has size " + std::to_string(z.size()) + " but R is " +
                    std::to_string(m_R.rows()) + " x " + std::to_string(m_R.rows())};
    }
    UkfStatus status = drawSigmaPoints();
    if (!status.ok) {
        return status;
    }
    if (!evaluate(h, m_sigma, m_hOut, m_R.rows(), status, "the measurement function")) {
        return status;
    }
    return finishUpdate(z, status.jitter);
}

} // namespace hsmu
