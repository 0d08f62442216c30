#pragma once
// ScheduledJob: the online identifiers' heavy work (calibrations of the history so far, replays
// of an estimate over it) on a worker thread, with its result applied at a step fixed when it
// starts (docs/method.md, "The robust UKF", Jobs). Used by AnchoredUkf.h (the robust,
// pinching and MR damper UKFs).
//
//  - start(n, meta, work): work(cancel) runs on a worker (std::async), at most one job at a
//    time, on inputs the caller has copied at history size n (the snapshot at step N_k); meta
//    is the caller's bookkeeping of the job, kept on the caller's thread.
//  - due(n): the history has reached applyAt() = N_k + scheduledJobDelay(N_k) = N_k + max(50, N_k / 20).
//    take() then returns the outcome, waiting for the worker if it has not finished (counted in
//    waits()). So what is applied, and when, depends on the samples only, not on the machine's
//    speed: an online run and an offline replay of its record give the same estimates bit for
//    bit.
//  - cancel(): sets the job's cancel flag (which the work checks between its iterations, e.g.
//    CalibrationSpec::cancel) and waits for the work to return; its outcome is returned, not
//    applied. The destructor cancels a running job, so closing a test or the replay window
//    does not wait for a calibration of the whole history.
// Thread rules: every member from one thread (the stepping thread); the work must only read
// its own copy of its inputs and the flag.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <utility>

namespace hsmu {

/// The step distance, in samples, between starting a job on a history of n samples and
/// applying its result: max(50, n / 20).
inline std::size_t scheduledJobDelay(std::size_t n) { return std::max<std::size_t>(50, n / 20); }

template <class Meta, class Outcome>
class ScheduledJob {
public:
    using Work = std::function<Outcome(const std::atomic<bool>& cancel)>;

    ScheduledJob() = default;
    ScheduledJob(const ScheduledJob&) = delete;
    ScheduledJob& operator=(const ScheduledJob&) = delete;
    ~ScheduledJob() { cancel(); }

    bool running() const { return m_future.valid(); }
    /// Starts work on a history of n samples (precondition: !running()); its meta, to amend.
    Meta& start(std::size_t n, Meta meta, Work work) {
        m_meta = std::move(meta);
        m_startSize = n;
        m_applyAt = n + scheduledJobDelay(n);
        m_cancel = std::make_shared<std::atomic<bool>>(false);
        m_future = std::async(std::launch::async,
                              [flag = m_cancel, work = std::move(work)] { return work(*flag); });
        ++m_started;
        return m_meta;
    }
    /// The running job's result is to be applied at history size n.
    bool due(std::size_t n) const { return running() && n >= m_applyAt; }
    Meta& meta() { return m_meta; }
    std::size_t startSize() const { return m_startSize; }
    std::size_t applyAt() const { return m_applyAt; }

    struct Taken {
        Meta meta;
        Outcome outcome;
        std::size_t startSize = 0;
    };
    /// The running job's outcome (waits for the worker if needed); the job is then over.
    Taken take() {
        if (m_future.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
            ++m_waits;
        Taken t{std::move(m_meta), m_future.get(), m_startSize};
        m_meta = Meta{};
        m_cancel.reset();
        return t;
    }
    /// Cancels the running job and returns its outcome once the work has returned (nothing if
    /// no job runs).
    std::optional<Outcome> cancel() {
        if (!running())
            return std::nullopt;
        m_cancel->store(true);
        m_cancel->notify_all();
        Outcome out = m_future.get();
        m_meta = Meta{};
        m_cancel.reset();
        ++m_cancelled;
        return out;
    }

    /// Jobs started, applications that had to wait for the worker (informative: depends on
    /// the machine), jobs cancelled.
    int started() const { return m_started; }
    int waits() const { return m_waits; }
    int cancelled() const { return m_cancelled; }

private:
    Meta m_meta{};
    std::size_t m_startSize = 0, m_applyAt = 0;
    std::shared_ptr<std::atomic<bool>> m_cancel;
    std::future<Outcome> m_future;
    int m_started = 0, m_waits = 0, m_cancelled = 0;
};

} // namespace hsmu
