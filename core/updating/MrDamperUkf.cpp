#include "core/updating/MrDamperUkf.h"

#include "core/hysteresis/BoucWen.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hsmu {

namespace {
constexpr int kFirst = 2;          // first parameter in the state
constexpr int kBeta = kFirst + 6;  // state index of beta
constexpr int kGamma = kFirst + 7; // state index of gamma
} // namespace

const std::array<const char*, kMrDamperUkfParameters>& mrDamperUkfParameterNames() {
    static const std::array<const char*, kMrDamperUkfParameters> names = {
        "c0", "c1", "k0", "k1", "f0", "alpha", "beta", "gamma", "n"};
    return names;
}

int mrDamperUkfParameterIndex(const std::string& name) {
    const auto& names = mrDamperUkfParameterNames();
    for (int j = 0; j < kMrDamperUkfParameters; ++j)
        if (name == names[std::size_t(j)])
            return j;
    return -1;
}

double& MrDamperUkf::field(MrDamperParameters& p, int j) {
    switch (j) {
    case 0: return p.c0;
    case 1: return p.c1;
    case 2: return p.k0;
    case 3: return p.k1;
    case 4: return p.f0;
    case 5: return p.alpha;
    case 6: return p.beta;
    case 7: return p.gamma;
    default: return p.n;
    }
}

double MrDamperUkf::field(const MrDamperParameters& p, int j) {
    return field(const_cast<MrDamperParameters&>(p), j);
}

MrDamperUkf::MrDamperUkf(const MrDamperParameters& initial, const Box& box, double dt,
                         const MrDamperUkfSettings& settings)
    : m_fixed(initial), m_box(box), m_dt(dt), m_settings(settings), m_law() {
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw std::invalid_argument("MR damper UKF: the samples' step dt must be > 0");
    MrDamperParameters lo = initial;
    for (int j = 0; j < kMrDamperUkfParameters; ++j) {
        const ParameterBounds& b = box[std::size_t(j)];
        if (!std::isfinite(b.lower) || !std::isfinite(b.upper) || !(b.lower <= b.upper))
            throw std::invalid_argument(std::string("MR damper UKF: the bounds of '") +
                                        mrDamperUkfParameterNames()[std::size_t(j)] +
                                        "' need finite lower <= upper");
        field(lo, j) = b.lower;
    }
    // The box's lower corner, beta + gamma apart (projected), must be an admissible law.
    BoucWen::projectBetaGamma(lo.beta, lo.gamma);
    if (!MrDamper::admissible(lo) ||
        !(box[6].upper + box[7].upper > BoucWen::kBetaGammaMargin))
        throw std::invalid_argument("MR damper UKF: the bounds leave laws that are not "
                                    "admissible (need c1 > 0, c0, k0, k1, alpha >= 0, n > 0)");
    m_law = MrDamper(lo);
    m_law.setTimeIncrement(dt);
    Values sd{};
    for (int j = 0; j < kMrDamperUkfParameters; ++j)
        sd[std::size_t(j)] = 0.1 * (box[std::size_t(j)].upper - box[std::size_t(j)].lower);
    MrDamperParameters start = initial;
    for (int j = 0; j < kMrDamperUkfParameters; ++j)
        field(start, j) = box[std::size_t(j)].clamp(field(initial, j));
    restart(start, {}, 0.0, sd);
}

MrDamperParameters MrDamperUkf::fromState(const Eigen::Ref<const Eigen::VectorXd>& x) const {
    MrDamperParameters p = m_fixed;
    for (int j = 0; j < kMrDamperUkfParameters; ++j)
        field(p, j) = x[kFirst + j];
    return p;
}

