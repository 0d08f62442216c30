#pragma once
// RthsMonitor: what the controller-side RTHS loop (hsmu-controller --rths; docs/rths.md, "The
// loop on the controller") needs beside runRths, between the loop's thread and the io thread
// that serves the monitor, without the loop ever waiting on the link:
//
//   MonitorGate    the run's TickGate: a hold asked by the monitor (Hold, EmergencyHold) or by
//                  the link's loss refuses the next tick with a sentence naming it and the
//                  tick; otherwise the RealtimePacer's admit / done (real-time pace), or
//                  nothing (fast pace).
//   FastPaceGate   the fast pace's gate: MonitorGate's holds, and a wait while the feed's ring
//                  is half full, so a fast run (CI, the benchmark) drops no sample however
//                  slowly its reader drains; never used at the real-time pace.
//   TelemetryFeed  the run's TickObserver: one sample every `decimation` ticks into a bounded
//                  single-producer single-consumer ring (kCapacity samples); a full ring drops
//                  the sample and counts it (the loop is never delayed).
//   UpdateOutbox   the run's TickObserver of the damper twin's update decisions (applied or
//                  refused, each with its tick), kept for another thread to take (rare: a short
//                  lock each): the controller's io thread, the console's view.
//
// Thread rules: admit / done / onTick on the loop's thread; requestHold and pop on the io
// thread; the counters from any thread.

#include "comms/rths/RealtimePacer.h"
#include "core/rths/RthsBenchmark.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace hsmu::comms {

class MonitorGate final : public rths::TickGate {
public:
    /// pacer: the real-time pace's (nullptr: fast pace); period h [s] for the hold's sentence.
    MonitorGate(RealtimePacer* pacer, double period) : m_pacer(pacer), m_h(period) {}

    bool admit(long k, std::string& why) override;
    void done(long k) override;
    /// The held run goes on with tick k: the hold asked is forgotten (a new one may come), the
    /// pacer's schedule restarts.
    void resume(long k) override;

    /// Hold before the next tick; the first request's reason is kept ("console hold: ...").
    void requestHold(const std::string& reason);
    bool holdRequested() const { return m_requested.load(std::memory_order_acquire); }
    long misses() const { return m_misses.load(std::memory_order_relaxed); }
    double worstLateness() const { return m_worst.load(std::memory_order_relaxed); } ///< [s]

private:
    RealtimePacer* m_pacer;
    double m_h;
    std::atomic<bool> m_requested{false};
    std::mutex m_mutex; // guards m_reason (taken by the loop once, when it holds)
    std::string m_reason;
    std::atomic<long> m_misses{0};
    std::atomic<double> m_worst{0.0};
};

/// One decimated tick as the loop saw it.
struct TelemetrySample {
    long tick = 0;
    double time = 0.0, desired = 0.0, command = 0.0, measured = 0.0, force = 0.0;
    long misses = 0;
    double worstLateness = 0.0;
};

class TelemetryFeed final : public rths::TickObserver {
public:
    static constexpr std::size_t kCapacity = 8192; ///< samples (64 s at 128 frames per second)

    TelemetryFeed(const MonitorGate& gate, long decimation) : m_gate(gate), m_every(decimation) {}

    void onTick(long k, const rths::RthsTick& tick,
                const Eigen::Ref<const Eigen::RowVectorXd, 0, Eigen::InnerStride<>>& reference) override;
    /// The oldest sample not yet taken; false when the ring is empty.
    bool pop(TelemetrySample& out);
    long produced() const { return m_produced.load(std::memory_order_relaxed); } ///< samples made
    long dropped() const { return m_dropped.load(std::memory_order_relaxed); }   ///< ring full
    /// Samples in the ring, not yet taken.
    std::size_t pending() const { return m_head.load(std::memory_order_acquire) - m_tail.load(std::memory_order_acquire); }

private:
    const MonitorGate& m_gate;
    long m_every;
    std::array<TelemetrySample, kCapacity> m_ring{};
    std::atomic<std::size_t> m_head{0}, m_tail{0}; // written by the loop / by the io thread
    std::atomic<long> m_produced{0}, m_dropped{0};
};

class FastPaceGate final : public rths::TickGate {
public:
    FastPaceGate(MonitorGate& gate, const TelemetryFeed& feed) : m_gate(gate), m_feed(feed) {}
    bool admit(long k, std::string& why) override;
    void done(long k) override { m_gate.done(k); }
    void resume(long k) override { m_gate.resume(k); }

private:
    MonitorGate& m_gate;
    const TelemetryFeed& m_feed;
};

class UpdateOutbox final : public rths::TickObserver {
public:
    void onTick(long, const rths::RthsTick&,
                const Eigen::Ref<const Eigen::RowVectorXd, 0, Eigen::InnerStride<>>&) override {}
    void onUpdate(long k, const UpdateEvent& e) override;
    /// Every decision since the last take, oldest first (any thread).
    std::vector<UpdateEvent> take();

private:
    std::mutex m_mutex;
    std::vector<UpdateEvent> m_events;
};

/// The default decimation: about 128 telemetry frames per second at the loop's rate [Hz].
long defaultDecimation(double rate);

} // namespace hsmu::comms
