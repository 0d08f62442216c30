#include "core/util/PortableRandom.h"

#include <cmath>
#include <numbers>

namespace hsmu {

double PortableRandom::uniform()
{
    // 53 random bits mapped to the open interval (0, 1).
    const std::uint64_t bits = m_engine() >> 11;
    return (static_cast<double>(bits) + 0.5) * 0x1.0p-53;
}

double PortableRandom::normal()
{
    if (m_hasSpare) {
        m_hasSpare = false;
        return m_spare;
    }
    const double u1 = uniform();
    const double u2 = uniform();
    const double r = std::sqrt(-2.0 * std::log(u1));
    const double phi = 2.0 * std::numbers::pi * u2;
    m_spare = r * std::sin(phi);
    m_hasSpare = true;
    return r * std::cos(phi);
}

} // namespace hsmu
