#pragma once
// PortableRandom: a seeded Gaussian generator whose output is the same on every platform
// and standard library (std::normal_distribution is not: its algorithm is unspecified).
// mt19937_64 raw output (fully specified by the standard) + the Box-Muller transform.

#include <cstdint>
#include <random>

namespace hsmu {

class PortableRandom {
public:
    explicit PortableRandom(std::uint64_t seed) : m_engine(seed) {}
    /// Uniform in (0, 1), never exactly 0 or 1.
    double uniform();
    /// Standard normal N(0, 1).
    double normal();

private:
    std::mt19937_64 m_engine;
    bool m_hasSpare = false;
    double m_spare = 0.0;
};

} // namespace hsmu
