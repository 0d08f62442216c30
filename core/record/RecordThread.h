#pragma once
// RecordThread: the one background thread of a RecordWriter (docs/recording.md, "Writing off
// the stepping thread"). The stepping thread fills a batch of rows in memory; at a flush it
// waits until the thread has finished the previous batch (back-pressure: a row is never
// dropped, at most one batch is being written while the next one fills), swaps the batches
// and starts the job, which writes the full batch to the file. The job runs on this thread
// only, one at a time; nothing else of the writer runs here.
//
// Thread rules: start(), wait() and the destructor on the owner's (stepping) thread.

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace hsmu {

class RecordThread {
public:
    /// Starts the thread; `job` is called on it once per start().
    explicit RecordThread(std::function<void()> job);
    /// Waits for a running job, then stops and joins the thread.
    ~RecordThread();
    RecordThread(const RecordThread&) = delete;
    RecordThread& operator=(const RecordThread&) = delete;

    /// Blocks until no job is running (returns at once when idle).
    void wait();
    /// Runs the job once on the thread. Call wait() first: a job is never queued behind
    /// another (the caller hands its data over between the two calls).
    void start();

private:
    void run();

    std::function<void()> m_job;
    std::mutex m_mutex;
    std::condition_variable m_changed;
    bool m_pending = false; // a job was started and has not finished
    bool m_stopping = false;
    std::thread m_thread; // last: started once the members above exist
};

} // namespace hsmu
