#include "gui/app/RecordBuffer.h"

namespace hsmu::gui {

bool RecordBuffer::push(const StepRecord& record) {
    const std::lock_guard lock(m_mutex);
    const bool wasEmpty = m_rows.empty();
    m_rows.push_back(record);
    m_pushed.fetch_add(1, std::memory_order_relaxed);
    return wasEmpty;
}

std::vector<StepRecord> RecordBuffer::takeAll() {
    std::vector<StepRecord> out;
    const std::lock_guard lock(m_mutex);
    out.swap(m_rows);
    return out;
}

} // namespace hsmu::gui
