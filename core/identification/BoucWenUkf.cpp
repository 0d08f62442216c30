#include "core/identification/BoucWenUkf.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace hsmu {

namespace {

constexpr int kZ = static_cast<int>(BoucWenUkfIndex::Z);
constexpr int kE = static_cast<int>(BoucWenUkfIndex::E);
constexpr int kK0 = static_cast<int>(BoucWenUkfIndex::K0);
constexpr int kAlpha = static_cast<int>(BoucWenUkfIndex::Alpha);
constexpr int kBeta = static_cast<int>(BoucWenUkfIndex::Beta);
constexpr int kGamma = static_cast<int>(BoucWenUkfIndex::Gamma);
constexpr int kN = static_cast<int>(BoucWenUkfIndex::N);
constexpr int kDeltaNu = static_cast<int>(BoucWenUkfIndex::DeltaNu);
constexpr int kDeltaEta = static_cast<int>(BoucWenUkfIndex::DeltaEta);
constexpr int kFirstParameter = kK0;
constexpr double kBetaGammaMargin = BoucWen::kBetaGammaMargin;

bool projectAdmissible(double& beta, double& gamma) {
    return BoucWen::projectBetaGamma(beta, gamma);
}

bool isParameter(BoucWenUkfIndex index) {
    const int i = static_cast<int>(index);
    return i >= kFirstParameter && i < kBoucWenUkfSize;
}

double width(const BoucWenUkf::Bounds& b) {
    return std::isfinite(b.upper - b.lower) ? b.upper - b.lower : 0.0;
}

} // namespace

const char* boucWenUkfIndexName(BoucWenUkfIndex index) {
    switch (index) {
    case BoucWenUkfIndex::Z:
        return "z";
    case BoucWenUkfIndex::E:
        return "e";
    case BoucWenUkfIndex::K0:
        return "k0";
    case BoucWenUkfIndex::Alpha:
        return "alpha";
    case BoucWenUkfIndex::Beta:
        return "beta";
    case BoucWenUkfIndex::Gamma:
        return "gamma";
    case BoucWenUkfIndex::N:
        return "n";
    case BoucWenUkfIndex::DeltaNu:
        return "deltaNu";
    case BoucWenUkfIndex::DeltaEta:
        return "deltaEta";
    }
    return "unknown";
}

BoucWenUkf::BoundsArray BoucWenUkf::tableIIIBounds() {
    BoundsArray b;
    b[kK0] = {0.7, 1.4};
    b[kAlpha] = {0.001, 0.05};
    b[kBeta] = {2.5, 5.0};
    b[kGamma] = {0.0, 2.5};
    b[kN] = {1.0, 3.0};
    b[kDeltaNu] = {0.001, 0.1};
    b[kDeltaEta] = {0.001, 0.1};
    return b;
}

bool BoucWenUkf::boundsAdmissible(const BoundsArray& b) {
    for (int i = kFirstParameter; i < kBoucWenUkfSize; ++i) {
        if (!std::isfinite(b[i].lower) || !std::isfinite(b[i].upper) || b[i].lower > b[i].upper) {
            return false;
        }
    }
    return b[kK0].lower > 0.0 && b[kAlpha].lower >= 0.0 && b[kAlpha].upper <= 1.0 &&
           b[kN].lower > 0.0 && b[kDeltaNu].lower >= 0.0 && b[kDeltaEta].lower >= 0.0 &&
           b[kBeta].upper + b[kGamma].upper > kBetaGammaMargin;
}

BoucWenUkf::BoucWenUkf(const BoucWenParameters& initial, const BoucWenUkfSettings& settings,
                       const BoundsArray& bounds)
    : m_fixed(initial), m_settings(settings),
      m_bounds(boundsAdmissible(bounds) ? bounds : tableIIIBounds()), m_ukf(settings.ukf) {
    reset(initial);
}

double BoucWenUkf::initialVariance(int i) const {
    if (i < kFirstParameter || m_locked[static_cast<std::size_t>(i)]) {
        return 0.0;
    }
    const double s = m_settings.initialStdFraction * width(m_bounds[static_cast<std::size_t>(i)]);
    return s * s;
}

