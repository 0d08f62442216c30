#include "comms/rths/RealtimePacer.h"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <sstream>

namespace hsmu::comms {

std::chrono::nanoseconds MonotonicClock::now()
{
    timespec ts{};
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return std::chrono::seconds(ts.tv_sec) + std::chrono::nanoseconds(ts.tv_nsec);
}

void MonotonicClock::sleepUntil(std::chrono::nanoseconds t)
{
    timespec ts{};
    ts.tv_sec = time_t(t.count() / 1000000000);
    ts.tv_nsec = long(t.count() % 1000000000);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
}

SpinningClock::SpinningClock(PaceClock& inner, std::chrono::nanoseconds margin)
    : m_inner(inner), m_margin(std::max(margin, std::chrono::nanoseconds(0)))
{
}

void SpinningClock::sleepUntil(std::chrono::nanoseconds t)
{
    if (m_margin.count() == 0) {
        m_inner.sleepUntil(t);
        return;
    }
    m_inner.sleepUntil(t - m_margin);
    while (m_inner.now() < t) {
    }
}

std::chrono::nanoseconds defaultSpinMargin(double period)
{
    return std::chrono::nanoseconds(std::int64_t(std::min(100e-6, 0.25 * period) * 1e9));
}

RealtimePacer::RealtimePacer(PaceClock& clock, double period, int holdAfterMisses)
    : m_clock(clock), m_period(std::chrono::nanoseconds(std::int64_t(period * 1e9 + 0.5))),
      m_holdAfter(holdAfterMisses)
{
}

bool RealtimePacer::admit(long k, std::string& why)
{
    if (k == 0) {
        prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL); // timer slack 1 ns (default 50 us) for this thread
        m_start = m_clock.now();
    }
    if (policyHolds()) {
        std::ostringstream o;
        o.precision(3);
        o << m_misses << " deadline misses (the last at tick " << m_lastMiss << ", "
          << m_lastLateness * 1e6 << " us late; the worst " << m_worst * 1e6
          << " us): test held before tick " << k;
        why = o.str();
        return false;
    }
    m_clock.sleepUntil(m_start + k * m_period);
    return true;
}

void RealtimePacer::resume(long k)
{
    m_start = m_clock.now() - k * m_period;
    m_missesBeforeResume = m_misses;
}

void RealtimePacer::done(long k)
{
    const auto deadline = m_start + (k + 1) * m_period;
    const auto now = m_clock.now();
    if (now <= deadline)
        return;
    const double late = std::chrono::duration<double>(now - deadline).count();
    ++m_misses;
    if (m_firstMiss < 0)
        m_firstMiss = k;
    m_lastMiss = k;
    m_lastLateness = late;
    m_worst = std::max(m_worst, late);
}

std::string enterRealtimePriority(int priority)
{
    sched_param p{};
    p.sched_priority = priority;
    if (const int e = pthread_setschedparam(pthread_self(), SCHED_FIFO, &p); e != 0)
        return std::string("SCHED_FIFO refused: ") + std::strerror(e);
    if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0)
        return std::string("mlockall refused: ") + std::strerror(errno);
    return {};
}

} // namespace hsmu::comms
