#pragma once
// RealtimePacer: runs the RTHS loop's ticks at the wall-clock pace of the loop period
// (docs/rths.md, "Real time"). Tick k is released at start + k h (absolute deadlines, no drift);
// its work must end before start + (k + 1) h, else it is a deadline miss (counted, its lateness
// kept). After holdAfterMisses misses (0: never) the next admit() refuses with a sentence naming
// the tick and the lateness: the test holds. The clock is injected so that tests drive it
// without sleeping.

#include "core/rths/RthsBenchmark.h"

#include <chrono>
#include <cstdint>
#include <string>

namespace hsmu::comms {

class PaceClock {
public:
    virtual ~PaceClock() = default;
    virtual std::chrono::nanoseconds now() = 0;
    virtual void sleepUntil(std::chrono::nanoseconds t) = 0;
};

/// CLOCK_MONOTONIC with clock_nanosleep(TIMER_ABSTIME).
class MonotonicClock final : public PaceClock {
public:
    std::chrono::nanoseconds now() override;
    void sleepUntil(std::chrono::nanoseconds t) override;
};

/// A clock that sleeps until `margin` before each release and busy-waits the rest (docs/rths.md,
/// "Real time"): a kernel without PREEMPT_RT wakes a sleeping thread up to hundreds of
/// microseconds late, a spinning one sees the release as it comes. Costs margin / period of a
/// core; under SCHED_FIFO keep margin well below the period (the kernel throttles a real-time
/// thread that never sleeps: sched_rt_runtime_us).
class SpinningClock final : public PaceClock {
public:
    SpinningClock(PaceClock& inner, std::chrono::nanoseconds margin);
    std::chrono::nanoseconds now() override { return m_inner.now(); }
    void sleepUntil(std::chrono::nanoseconds t) override;

private:
    PaceClock& m_inner;
    std::chrono::nanoseconds m_margin;
};

/// The default busy-wait before a release: a quarter of the period, at most 100 us (the native
/// controller's 1024 Hz loop spins 100 us too): 61 us at 4096 Hz.
std::chrono::nanoseconds defaultSpinMargin(double period);

class RealtimePacer final : public rths::TickGate {
public:
    RealtimePacer(PaceClock& clock, double period, int holdAfterMisses);

    bool admit(long k, std::string& why) override;
    void done(long k) override;
    /// A held run goes on with tick k: k is released now (the schedule restarts, the time held
    /// is no lateness) and the policy counts the misses from here (misses() keeps them all).
    void resume(long k) override;

    long misses() const { return m_misses; }
    double worstLateness() const { return m_worst; } ///< [s]
    long firstMissTick() const { return m_firstMiss; } ///< -1: none
    /// The policy holds the run (holdAfterMisses reached since the start or the last resume).
    bool policyHolds() const { return m_holdAfter > 0 && m_misses - m_missesBeforeResume >= m_holdAfter; }

private:
    PaceClock& m_clock;
    std::chrono::nanoseconds m_period;
    int m_holdAfter;
    std::chrono::nanoseconds m_start{0};
    long m_misses = 0, m_firstMiss = -1, m_lastMiss = -1;
    long m_missesBeforeResume = 0; // not counted by the policy
    double m_worst = 0.0, m_lastLateness = 0.0;
};

/// Put the calling thread under SCHED_FIFO at priority (1..99) and lock the process's memory;
/// "" on success, else why not (e.g. no CAP_SYS_NICE): the run goes on at normal priority.
std::string enterRealtimePriority(int priority);

} // namespace hsmu::comms