void BoucWenUkf::reset(const BoucWenParameters& initial) {
    m_fixed = initial;
    Eigen::VectorXd x(kBoucWenUkfSize);
    x << 0.0, 0.0, initial.k0, initial.alpha, initial.beta, initial.gamma, initial.n,
        initial.deltaNu, initial.deltaEta;
    for (int i = kFirstParameter; i < kBoucWenUkfSize; ++i) {
        if (m_locked[static_cast<std::size_t>(i)]) {
            m_lockedValue[static_cast<std::size_t>(i)] = x(i);
        }
    }
    refreshBoxes();
    project(x, true);
    Eigen::MatrixXd P = Eigen::MatrixXd::Zero(kBoucWenUkfSize, kBoucWenUkfSize);
    for (int i = 0; i < kBoucWenUkfSize; ++i) {
        P(i, i) = initialVariance(i);
    }
    m_ukf.init(x, P); // x is finite and P diagonal >= 0: cannot fail (and zeroes Q)
    m_refreshNeeded = true;
    m_lastX = 0.0;
    m_x = 0.0;
}

void BoucWenUkf::restart(const BoucWenParameters& estimate, const BoucWenState& state,
                         double deformation, const std::array<double, kBoucWenUkfSize>& stddev) {
    m_fixed = estimate;
    Eigen::VectorXd x(kBoucWenUkfSize);
    x << state.z, state.e, estimate.k0, estimate.alpha, estimate.beta, estimate.gamma, estimate.n,
        estimate.deltaNu, estimate.deltaEta;
    for (int i = kFirstParameter; i < kBoucWenUkfSize; ++i)
        if (m_locked[static_cast<std::size_t>(i)])
            m_lockedValue[static_cast<std::size_t>(i)] = x(i);
    refreshBoxes();
    project(x, true);
    projectAdmissible(x(kBeta), x(kGamma));
    Eigen::MatrixXd P = Eigen::MatrixXd::Zero(kBoucWenUkfSize, kBoucWenUkfSize);
    for (int i = 0; i < kBoucWenUkfSize; ++i) {
        const double sd = std::isfinite(stddev[static_cast<std::size_t>(i)])
                              ? stddev[static_cast<std::size_t>(i)]
                              : 0.0;
        P(i, i) = m_locked[static_cast<std::size_t>(i)] ? 0.0 : sd * sd;
    }
    m_ukf.init(x, P);
    m_refreshNeeded = true;
    m_lastX = deformation / m_fixed.uRef;
    m_x = m_lastX;
}

void BoucWenUkf::project(Eigen::Ref<Eigen::VectorXd> x, bool mean) const {
    const auto& lower = mean ? m_meanLower : m_sigmaLower;
    const auto& upper = mean ? m_meanUpper : m_sigmaUpper;
    for (int i = kFirstParameter; i < kBoucWenUkfSize; ++i) {
        const auto u = static_cast<std::size_t>(i);
        x(i) = std::clamp(x(i), lower[u], upper[u]);
    }
}

void BoucWenUkf::refreshBoxes() {
    for (int i = kFirstParameter; i < kBoucWenUkfSize; ++i) {
        const auto u = static_cast<std::size_t>(i);
        if (m_locked[u]) {
            m_sigmaLower[u] = m_sigmaUpper[u] = m_meanLower[u] = m_meanUpper[u] = m_lockedValue[u];
            continue;
        }
        const Bounds& b = m_bounds[u];
        const double margin = std::clamp(m_settings.boundMargin, 0.0, 0.5) * width(b);
        m_sigmaLower[u] = b.lower;
        m_sigmaUpper[u] = b.upper;
        m_meanLower[u] = b.lower + margin;
        m_meanUpper[u] = std::max(b.upper - margin, m_meanLower[u]);
    }
    // The filter holds its sigma points and means in these boxes; z and e are unbounded.
    const auto vector = [](const std::array<double, kBoucWenUkfSize>& values, double unbounded) {
        Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(values.data(), kBoucWenUkfSize);
        v(kZ) = v(kE) = unbounded;
        return v;
    };
    constexpr double inf = std::numeric_limits<double>::infinity();
    m_ukf.setBounds(vector(m_sigmaLower, -inf), vector(m_sigmaUpper, inf),
                    vector(m_meanLower, -inf), vector(m_meanUpper, inf));
}

