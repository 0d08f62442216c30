#include "core/identification/UnscentedKalmanFilter.h"

#include <string>

#include "core/identification/UkfKernels.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hsmu {

namespace {

std::string sizeText(Eigen::Index rows, Eigen::Index cols) {
    return std::to_string(rows) + " x " + std::to_string(cols);
}

// Second differences below this many eps of the three function values are rounding noise.
constexpr double kRoundingFloor = 8.0 * std::numeric_limits<double>::epsilon();

} // namespace

UkfStatus UnscentedKalmanFilter::init(const Vector& x0, const Matrix& P0) {
    UkfStatus status = setState(x0, P0);
    if (!status.ok) {
        return status;
    }
    m_Q = Matrix::Zero(x0.size(), x0.size());
    if (m_R.rows() == 0) {
        m_R = Matrix::Identity(1, 1);
    }
    return status;
}

UkfStatus UnscentedKalmanFilter::setState(const Vector& x, const Matrix& P) {
    if (x.size() == 0 || P.rows() != x.size() || P.cols() != x.size()) {
        return {false, UkfFault::DimensionMismatch,
                "state of size " + std::to_string(x.size()) + " with a covariance of size " +
                    sizeText(P.rows(), P.cols())};
    }
    if (!x.allFinite()) {
        return {false, UkfFault::NonFiniteValue, "the state is not finite"};
    }
    Matrix symmetric = P;
    ukfkernels::symmetrize(symmetric);
    UkfStatus status = factor(symmetric, "the covariance");
    if (!status.ok) {
        return status;
    }
    addJitter(symmetric, status.jitter);
    m_x = x;
    m_P = symmetric;
    m_sqrtIsOfP = true;
    if (m_Q.rows() != x.size()) {
        m_Q = Matrix::Zero(x.size(), x.size());
    }
    m_initialized = true;
    return status;
}

UkfStatus UnscentedKalmanFilter::setProcessNoise(const Matrix& Q) {
    if (m_initialized && (Q.rows() != m_x.size() || Q.cols() != m_x.size())) {
        return {false, UkfFault::DimensionMismatch,
                "Q is " + sizeText(Q.rows(), Q.cols()) + ", expected " +
                    sizeText(m_x.size(), m_x.size())};
    }
    if (!Q.allFinite()) {
        return {false, UkfFault::NonFiniteValue, "Q is not finite"};
    }
    m_Q = Q;
    return {};
}

UkfStatus UnscentedKalmanFilter::setMeasurementNoise(const Matrix& R) {
    if (R.rows() == 0 || R.rows() != R.cols()) {
        return {false, UkfFault::DimensionMismatch,
                "R is " + sizeText(R.rows(), R.cols()) + ", expected a square matrix"};
    }
    if (!R.allFinite()) {
        return {false, UkfFault::NonFiniteValue, "R is not finite"};
    }
    m_R = R;
    return {};
}

UkfStatus UnscentedKalmanFilter::setBounds(const Vector& sigmaLower, const Vector& sigmaUpper,
                                           const Vector& meanLower, const Vector& meanUpper) {
    const Eigen::Index n = sigmaLower.size();
    if (sigmaUpper.size() != n || meanLower.size() != n || meanUpper.size() != n ||
        (m_initialized && n != m_x.size())) {
        return {false, UkfFault::DimensionMismatch, "the bounds do not have the state's size"};
    }
    for (Eigen::Index i = 0; i < n; ++i) {
        if (!(sigmaLower(i) <= sigmaUpper(i)) || !(meanLower(i) <= meanUpper(i))) {
            return {false, UkfFault::InvalidSettings,
                    "lower bound above upper bound (or NaN) at component " + std::to_string(i)};
        }
    }
    m_sigmaLower = sigmaLower;
    m_sigmaUpper = sigmaUpper;
    m_meanLower = meanLower;
    m_meanUpper = meanUpper;
    m_bounded = true;
    return {};
}

void UnscentedKalmanFilter::clearBounds() {
    m_bounded = false;
}

void UnscentedKalmanFilter::clampInto(double* v, const Vector& lower, const Vector& upper) {
    for (Eigen::Index i = 0; i < lower.size(); ++i) {
        v[i] = std::clamp(v[i], lower(i), upper(i));
    }
}