void MrDamperUkf::applyNoiseAndBounds() {
    Eigen::VectorXd lo(kMrDamperUkfSize), hi(kMrDamperUkfSize), mlo(kMrDamperUkfSize),
        mhi(kMrDamperUkfSize);
    const double inf = std::numeric_limits<double>::infinity();
    Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(kMrDamperUkfSize, kMrDamperUkfSize);
    for (int i = 0; i < kFirst; ++i) {
        lo[i] = mlo[i] = -inf;
        hi[i] = mhi[i] = inf;
        Q(i, i) = m_settings.stateNoise * m_settings.stateNoise;
    }
    for (int j = 0; j < kMrDamperUkfParameters; ++j) {
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

void MrDamperUkf::restart(const MrDamperParameters& estimate, const MrDamperState& state,
                          double u, const Values& sd) {
    m_fixed = estimate;
    Eigen::VectorXd x(kMrDamperUkfSize);
    x[0] = state.w;
    x[1] = state.z;
    Eigen::MatrixXd P = Eigen::MatrixXd::Zero(kMrDamperUkfSize, kMrDamperUkfSize);
    P(0, 0) = P(1, 1) = 1e-6;
    for (int j = 0; j < kMrDamperUkfParameters; ++j) {
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
    m_u = u;
}

bool MrDamperUkf::advance(Eigen::Ref<Eigen::VectorXd> x, double u) {
    BoucWen::projectBetaGamma(x[kBeta], x[kGamma]);
    if (!m_law.setParameters(fromState(x)))
        return false;
    m_law.setCommittedState({x[0], x[1]}, m_u, 0.0);
    if (m_law.setTrialDeformation(u) != LawStatus::Ok)
        return false;
    const MrDamperState s = m_law.trialState();
    x[0] = s.w;
    x[1] = s.z;
    return true;
}

MrDamperUkfStep MrDamperUkf::step(double deformation, double force) {
    MrDamperUkfStep out;
    const double uRef = m_fixed.uRef, fRef = m_fixed.fRef;
    const double x = deformation / uRef;
    const double xd = (deformation - m_u) / (uRef * m_dt);
    const auto process = [&](const Eigen::Ref<const Eigen::VectorXd>& in,
                             Eigen::Ref<Eigen::VectorXd> next) -> bool {
        next = in;
        return advance(next, deformation);
    };
    const auto measure = [&](const Eigen::Ref<const Eigen::VectorXd>& in,
                             Eigen::Ref<Eigen::VectorXd> y) {
        const double c0 = in[kFirst], c1 = in[kFirst + 1], k0 = in[kFirst + 2],
                     k1 = in[kFirst + 3], f0 = in[kFirst + 4], alpha = in[kFirst + 5];
        const double c = c0 + c1;
        y[0] = c0 * c1 / c * xd + c1 / c * (alpha * in[1] + k0 * in[0]) + k1 * x + f0;
    };
    out.status = m_ukf.predict(process);
    Eigen::VectorXd y(1);
    if (!out.status.ok) {
        // keep w and z in step with the deformation: the estimate's own parameters
        Eigen::VectorXd s = m_ukf.state();
        if (advance(s, deformation))
            m_ukf.setState(s, m_ukf.covariance());
        m_u = deformation;
        measure(m_ukf.state(), y);
        out.predictedForce = y[0] * fRef;
        return out;
    }
    m_u = deformation;
    measure(m_ukf.state(), y);
    out.predictedForce = y[0] * fRef;
    Eigen::VectorXd z(1);
    z[0] = force / fRef;
    out.status = m_ukf.update(measure, z);
    if (out.status.ok) {
        Eigen::VectorXd s = m_ukf.state();
        if (BoucWen::projectBetaGamma(s[kBeta], s[kGamma]))
            m_ukf.setState(s, m_ukf.covariance());
    }
    return out;
}

MrDamperParameters MrDamperUkf::estimate() const {
    Eigen::VectorXd s = m_ukf.state();
    BoucWen::projectBetaGamma(s[kBeta], s[kGamma]);
    return fromState(s);
}

MrDamperUkf::Values MrDamperUkf::standardDeviation() const {
    const Eigen::VectorXd sd = m_ukf.standardDeviations();
    Values out{};
    for (int j = 0; j < kMrDamperUkfParameters; ++j)
        out[std::size_t(j)] = sd[kFirst + j];
    return out;
}

MrDamperState MrDamperUkf::state() const {
    return {m_ukf.state()[0], m_ukf.state()[1]};
}

} // namespace hsmu