bool BoucWenUkf::setBounds(BoucWenUkfIndex index, double lower, double upper) {
    if (!isParameter(index)) {
        return false;
    }
    BoundsArray candidate = m_bounds;
    candidate[static_cast<std::size_t>(index)] = {lower, upper};
    if (!boundsAdmissible(candidate)) {
        return false;
    }
    m_bounds = candidate;
    m_refreshNeeded = true;
    const auto u = static_cast<std::size_t>(index);
    if (m_locked[u]) {
        m_lockedValue[u] = std::clamp(m_lockedValue[u], lower, upper);
    }
    return true;
}

bool BoucWenUkf::setLocked(BoucWenUkfIndex index, bool lock) {
    if (!isParameter(index)) {
        return false;
    }
    const int i = static_cast<int>(index);
    const auto u = static_cast<std::size_t>(i);
    if (m_locked[u] == lock) {
        return true;
    }
    Eigen::VectorXd x = m_ukf.state();
    Eigen::MatrixXd P = m_ukf.covariance();
    m_locked[u] = lock;
    m_refreshNeeded = true;
    P.row(i).setZero();
    P.col(i).setZero();
    if (lock) {
        m_lockedValue[u] = x(i);
    } else {
        P(i, i) = initialVariance(i);
    }
    m_ukf.setState(x, P); // a principal submatrix of an accepted P plus a variance: PSD
    return true;
}

bool BoucWenUkf::locked(BoucWenUkfIndex index) const {
    return isParameter(index) && m_locked[static_cast<std::size_t>(index)];
}

BoucWenParameters BoucWenUkf::parametersOf(const Eigen::Ref<const Eigen::VectorXd>& x) const {
    BoucWenParameters p = m_fixed;
    p.k0 = x(kK0);
    p.alpha = x(kAlpha);
    p.beta = x(kBeta);
    p.gamma = x(kGamma);
    p.n = x(kN);
    p.deltaNu = x(kDeltaNu);
    p.deltaEta = x(kDeltaEta);
    return p;
}

BoucWenParameters BoucWenUkf::estimate() const {
    return parametersOf(m_ukf.state());
}

BoucWenState BoucWenUkf::state() const {
    return {m_ukf.state()(kZ), m_ukf.state()(kE)};
}

void BoucWenUkf::refresh() {
    refreshBoxes();
    m_Q.setZero(kBoucWenUkfSize, kBoucWenUkfSize);
    m_Q(kZ, kZ) = m_settings.zNoise * m_settings.zNoise;
    m_Q(kE, kE) = m_settings.eNoise * m_settings.eNoise;
    for (int i = kFirstParameter; i < kBoucWenUkfSize; ++i) {
        const auto u = static_cast<std::size_t>(i);
        const double s = m_locked[u] ? 0.0 : m_settings.parameterNoise * width(m_bounds[u]);
        m_Q(i, i) = s * s;
    }
    m_R.setConstant(1, 1, m_settings.forceNoise * m_settings.forceNoise);
    m_ukf.setSettings(m_settings.ukf);
    m_ukf.setProcessNoise(m_Q);
    m_ukf.setMeasurementNoise(m_R);
}

BoucWenUkfStep BoucWenUkf::result(UkfStatus status, double predicted) const {
    BoucWenUkfStep out;
    out.status = std::move(status);
    const Eigen::VectorXd& x = m_ukf.state();
    out.estimate = parametersOf(x);
    out.state = {x(kZ), x(kE)};
    const Eigen::MatrixXd& P = m_ukf.covariance(); // as standardDeviations(), without a vector
    for (int i = 0; i < kBoucWenUkfSize; ++i) {
        out.standardDeviation[static_cast<std::size_t>(i)] = std::sqrt(std::max(P(i, i), 0.0));
    }
    const auto force = [&](const Eigen::VectorXd& s) {
        return m_fixed.fRef * (s(kAlpha) * s(kK0) * m_x + (1.0 - s(kAlpha)) * s(kK0) * s(kZ));
    };
    out.predictedForce = std::isfinite(predicted) ? m_fixed.fRef * predicted : force(x);
    out.filteredForce = force(x);
    return out;
}

