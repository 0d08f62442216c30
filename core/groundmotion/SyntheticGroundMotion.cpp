#include "core/groundmotion/SyntheticGroundMotion.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace hsmu {

namespace {

// exp and log by fixed-length series: the platform libm may differ in the last bit, and one
// differing bit would change every later sample. Only IEEE-exact operations are used here
// (+ - * /, frexp, ldexp, floor), so the result is the same everywhere.
constexpr double kLn2 = 0.6931471805599453;

double portableExp(double x) {
    if (x < -700.0)
        return 0.0;
    const double k = std::floor(x / kLn2 + 0.5);
    const double r = x - k * kLn2; // |r| <= ~0.35
    double sum = 1.0;
    for (int n = 22; n >= 1; --n)
        sum = 1.0 + sum * r / static_cast<double>(n);
    return std::ldexp(sum, static_cast<int>(k));
}

double portableLog(double x) {
    int exponent = 0;
    double m = std::frexp(x, &exponent); // x = m 2^exponent, m in [0.5, 1)
    if (m < 0.7071067811865476) {
        m *= 2.0;
        --exponent;
    }
    const double s = (m - 1.0) / (m + 1.0); // |s| <= 0.172
    const double s2 = s * s;
    double sum = 0.0;
    for (int k = 15; k >= 0; --k)
        sum = 1.0 / static_cast<double>(2 * k + 1) + s2 * sum;
    return static_cast<double>(exponent) * kLn2 + 2.0 * s * sum;
}

// N(0, 1) from std::mt19937_64 (its output sequence is fixed by the standard).
class PortableGaussian {
public:
    explicit PortableGaussian(std::uint64_t seed) : m_engine(seed) {}

    double next() {
        if (m_hasSpare) {
            m_hasSpare = false;
            return m_spare;
        }
        double u = 0.0;
        double v = 0.0;
        double s = 0.0;
        do {
            u = 2.0 * uniform() - 1.0;
            v = 2.0 * uniform() - 1.0;
            s = u * u + v * v;
        } while (s >= 1.0 || s == 0.0);
        const double factor = std::sqrt(-2.0 * portableLog(s) / s);
        m_spare = v * factor;
        m_hasSpare = true;
        return u * factor;
    }

private:
    double uniform() { return static_cast<double>(m_engine() >> 11) * 0x1.0p-53; }

    std::mt19937_64 m_engine;
    double m_spare = 0.0;
    bool m_hasSpare = false;
};

// x'' + 2 zeta omega x' + omega^2 x = u(t) by the trapezoidal rule on the state (x, x'):
// s[n+1] = Phi s[n] + Gamma (u[n] + u[n+1]).
class TrapezoidOscillator {
public:
    TrapezoidOscillator(double omega, double zeta, double h) : m_omega(omega), m_zeta(zeta) {
        const double a = h * zeta * omega;
        const double b = h * h * omega * omega / 4.0;
        const double det = 1.0 + a + b;
        m_phi11 = (1.0 + a - b) / det;
        m_phi12 = h / det;
        m_phi21 = -h * omega * omega / det;
        m_phi22 = (1.0 - a - b) / det;
        m_gamma1 = h * h / 4.0 / det;
        m_gamma2 = h / 2.0 / det;
    }

    void step(double u0, double u1) {
        const double sum = u0 + u1;
        const double x = m_phi11 * m_x + m_phi12 * m_v + m_gamma1 * sum;
        const double v = m_phi21 * m_x + m_phi22 * m_v + m_gamma2 * sum;
        m_x = x;
        m_v = v;
    }

    /// Restoring plus damping term 2 zeta omega x' + omega^2 x at the current state.
    double restoring() const { return 2.0 * m_zeta * m_omega * m_v + m_omega * m_omega * m_x; }

private:
    double m_omega;
    double m_zeta;
    double m_phi11, m_phi12, m_phi21, m_phi22, m_gamma1, m_gamma2;
    double m_x = 0.0;
    double m_v = 0.0;
};

double envelope(double t) {
    if (t < kSyntheticRiseTime) {
        const double r = t / kSyntheticRiseTime;
        return r * r;
    }
    if (t <= kSyntheticStrongEnd)
        return 1.0;
    return portableExp(-kSyntheticDecayRate * (t - kSyntheticStrongEnd));
}

} // namespace

GroundMotion makeSyntheticGroundMotion(unsigned seed, double duration, double dt, double pgaG) {
    if (!(std::isfinite(duration) && duration > 0.0))
        throw std::invalid_argument("makeSyntheticGroundMotion: duration must be > 0 s");
    if (!(std::isfinite(dt) && dt > 0.0))
        throw std::invalid_argument("makeSyntheticGroundMotion: dt must be > 0 s");
    if (!(std::isfinite(pgaG) && pgaG > 0.0))
        throw std::invalid_argument("makeSyntheticGroundMotion: pgaG must be > 0");
    const double count = std::floor(duration / dt + 1e-9) + 1.0;
    if (count > 1e8)
        throw std::invalid_argument("makeSyntheticGroundMotion: more than 1e8 samples");
    const auto n = static_cast<std::size_t>(count);

    PortableGaussian noise(seed);
    std::vector<double> w(n);
    for (double& value : w)
        value = noise.next();

    // Kanai-Tajimi absolute acceleration times the envelope: the Clough-Penzien input.
    TrapezoidOscillator soil(kSyntheticOmegaG, kSyntheticZetaG, dt);
    std::vector<double> u(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0)
            soil.step(w[i - 1], w[i]);
        u[i] = -soil.restoring() * envelope(static_cast<double>(i) * dt);
    }

    TrapezoidOscillator highPass(kSyntheticOmegaF, kSyntheticZetaF, dt);
    std::vector<double> a(n);
    double peak = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0)
            highPass.step(u[i - 1], u[i]);
        a[i] = u[i] - highPass.restoring();
        peak = std::max(peak, std::abs(a[i]));
    }
    if (!(peak > 0.0))
        throw std::invalid_argument("makeSyntheticGroundMotion: the record is too short");

    // a / peak * target (not a * (target / peak)) so the peak sample is exactly +-target.
    const double target = pgaG * kStandardGravity;
    for (double& value : a)
        value = value / peak * target;

    GroundMotion motion;
    motion.name = "synthetic Kanai-Tajimi (seed " + std::to_string(seed) + ")";
    motion.source = "builtin";
    motion.dt = dt;
    motion.acceleration = std::move(a);
    return motion;
}

} // namespace hsmu
