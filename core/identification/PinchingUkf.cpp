#include "core/identification/PinchingUkf.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsmu {

namespace {
constexpr int kFirst = 2;                // first parameter in the state
constexpr int kBeta = kFirst + 3;        // state index of beta
constexpr int kGamma = kFirst + 4;       // state index of gamma
} // namespace

const std::array<const char*, kPinchingUkfParameters>& pinchingUkfParameterNames() {
    static const std::array<const char*, kPinchingUkfParameters> names = {
        "k0",       "alpha", "n", "beta", "gamma", "deltaNu",  "deltaEta",
        "zetaS",    "p",     "q", "psi",  "deltaPsi", "lambda"};
    return names;
}

int pinchingUkfParameterIndex(const std::string& name) {
    const auto& names = pinchingUkfParameterNames();
    for (int j = 0; j < kPinchingUkfParameters; ++j)
        if (name == names[std::size_t(j)])
            return j;
    return -1;
}

double& PinchingUkf::field(BoucWenPinchingParameters& p, int j) {
    switch (j) {
    case 0: return p.boucWen.k0;
    case 1: return p.boucWen.alpha;
    case 2: return p.boucWen.n;
    case 3: return p.boucWen.beta;
    case 4: return p.boucWen.gamma;
    case 5: return p.boucWen.deltaNu;
    case 6: return p.boucWen.deltaEta;
    case 7: return p.pinching.zetaS;
    case 8: return p.pinching.p;
    case 9: return p.pinching.q;
    case 10: return p.pinching.psi;
    case 11: return p.pinching.deltaPsi;
    default: return p.pinching.lambda;
    }
}

double PinchingUkf::field(const BoucWenPinchingParameters& p, int j) {
    return field(const_cast<BoucWenPinchingParameters&>(p), j);
}

PinchingUkf::PinchingUkf(const BoucWenPinchingParameters& initial, const Box& box,
                         const PinchingUkfSettings& settings)
    : m_fixed(initial), m_box(box), m_settings(settings) {
    BoucWenPinchingParameters lo = initial, hi = initial;
    for (int j = 0; j < kPinchingUkfParameters; ++j) {
        const ParameterBounds& b = box[std::size_t(j)];
        if (!std::isfinite(b.lower) || !std::isfinite(b.upper) || !(b.lower <= b.upper))
            throw std::invalid_argument(std::string("pinching UKF: the bounds of '") +
                                        pinchingUkfParameterNames()[std::size_t(j)] +
                                        "' need finite lower <= upper");
        field(lo, j) = b.lower;
        field(hi, j) = b.upper;
    }
    // The box's corners, beta + gamma apart (projected), must be admissible laws.
    BoucWen::projectBetaGamma(lo.boucWen.beta, lo.boucWen.gamma);
    if (!BoucWenPinching::admissible(lo) || !(hi.pinching.zetaS < 1.0) || !(hi.pinching.q < 1.0) ||
        !(box[1].upper <= 1.0) || !(box[0].lower > 0.0) || !(box[2].lower > 0.0) ||
        !(box[3].upper + box[4].upper > BoucWen::kBetaGammaMargin))
        throw std::invalid_argument("pinching UKF: the bounds leave laws that are not "
                                    "admissible (need k0 > 0, 0 <= alpha <= 1, n > 0, rates "
                                    ">= 0, 0 <= zetaS < 1, 0 <= q < 1, psi > 0, lambda > 0)");
    Eigen::VectorXd x = Eigen::VectorXd::Zero(kPinchingUkfSize);
    for (int j = 0; j < kPinchingUkfParameters; ++j)
        x[kFirst + j] = box[std::size_t(j)].clamp(field(initial, j));
    std::array<double, kPinchingUkfParameters> sd{};
    for (int j = 0; j < kPinchingUkfParameters; ++j)
        sd[std::size_t(j)] = 0.1 * (box[std::size_t(j)].upper - box[std::size_t(j)].lower);
    restart(fromState(x), {}, 0.0, sd);
}

BoucWenPinchingParameters PinchingUkf::fromState(const Eigen::Ref<const Eigen::VectorXd>& x) const {
    BoucWenPinchingParameters p = m_fixed;
    for (int j = 0; j < kPinchingUkfParameters; ++j)
        field(p, j) = x[kFirst + j];
    return p;
}

void PinchingUkf::applyNoiseAndBounds() {
    Eigen::VectorXd lo(kPinchingUkfSize), hi(kPinchingUkfSize), mlo(kPinchingUkfSize),
        mhi(kPinchingUkfSize);
    const double inf = std::numeric_limits<double>::infinity();
    lo[0] = mlo[0] = -inf;
    hi[0] = mhi[0] = inf;
    lo[1] = mlo[1] = 0.0; // the dissipated energy
    hi[1] = mhi[1] = inf;
    Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(kPinchingUkfSize, kPinchingUkfSize);
    Q(0, 0) = m_settings.zNoise * m_settings.zNoise;
    Q(1, 1) = m_settings.eNoise * m_settings.eNoise;
    for (int j = 0; j < kPinchingUkfParameters; ++j) {
        const ParameterBounds& b = m_box[std::size_t(j)];
        const double w = b.upper - b.lower, m = m_settings.boundMargin * w;
        lo[kFirst + j] = b.lower;
        hi[kFirst + j] = b.upper;
        mlo[kFirst + j] = b.lower + m;
        mhi[kFirst + j] = b.upper - m;
        const double q = m_settings.parameterNoise * w;
        Q(kFirst + j, kFirst + j) = q * q;
    }
    m_ukf.setBounds(lo, hi, mlo, mhi);
    m_ukf.setProcessNoise(Q);
    m_ukf.setMeasurementNoise(
        Eigen::MatrixXd::Constant(1, 1, m_settings.forceNoise * m_settings.forceNoise));
}

