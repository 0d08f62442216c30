#include "core/rths/ServoHydraulicPlant.h"

#include <Eigen/Dense>

#include <cmath>
#include <sstream>

namespace hsmu::rths {

double PlantParameters::specimenDamping(double zeta, double ke, double me)
{
    return 2.0 * zeta * std::sqrt(ke * me);
}

std::array<double, 6> PlantParameters::denominator() const
{
    const double k3 = ke + ce * a3 + a2; // (ke + ce a3 + a2)
    const double c3 = ce + me * a3;      // (ce + me a3)
    return {ke * a3 * b2 + a1b0,
            ke * a3 * b1 + k3 * b2,
            ke * a3 + k3 * b1 + c3 * b2,
            k3 + c3 * b1 + me * b2,
            c3 + me * b1,
            me};
}

std::complex<double> PlantParameters::frequencyResponse(double omega) const
{
    const auto a = denominator();
    const std::complex<double> s(0.0, omega);
    std::complex<double> d = 0.0;
    for (int i = 5; i >= 0; --i)
        d = d * s + a[std::size_t(i)];
    return g * a1b0 / d;
}

std::string PlantParameters::validate() const
{
    const std::pair<const char*, double> positive[] = {{"a1b0", a1b0}, {"b1", b1}, {"b2", b2},
                                                       {"me", me},     {"ke", ke}, {"g", g}};
    for (const auto& [name, v] : positive)
        if (!(std::isfinite(v) && v > 0.0)) {
            std::ostringstream o;
            o << "plant parameter " << name << " must be a positive number (got " << v << ")";
            return o.str();
        }
    const std::pair<const char*, double> nonNegative[] = {{"a2", a2}, {"a3", a3}, {"ce", ce}};
    for (const auto& [name, v] : nonNegative)
        if (!(std::isfinite(v) && v >= 0.0)) {
            std::ostringstream o;
            o << "plant parameter " << name << " must be zero or positive (got " << v << ")";
            return o.str();
        }
    return {};
}

ServoHydraulicPlant::ServoHydraulicPlant(const PlantParameters& p) : m_p(p) { reset(0.0); }

void ServoHydraulicPlant::reset(double x0)
{
    const double f = m_p.ke * x0;
    m_s = {m_p.a3 * f, 0.0, f, x0, 0.0};
}

ServoHydraulicPlant::State ServoHydraulicPlant::derivative(const State& s, double u, double fd) const
{
    const double q = s[0], qd = s[1], f = s[2], x = s[3], v = s[4];
    return {qd,
            m_p.a1b0 * (m_p.g * u - x) - m_p.b1 * qd - m_p.b2 * q,
            -m_p.a3 * f + q - m_p.a2 * v,
            v,
            (f - m_p.ce * v - m_p.ke * x - fd) / m_p.me};
}

void ServoHydraulicPlant::advance(double u, double h, double fd)
{
    auto add = [](const State& a, const State& b, double c) {
        State r;
        for (std::size_t i = 0; i < r.size(); ++i)
            r[i] = a[i] + c * b[i];
        return r;
    };
    const State k1 = derivative(m_s, u, fd);
    const State k2 = derivative(add(m_s, k1, 0.5 * h), u, fd);
    const State k3 = derivative(add(m_s, k2, 0.5 * h), u, fd);
    const State k4 = derivative(add(m_s, k3, h), u, fd);
    for (std::size_t i = 0; i < m_s.size(); ++i)
        m_s[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
}

std::complex<double> ServoHydraulicPlant::stateSpaceResponse(double omega) const
{
    // A and B from derivative(): columns by unit states, B by a unit command.
    Eigen::Matrix<double, 5, 5> a;
    const State zero{};
    for (int j = 0; j < 5; ++j) {
        State e{};
        e[std::size_t(j)] = 1.0;
        const State d = derivative(e, 0.0);
        for (int i = 0; i < 5; ++i)
            a(i, j) = d[std::size_t(i)];
    }
    const State bu = derivative(zero, 1.0);
    Eigen::Matrix<std::complex<double>, 5, 1> b;
    for (int i = 0; i < 5; ++i)
        b(i) = bu[std::size_t(i)];
    Eigen::Matrix<std::complex<double>, 5, 5> m =
        std::complex<double>(0.0, omega) * Eigen::Matrix<std::complex<double>, 5, 5>::Identity() -
        a.cast<std::complex<double>>();
    const Eigen::Matrix<std::complex<double>, 5, 1> x = m.partialPivLu().solve(b);
    return x(3); // C picks x
}

} // namespace hsmu::rths