UnscentedKalmanFilter::Vector UnscentedKalmanFilter::standardDeviations() const {
    return m_P.diagonal().cwiseMax(0.0).cwiseSqrt();
}

UkfStatus UnscentedKalmanFilter::computeWeights(Weights& w) const {
    const double n = static_cast<double>(m_x.size());
    const double a = m_settings.a;
    const double kappa = m_settings.kappa.value_or(3.0 - n);
    const double b = m_settings.b;
    if (!(std::isfinite(a) && a > 0.0) || !std::isfinite(b) || !std::isfinite(kappa)) {
        return {false, UkfFault::InvalidSettings, "a must be finite and > 0, b and kappa finite"};
    }
    if (!(n + kappa > 0.0)) {
        return {false, UkfFault::InvalidSettings, "L + kappa must be > 0"};
    }
    if (!(m_settings.jitterStart > 0.0 && m_settings.jitterMax >= m_settings.jitterStart)) {
        return {false, UkfFault::InvalidSettings, "need 0 < jitterStart <= jitterMax"};
    }
    const double nPlusLambda = a * a * (n + kappa);
    w.other = 0.5 / nPlusLambda;
    w.spread = std::sqrt(nPlusLambda);
    if (!std::isfinite(w.other) || !std::isfinite(w.spread) || w.spread == 0.0) {
        return {false, UkfFault::InvalidSettings, "the sigma-point weights are not finite"};
    }
    return {};
}

void UnscentedKalmanFilter::addJitter(Matrix& P, double jitter) const {
    if (jitter == 0.0) {
        return;
    }
    for (const int j : m_active) {
        P(j, j) += jitter;
    }
}

UkfStatus UnscentedKalmanFilter::factor(const Matrix& P, const char* what) {
    m_sqrtIsOfP = false;
    const Eigen::Index n = P.rows();
    if (!ukfkernels::allFinite(P)) {
        return {false, UkfFault::NonFiniteValue, std::string(what) + " is not finite"};
    }
    m_active.clear();
    double scale = 0.0;
    for (Eigen::Index j = 0; j < n; ++j) {
        const double v = P(j, j);
        if (v < 0.0) {
            return {false, UkfFault::NotPositiveDefinite,
                    std::string(what) + " has a negative variance at component " +
                        std::to_string(j)};
        }
        if (v > 0.0) {
            m_active.push_back(static_cast<int>(j));
            scale += v;
        }
    }
    if (m_active.empty()) {
        m_sqrt.setZero(n, n);
        return {};
    }
    scale /= static_cast<double>(m_active.size());
    const bool allActive = static_cast<Eigen::Index>(m_active.size()) == n;
    if (!allActive) {
        // A zero-variance component must be uncorrelated; tolerate round-off of jitter size.
        for (Eigen::Index j = 0; j < n; ++j) {
            if (P(j, j) == 0.0 && P.row(j).cwiseAbs().maxCoeff() > m_settings.jitterMax * scale) {
                return {false, UkfFault::NotPositiveDefinite,
                        std::string(what) +
                            " has zero variance but non-zero covariance at component " +
                            std::to_string(j)};
            }
        }
    }
    double jitter = 0.0;
    for (;;) {
        if (allActive) {
            m_sub = P;
        } else {
            m_sub = P(m_active, m_active);
        }
        m_sub.diagonal().array() += jitter;
        if (ukfkernels::choleskyInPlace(m_sub)) {
            break;
        }
        jitter = jitter == 0.0 ? m_settings.jitterStart * scale : 10.0 * jitter;
        if (jitter > m_settings.jitterMax * scale * (1.0 + 1e-9)) {
            return {false, UkfFault::NotPositiveDefinite,
                    std::string(what) + " is not positive definite even with a jitter of " +
                        std::to_string(m_settings.jitterMax) + " x the mean variance"};
        }
    }
    if (allActive) {
        m_sqrt.swap(m_sub);
    } else {
        m_sqrt.setZero(n, n);
        const auto k = m_active.size();
        for (std::size_t c = 0; c < k; ++c) {
            for (std::size_t r = c; r < k; ++r) {
                m_sqrt(m_active[r], m_active[c]) =
                    m_sub(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c));
            }
        }
    }
    UkfStatus status;
    status.jitter = jitter;
    return status;
}

