#pragma once
// RecordCollector: a StepObserver keeping a copy of every StepRecord (for the plots that
// `hsmu run --plots` draws after the run). Memory: one record per step (a few hundred bytes).
// Thread rules: onStep() on the test's thread; read records() after the test stopped.

#include "core/experiment/StepRecord.h"

#include <vector>

namespace hsmu::gui {

class RecordCollector final : public StepObserver {
public:
    void onStep(const StepRecord& record) override { m_records.push_back(record); }
    const std::vector<StepRecord>& records() const { return m_records; }

private:
    std::vector<StepRecord> m_records;
};

} // namespace hsmu::gui
