#pragma once
// RecordBuffer: StepRecords handed from the test worker to the GUI (the PlotJuggler pattern):
// the worker pushes under a short lock; the GUI takes every pending row at once, at most
// ~30 times a second, and replots once.
// Thread rules: push() from the worker thread, takeAll() from the GUI thread; both lock.

#include "core/experiment/StepRecord.h"

#include <atomic>
#include <mutex>
#include <vector>

namespace hsmu::gui {

class RecordBuffer {
public:
    /// Append a copy. True if the buffer was empty before (the caller should notify once).
    bool push(const StepRecord& record);
    /// Move every pending row out (oldest first) and leave the buffer empty.
    std::vector<StepRecord> takeAll();
    /// Rows pushed so far (any thread, lock-free): the worker's progress even while the GUI
    /// thread takes nothing.
    long long pushedCount() const { return m_pushed.load(std::memory_order_relaxed); }

private:
    std::mutex m_mutex;
    std::vector<StepRecord> m_rows;
    std::atomic<long long> m_pushed{0};
};

} // namespace hsmu::gui
