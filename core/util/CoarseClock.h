#pragma once
// CoarseClock: a steady std::chrono clock read from Linux's CLOCK_MONOTONIC_COARSE: the time
// of the last kernel tick, so its resolution is the tick (1-10 ms; 4 ms with Debian's
// kernels) and a read costs a few nanoseconds, against about 20 ns for steady_clock (a TSC
// read, slower under a hypervisor). For intervals of 0.1 s and more that are checked once a
// step: RecordWriter's flush interval, TestSession::advance()'s budget (issue 27: those two
// steady_clock reads a step were 3 % of the strong SDOF's CPU). Not for pacing or timing.
// Falls back to steady_clock where the coarse clock does not exist.
// Thread rules: none (now() is thread-safe).

#include <chrono>
#include <ctime>

namespace hsmu {

struct CoarseClock {
    using duration = std::chrono::nanoseconds;
    using rep = duration::rep;
    using period = duration::period;
    using time_point = std::chrono::time_point<CoarseClock>;
    static constexpr bool is_steady = true;

    static time_point now() noexcept {
#ifdef CLOCK_MONOTONIC_COARSE
        timespec ts{};
        if (clock_gettime(CLOCK_MONOTONIC_COARSE, &ts) == 0)
            return time_point(std::chrono::seconds(ts.tv_sec) +
                              std::chrono::nanoseconds(ts.tv_nsec));
#endif
        return time_point(std::chrono::duration_cast<duration>(
            std::chrono::steady_clock::now().time_since_epoch()));
    }
};

} // namespace hsmu
