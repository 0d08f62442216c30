#include "core/record/RecordThread.h"

#include <utility>

namespace hsmu {

RecordThread::RecordThread(std::function<void()> job)
    : m_job(std::move(job)), m_thread([this] { run(); }) {}

RecordThread::~RecordThread() {
    {
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [this] { return !m_pending; });
        m_stopping = true;
    }
    m_changed.notify_all();
    m_thread.join();
}

void RecordThread::wait() {
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [this] { return !m_pending; });
}

void RecordThread::start() {
    {
        std::unique_lock lock(m_mutex);
        m_changed.wait(lock, [this] { return !m_pending; });
        m_pending = true;
    }
    m_changed.notify_all();
}

void RecordThread::run() {
    std::unique_lock lock(m_mutex);
    for (;;) {
        m_changed.wait(lock, [this] { return m_pending || m_stopping; });
        if (!m_pending)
            return; // stopping with nothing to do
        lock.unlock();
        m_job();
        lock.lock();
        m_pending = false;
        m_changed.notify_all();
    }
}

} // namespace hsmu
