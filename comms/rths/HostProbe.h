#pragma once
// HostProbe: can this computer keep the RTHS loop's pace? The pacer of the real loop
// (RealtimePacer with the same clock, spin margin and priority) releases N empty ticks and the
// probe keeps how late each release came (docs/rths.md, "Checking a host"). A lab runs it
// before a real-time test (`hsmu rths CONFIG --probe-host SECONDS`): a host that misses
// deadlines with no work at all cannot run the test without misses.

#include "comms/rths/RealtimePacer.h"

#include <array>
#include <string>

namespace hsmu::comms {

struct HostProbeResult {
    long ticks = 0;
    long misses = 0;              ///< ticks that ended after their deadline (the pacer's count)
    double worstLateness = 0.0;   ///< [s] the pacer's worst lateness past a deadline
    double worstRelease = 0.0;    ///< [s] the latest release after its scheduled time
    /// Releases by lateness [us]: < 10, < 50, < 100, < period, < 2 periods, >= 2 periods.
    std::array<long, 6> histogram{};
};

/// Releases `ticks` ticks of `period` [s] on `clock` (no work inside) and measures them.
HostProbeResult probeHost(PaceClock& clock, double period, long ticks);

/// One line: ticks, misses, worst lateness and the histogram, in microseconds.
std::string describeHostProbe(const HostProbeResult& r, double period);

} // namespace hsmu::comms