UkfStatus UnscentedKalmanFilter::drawSigmaPoints() {
    if (!m_initialized) {
        return {false, UkfFault::NotInitialized, "the filter has not been initialized"};
    }
    UkfStatus status = computeWeights(m_w);
    if (!status.ok) {
        return status;
    }
    if (!m_sqrtIsOfP) {
        status = factor(m_P, "the covariance");
        if (!status.ok) {
            return status;
        }
        addJitter(m_P, status.jitter);
        m_sqrtIsOfP = true;
    }
    const Eigen::Index n = m_x.size();
    if (m_bounded && m_sigmaLower.size() != n) {
        return {false, UkfFault::DimensionMismatch, "the bounds do not have the state's size"};
    }
    m_centre = m_x;
    if (m_bounded) {
        clampInto(m_centre.data(), m_meanLower, m_meanUpper);
    }
    // chi_0 = x, chi_j = x + c S_j, chi_n+j = x - c S_j.
    m_sigma.resize(n, 2 * n + 1);
    m_weight.setConstant(2 * n, m_w.other);
    double* plus = m_sigma.data() + n;
    double* minus = plus + n * n;
    m_sigma.col(0) = m_centre;
    if (!m_bounded) {
        ukfkernels::offsetColumns(m_centre, m_sqrt, m_w.spread, plus);
    } else {
        // Usually no point leaves the box, which the points show as they are written; else
        // pair by pair.
        const bool plusOut = ukfkernels::offsetColumnsOutside(m_centre, m_sqrt, m_w.spread, plus,
                                                              m_sigmaLower, m_sigmaUpper);
        const bool minusOut = ukfkernels::offsetColumnsOutside(m_centre, m_sqrt, -m_w.spread, minus,
                                                               m_sigmaLower, m_sigmaUpper);
        if (!ukfkernels::allFinite(m_centre.data(), n) || plusOut || minusOut) {
            for (Eigen::Index j = 0; j < n; ++j) {
                shrinkPair(j);
            }
        }
    }
    // Exactly opposite deviations: (x + d) - x is exact, so each pair sums to zero and no
    // rounding of x is multiplied by W_i.
    ukfkernels::mirrorColumns(m_centre, plus, minus);
    return status;
}

void UnscentedKalmanFilter::shrinkPair(Eigen::Index j) {
    const Eigen::Index n = m_x.size();
    // Shrink factor from the components the clamp moves (t = 1 if none).
    double t = 1.0;
    for (const Eigen::Index c : {j, n + j}) {
        const double* point = m_sigma.data() + (1 + c) * n;
        for (Eigen::Index r = 0; r < n; ++r) {
            const double projected = std::clamp(point[r], m_sigmaLower(r), m_sigmaUpper(r));
            if (projected != point[r]) {
                t = std::min(t,
                             std::max(0.0, (projected - m_centre(r)) / (point[r] - m_centre(r))));
            }
        }
    }
    // Rounding may leave the shrunk pair an ulp outside: shrink a little more.
    for (int attempt = 0; t < 1.0 && t > 0.0; ++attempt) {
        m_plus = m_centre + t * m_w.spread * m_sqrt.col(j);
        m_minus = m_centre - (m_plus - m_centre);
        m_step = m_plus;
        clampInto(m_step.data(), m_sigmaLower, m_sigmaUpper);
        bool inside = m_step == m_plus;
        m_step = m_minus;
        clampInto(m_step.data(), m_sigmaLower, m_sigmaUpper);
        if (inside && m_step == m_minus) {
            break;
        }
        t = attempt < 3 ? t * (1.0 - 1e-9) : 0.0;
    }
    if (t < 1.0) {
        m_sigma.col(1 + j) = t > 0.0 ? m_plus : m_centre;
        m_weight(j) = m_weight(n + j) = t > 0.0 ? m_w.other / (t * t) : 0.0;
    }
}