void PinchingUkf::restart(const BoucWenPinchingParameters& estimate, const BoucWenState& state,
                          double u, const std::array<double, kPinchingUkfParameters>& sd) {
    m_fixed = estimate;
    Eigen::VectorXd x(kPinchingUkfSize);
    x[0] = state.z;
    x[1] = std::max(state.e, 0.0);
    Eigen::MatrixXd P = Eigen::MatrixXd::Zero(kPinchingUkfSize, kPinchingUkfSize);
    P(0, 0) = P(1, 1) = 1e-6;
    for (int j = 0; j < kPinchingUkfParameters; ++j) {
        const ParameterBounds& b = m_box[std::size_t(j)];
        const double m = m_settings.boundMargin * (b.upper - b.lower);
        x[kFirst + j] = std::clamp(field(estimate, j), b.lower + m, b.upper - m);
        const double s = std::isfinite(sd[std::size_t(j)]) ? sd[std::size_t(j)] : 0.0;
        P(kFirst + j, kFirst + j) = s * s;
    }
    BoucWen::projectBetaGamma(x[kBeta], x[kGamma]);
    m_ukf.setSettings(m_settings.ukf);
    m_ukf.init(x, P);
    applyNoiseAndBounds();
    m_x = u / m_fixed.boucWen.uRef;
}

PinchingUkfStep PinchingUkf::step(double deformation, double force) {
    PinchingUkfStep out;
    const double x = deformation / m_fixed.boucWen.uRef;
    const double dx = x - m_x;
    m_x = x;
    const auto process = [&](const Eigen::Ref<const Eigen::VectorXd>& in,
                             Eigen::Ref<Eigen::VectorXd> next) -> bool {
        next = in;
        BoucWen::projectBetaGamma(next[kBeta], next[kGamma]);
        const BoucWenPinchingParameters p = fromState(next);
        const BoucWenIncrement inc = BoucWenPinching::integrate(p, {next[0], next[1]}, dx);
        if (inc.status != LawStatus::Ok)
            return false;
        next[0] = inc.state.z;
        next[1] = inc.state.e;
        return true;
    };
    const auto measure = [&](const Eigen::Ref<const Eigen::VectorXd>& in,
                             Eigen::Ref<Eigen::VectorXd> y) {
        const double k0 = in[kFirst], alpha = in[kFirst + 1];
        y[0] = alpha * k0 * x + (1.0 - alpha) * k0 * in[0];
    };
    out.status = m_ukf.predict(process);
    if (!out.status.ok) {
        // keep z and e in step with the deformation: the estimate's own parameters
        Eigen::VectorXd s = m_ukf.state();
        BoucWen::projectBetaGamma(s[kBeta], s[kGamma]);
        const BoucWenIncrement inc = BoucWenPinching::integrate(fromState(s), {s[0], s[1]}, dx);
        if (inc.status == LawStatus::Ok) {
            s[0] = inc.state.z;
            s[1] = inc.state.e;
            m_ukf.setState(s, m_ukf.covariance());
        }
        Eigen::VectorXd y(1);
        measure(m_ukf.state(), y);
        out.predictedForce = y[0] * m_fixed.boucWen.fRef;
        return out;
    }
    {
        Eigen::VectorXd y(1);
        measure(m_ukf.state(), y);
        out.predictedForce = y[0] * m_fixed.boucWen.fRef;
    }
    Eigen::VectorXd z(1);
    z[0] = force / m_fixed.boucWen.fRef;
    out.status = m_ukf.update(measure, z);
    if (out.status.ok) {
        Eigen::VectorXd s = m_ukf.state();
        if (BoucWen::projectBetaGamma(s[kBeta], s[kGamma]))
            m_ukf.setState(s, m_ukf.covariance());
    }
    return out;
}

BoucWenPinchingParameters PinchingUkf::estimate() const {
    Eigen::VectorXd s = m_ukf.state();
    BoucWen::projectBetaGamma(s[kBeta], s[kGamma]);
    return fromState(s);
}

std::array<double, kPinchingUkfParameters> PinchingUkf::standardDeviation() const {
    const Eigen::VectorXd sd = m_ukf.standardDeviations();
    std::array<double, kPinchingUkfParameters> out{};
    for (int j = 0; j < kPinchingUkfParameters; ++j)
        out[std::size_t(j)] = sd[kFirst + j];
    return out;
}

BoucWenState PinchingUkf::state() const {
    return {m_ukf.state()[0], m_ukf.state()[1]};
}

} // namespace hsmu