BoucWenUkfStep BoucWenUkf::step(double deformation, double force) {
    if (!std::isfinite(deformation) || !std::isfinite(force)) {
        m_x = m_lastX;
        return result({false, UkfFault::NonFiniteValue,
                       "the measured deformation or force is "
                       "not finite: step skipped"},
                      std::numeric_limits<double>::quiet_NaN());
    }
    const double previousX = m_lastX;
    m_x = deformation / m_fixed.uRef;
    const double dx = m_x - m_lastX;
    m_lastX = m_x;
    if (m_refreshNeeded) {
        refresh();
        m_refreshNeeded = false;
    }

    // All sigma points' integrations in one call: BoucWen::integrateStates interleaves them.
    LawStatus lawStatus = LawStatus::Ok;
    UkfStatus predicted = m_ukf.predict(
        AllSigmaPoints{[&](const Eigen::MatrixXd& points, Eigen::MatrixXd& values) -> Eigen::Index {
            const auto count = static_cast<std::size_t>(points.cols());
            m_sigmaParameters.resize(count);
            m_sigmaStates.resize(count);
            m_sigmaIncrements.resize(count);
            values = points;
            for (std::size_t i = 0; i < count; ++i) {
                const auto column = points.col(static_cast<Eigen::Index>(i));
                m_sigmaParameters[i] = parametersOf(column);
                m_sigmaStates[i] = {column(kZ), column(kE)};
                BoucWenParameters& q = m_sigmaParameters[i];
                if (projectAdmissible(q.beta, q.gamma)) { // the point itself moves too
                    values(kBeta, static_cast<Eigen::Index>(i)) = q.beta;
                    values(kGamma, static_cast<Eigen::Index>(i)) = q.gamma;
                }
            }
            BoucWen::integrateStates(m_sigmaParameters, m_sigmaStates, dx, m_sigmaIncrements,
                                     BoucWen::BatchMath::Fast);
            for (std::size_t i = 0; i < count; ++i) {
                const BoucWenIncrement& inc = m_sigmaIncrements[i];
                if (inc.status != LawStatus::Ok) {
                    lawStatus = inc.status;
                    return static_cast<Eigen::Index>(i);
                }
                values(kZ, static_cast<Eigen::Index>(i)) = inc.state.z;
                values(kE, static_cast<Eigen::Index>(i)) = inc.state.e;
            }
            return -1;
        }});
    if (!predicted.ok) {
        if (predicted.fault == UkfFault::FunctionFailed) {
            predicted.reason = std::string("Bouc-Wen integration failed (") +
                               lawStatusName(lawStatus) + "): " + predicted.reason;
        }
        predicted.reason = "prediction rejected: " + predicted.reason;
        // Keep z, e in step with the deformation using the estimate's own parameters.
        Eigen::VectorXd x = m_ukf.state();
        const BoucWenIncrement inc =
            BoucWen::integrateState(parametersOf(x), BoucWenState{x(kZ), x(kE)}, dx);
        if (inc.status == LawStatus::Ok) {
            x(kZ) = inc.state.z;
            x(kE) = inc.state.e;
            m_ukf.setState(x, m_ukf.covariance());
        } else {
            // The state still belongs to the previous deformation: skip this one entirely.
            predicted.reason += "; z and e could not be advanced either: step skipped";
            m_lastX = previousX;
            m_x = previousX;
        }
        return result(predicted, std::numeric_limits<double>::quiet_NaN());
    }

    const double x = m_x;
    m_measured.resize(1);
    m_measured(0) = force / m_fixed.fRef;
    // Eq. 7 for all sigma points in one call (no per-point call through Eigen::Ref).
    UkfStatus updated = m_ukf.update(
        AllSigmaPoints{[x](const Eigen::MatrixXd& points, Eigen::MatrixXd& out) -> Eigen::Index {
            for (Eigen::Index i = 0; i < points.cols(); ++i) {
                const double* s = points.data() + i * kBoucWenUkfSize;
                out(0, i) = s[kAlpha] * s[kK0] * x + (1.0 - s[kAlpha]) * s[kK0] * s[kZ];
            }
            return -1;
        }},
        m_measured);
    if (!updated.ok) {
        updated.reason = "update rejected: " + updated.reason;
        return result(updated, std::numeric_limits<double>::quiet_NaN());
    }
    updated.jitter = std::max(updated.jitter, predicted.jitter);
    if (Eigen::VectorXd post = m_ukf.state(); projectAdmissible(post(kBeta), post(kGamma)))
        m_ukf.setState(post, m_ukf.covariance()); // the posterior mean made admissible
    return result(updated, m_ukf.predictedMeasurement()(0));
}

} // namespace hsmu
