#include "core/updating/TwinIdentification.h"

#include "core/updating/MrDamperUkfIdentifier.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace hsmu::rths {

namespace {
constexpr std::size_t kRing = 1u << 16; // samples (power of two)
struct Sample {
    long tick = 0;
    double u = 0.0, f = 0.0;
};
} // namespace

struct TwinIdentification::Impl {
    TwinIdentificationSettings s;
    long decimation = 1, intervalSamples = 1, latencyTicks = 0;
    std::unique_ptr<MrDamperUkfIdentifier> id;
    // The ring: the loop writes at head, the worker reads at tail.
    std::vector<Sample> ring = std::vector<Sample>(kRing);
    std::atomic<std::size_t> head{0}, tail{0};
    std::atomic<long> processed{-1}; // the last sample's tick the worker has taken
    std::atomic<long> dropped{0};
    std::atomic<bool> stop{false}, failed{false};
    mutable std::mutex m; // offers, due, failure
    std::condition_variable progress;
    std::deque<TwinUpdate> due;
    std::vector<TwinUpdate> all;
    std::string failure;
    std::thread worker;

    void work()
    {
        long samples = 0;
        while (!stop.load(std::memory_order_acquire)) {
            const std::size_t t = tail.load(std::memory_order_relaxed);
            if (t == head.load(std::memory_order_acquire)) {
                std::this_thread::sleep_for(std::chrono::microseconds(200));
                continue;
            }
            const Sample x = ring[t % kRing];
            TwinUpdate offer;
            bool offered = false;
            try {
                const IdentificationStatus st = id->observe(x.u, x.f, false);
                if (samples > 0 && samples % intervalSamples == 0 && st.ok && st.reportable) {
                    const auto e = id->estimate();
                    offer = TwinUpdate{id->layout().names(), std::vector<double>(e.begin(), e.end()),
                                       "identification", x.tick + latencyTicks};
                    offered = true;
                }
            } catch (const std::exception& e) {
                std::lock_guard lock(m);
                failure = std::string("the damper's identification failed: ") + e.what();
                failed.store(true, std::memory_order_release);
            }
            ++samples;
            tail.store(t + 1, std::memory_order_release);
            {
                std::lock_guard lock(m);
                if (offered) {
                    due.push_back(offer);
                    all.push_back(std::move(offer));
                }
                processed.store(x.tick, std::memory_order_release);
            }
            progress.notify_all();
            if (failed.load(std::memory_order_acquire))
                return;
        }
    }
};

TwinIdentification::TwinIdentification(const DamperSettings& damper,
                                       const TwinIdentificationSettings& s, double rate)
    : d(std::make_unique<Impl>())
{
    if (!damper.enabled)
        throw std::invalid_argument("RTHS identification: the run has no damper twin");
    if (s.decimation < 1 || !(s.interval > 0.0) || !(s.latency >= 0.0) || !(rate > 0.0))
        throw std::invalid_argument("RTHS identification: decimation >= 1, interval > 0 s and "
                                    "latency >= 0 s are needed");
    d->s = s;
    const double h = 1.0 / rate;
    d->decimation = s.decimation;
    d->intervalSamples = std::max(1L, std::lround(s.interval / (s.decimation * h)));
    d->latencyTicks = std::lround(s.latency / h);
    MrDamper model(damper.twin);
    model.setTimeIncrement(s.decimation * h);
    // The user bounds: the twin's box on the names the identifier filters.
    ParameterBoundsMap bounds;
    for (const auto& [name, b] : damper.box)
        if (name != "uRef" && name != "fRef" && name != "A")
            bounds[name] = b;
    d->id = std::make_unique<MrDamperUkfIdentifier>(model, damper.twin.uRef, damper.twin.fRef,
                                                    bounds);
    d->worker = std::thread([this] { d->work(); });
}

TwinIdentification::~TwinIdentification()
{
    d->stop.store(true, std::memory_order_release);
    if (d->worker.joinable())
        d->worker.join();
}

void TwinIdentification::observe(long k, double deformation, double force)
{
    if (k % d->decimation != 0 || d->failed.load(std::memory_order_acquire))
        return;
    const std::size_t h = d->head.load(std::memory_order_relaxed);
    while (h - d->tail.load(std::memory_order_acquire) >= kRing) {
        if (!d->s.wait) {
            d->dropped.fetch_add(1, std::memory_order_relaxed);
            return;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    d->ring[h % kRing] = Sample{k, deformation, force};
    d->head.store(h + 1, std::memory_order_release);
}

bool TwinIdentification::next(long k, TwinUpdate& out)
{
    const long period = d->intervalSamples * d->decimation;
    const long source = k - d->latencyTicks; // the tick of an offer due now
    std::unique_lock lock(d->m, std::defer_lock);
    if (d->s.wait) {
        lock.lock();
        if (source > 0 && source % period == 0)
            d->progress.wait(lock, [&] {
                return d->processed.load(std::memory_order_acquire) >= source ||
                       d->failed.load(std::memory_order_acquire);
            });
    } else if (!lock.try_lock()) {
        return false; // the worker holds it for a moment: the next tick looks again
    }
    if (d->due.empty() || d->due.front().due > k)
        return false;
    out = std::move(d->due.front());
    d->due.pop_front();
    return true;
}

std::vector<TwinUpdate> TwinIdentification::offers() const
{
    std::lock_guard lock(d->m);
    return d->all;
}

long TwinIdentification::samplesDropped() const
{
    return d->dropped.load();
}

std::string TwinIdentification::failure() const
{
    std::lock_guard lock(d->m);
    return d->failure;
}

} // namespace hsmu::rths