UkfStatus UnscentedKalmanFilter::finishPredict(double jitter) {
    if (m_Q.rows() != m_x.size() || m_Q.cols() != m_x.size()) {
        return {false, UkfFault::DimensionMismatch,
                "Q is " + sizeText(m_Q.rows(), m_Q.cols()) + ", expected " +
                    sizeText(m_x.size(), m_x.size())};
    }
    const double cross = m_settings.b - m_settings.a * m_settings.a;
    ukfkernels::pairMoments(m_fOut, m_weight, kRoundingFloor, m_fDev, m_fMu);
    m_newX = m_fOut.col(0) + m_fMu;
    ukfkernels::weightedGram(m_fDev, m_weight, m_newP);
    ukfkernels::addScaledOuter(m_newP, cross, m_fMu);
    m_newP += m_Q;
    ukfkernels::symmetrize(m_newP); // Q may be slightly asymmetric
    return acceptCandidate("predicted", jitter);
}

UkfStatus UnscentedKalmanFilter::finishUpdate(const Vector& z, double jitter) {
    if (!z.allFinite()) {
        return {false, UkfFault::NonFiniteValue, "the measurement is not finite"};
    }
    const double cross = m_settings.b - m_settings.a * m_settings.a;
    // The sigma points are exactly symmetric about the centre (drawSigmaPoints): mux = 0.
    ukfkernels::deviations(m_sigma, m_dx); // column 0 is m_centre
    ukfkernels::pairMoments(m_hOut, m_weight, kRoundingFloor, m_hDev, m_hMu);
    ukfkernels::weightedGram(m_hDev, m_weight, m_Pyy);
    ukfkernels::addScaledOuter(m_Pyy, cross, m_hMu);
    m_Pyy += m_R;
    ukfkernels::symmetrize(m_Pyy);
    ukfkernels::weightedOuter(m_dx, m_hDev, m_weight, m_Pxy);
    m_yHat = m_hOut.col(0) + m_hMu;
    if (!m_Pyy.allFinite() || !m_Pxy.allFinite() || !m_yHat.allFinite()) {
        return {false, UkfFault::NonFiniteValue, "the predicted measurement is not finite"};
    }
    m_lowerYy = m_Pyy;
    if (!ukfkernels::choleskyInPlace(m_lowerYy)) {
        return {false, UkfFault::NotPositiveDefinite,
                "the innovation covariance is not positive definite (check R)"};
    }
    m_gain = m_Pxy;
    ukfkernels::solveRightInPlace(m_lowerYy, m_gain); // K = P_xy P_yy^-1
    m_newX = m_centre;
    m_innovation = z - m_yHat;
    m_newX.noalias() += m_gain * m_innovation;
    m_newP = m_P;
    m_newP.noalias() -= m_gain * m_Pxy.transpose(); // K P_yy K^T = K P_xy^T
    ukfkernels::symmetrize(m_newP);
    // Components known exactly (zero variance) stay exactly known.
    for (Eigen::Index j = 0; j < m_newP.rows(); ++j) {
        if (m_P(j, j) == 0.0) {
            m_newP.row(j).setZero();
            m_newP.col(j).setZero();
        }
    }
    return acceptCandidate("updated", jitter);
}

// Project, check and factor the candidate (m_newX, m_newP) of a phase; adopt it only if all
// of that succeeds (otherwise the last good estimate stays).
UkfStatus UnscentedKalmanFilter::acceptCandidate(const char* phase, double jitter) {
    if (m_bounded) {
        clampInto(m_newX.data(), m_meanLower, m_meanUpper);
    }
    if (!m_newX.allFinite()) {
        return {false, UkfFault::NonFiniteValue,
                std::string("the ") + phase + " mean is not finite"};
    }
    const std::string what = std::string("the ") + phase + " covariance";
    UkfStatus status = factor(m_newP, what.c_str());
    if (!status.ok) {
        return status;
    }
    addJitter(m_newP, status.jitter);
    m_x = m_newX;
    m_P.swap(m_newP);
    m_sqrtIsOfP = true;
    status.jitter = std::max(status.jitter, jitter);
    return status;
}

} // namespace hsmu
