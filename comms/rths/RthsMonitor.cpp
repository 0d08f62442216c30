#include "comms/rths/RthsMonitor.h"

#include <algorithm>
#include <chrono>
#include <thread>
#include <utility>
#include <cmath>
#include <sstream>

namespace hsmu::comms {

bool MonitorGate::admit(long k, std::string& why)
{
    if (m_requested.load(std::memory_order_acquire)) {
        std::lock_guard lock(m_mutex);
        std::ostringstream o;
        o.precision(6);
        o << m_reason << " before tick " << k << " (t = " << double(k) * m_h << " s): test held";
        why = o.str();
        return false;
    }
    return m_pacer ? m_pacer->admit(k, why) : true;
}

void MonitorGate::done(long k)
{
    if (!m_pacer)
        return;
    m_pacer->done(k);
    m_misses.store(m_pacer->misses(), std::memory_order_relaxed);
    m_worst.store(m_pacer->worstLateness(), std::memory_order_relaxed);
}

void MonitorGate::resume(long k)
{
    {
        std::lock_guard lock(m_mutex);
        m_reason.clear();
        m_requested.store(false, std::memory_order_release);
    }
    if (m_pacer)
        m_pacer->resume(k);
}

void MonitorGate::requestHold(const std::string& reason)
{
    std::lock_guard lock(m_mutex);
    if (m_requested.load(std::memory_order_relaxed))
        return;
    m_reason = reason;
    m_requested.store(true, std::memory_order_release);
}

void TelemetryFeed::onTick(long k, const rths::RthsTick& t,
                           const Eigen::Ref<const Eigen::RowVectorXd, 0, Eigen::InnerStride<>>&)
{
    if (k % m_every != 0)
        return;
    m_produced.fetch_add(1, std::memory_order_relaxed);
    const std::size_t head = m_head.load(std::memory_order_relaxed);
    if (head - m_tail.load(std::memory_order_acquire) >= kCapacity) {
        m_dropped.fetch_add(1, std::memory_order_relaxed);
        return;
    }
    m_ring[head % kCapacity] = TelemetrySample{k, t.time, t.desired, t.command, t.measured,
                                               t.force, m_gate.misses(), m_gate.worstLateness()};
    m_head.store(head + 1, std::memory_order_release);
}

bool TelemetryFeed::pop(TelemetrySample& out)
{
    const std::size_t tail = m_tail.load(std::memory_order_relaxed);
    if (tail == m_head.load(std::memory_order_acquire))
        return false;
    out = m_ring[tail % kCapacity];
    m_tail.store(tail + 1, std::memory_order_release);
    return true;
}

bool FastPaceGate::admit(long k, std::string& why)
{
    while (m_feed.pending() > TelemetryFeed::kCapacity / 2 && !m_gate.holdRequested())
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return m_gate.admit(k, why);
}

long defaultDecimation(double rate)
{
    return std::max(1L, std::lround(rate / 128.0));
}

void UpdateOutbox::onUpdate(long, const UpdateEvent& e)
{
    std::lock_guard lock(m_mutex);
    m_events.push_back(e);
}

std::vector<UpdateEvent> UpdateOutbox::take()
{
    std::lock_guard lock(m_mutex);
    return std::exchange(m_events, {});
}

} // namespace hsmu::comms
