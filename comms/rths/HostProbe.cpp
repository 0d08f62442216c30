#include "comms/rths/HostProbe.h"

#include <algorithm>
#include <cstdint>
#include <sstream>

namespace hsmu::comms {

namespace {

int bin(double lateUs, double periodUs)
{
    if (lateUs < 10.0)
        return 0;
    if (lateUs < 50.0)
        return 1;
    if (lateUs < 100.0)
        return 2;
    if (lateUs < periodUs)
        return 3;
    return lateUs < 2.0 * periodUs ? 4 : 5;
}

} // namespace

HostProbeResult probeHost(PaceClock& clock, double period, long ticks)
{
    HostProbeResult r;
    RealtimePacer pacer(clock, period, 0);
    std::chrono::nanoseconds start{0};
    const std::chrono::nanoseconds h(std::int64_t(period * 1e9 + 0.5)); // as the pacer rounds it
    std::string why;
    for (long k = 0; k < ticks; ++k) {
        pacer.admit(k, why); // never refuses: no hold policy
        const auto now = clock.now();
        if (k == 0)
            start = now;
        const double late = std::max<std::int64_t>(0, (now - start - k * h).count()) * 1e-9;
        r.worstRelease = std::max(r.worstRelease, late);
        ++r.histogram[std::size_t(bin(late * 1e6, period * 1e6))];
        pacer.done(k);
    }
    r.ticks = ticks;
    r.misses = pacer.misses();
    r.worstLateness = pacer.worstLateness();
    return r;
}

std::string describeHostProbe(const HostProbeResult& r, double period)
{
    std::ostringstream o;
    o.setf(std::ios::fixed);
    o.precision(1);
    const double p = period * 1e6;
    o << r.ticks << " ticks of " << p << " us: " << r.misses << " deadline misses (worst " << r.worstLateness * 1e6
      << " us past a deadline); releases late by < 10 us " << r.histogram[0] << ", < 50 us " << r.histogram[1]
      << ", < 100 us " << r.histogram[2] << ", < " << p << " us " << r.histogram[3] << ", < " << 2.0 * p << " us "
      << r.histogram[4] << ", more " << r.histogram[5] << " (worst " << r.worstRelease * 1e6 << " us)";
    return o.str();
}

} // namespace hsmu::comms
