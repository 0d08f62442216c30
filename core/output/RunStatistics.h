#pragma once
// RunStatistics: a StepObserver keeping what a run's summary reports: the number of records,
// the last record (final state) and peak absolute values over every committed step:
//   displacement per DOF [m], force and deformation per element (the element's units,
//   measured for a specimen), ground acceleration [m/s^2].
// Non-finite values are ignored for the peaks.
//
// Thread rules: onStep() runs on the test's thread; read the results once the test stopped
// stepping (or on that thread).

#include "core/output/RunLayout.h"
#include "core/experiment/StepRecord.h"

#include <vector>

namespace hsmu {

class RunStatistics final : public StepObserver {
public:
    explicit RunStatistics(RunLayout layout);

    void onStep(const StepRecord& record) override;

    const RunLayout& layout() const { return m_layout; }
    /// Records seen, the initial state (step 0) included.
    int recordCount() const { return m_count; }
    /// The last record seen (default-constructed before any).
    const StepRecord& last() const { return m_last; }
    const std::vector<double>& peakDisplacement() const { return m_peakU; }
    const std::vector<double>& peakForce() const { return m_peakForce; }
    const std::vector<double>& peakDeformation() const { return m_peakDeformation; }
    double peakGroundAcceleration() const { return m_peakAg; }

private:
    RunLayout m_layout;
    int m_count = 0;
    StepRecord m_last;
    std::vector<double> m_peakU, m_peakForce, m_peakDeformation;
    double m_peakAg = 0.0;
};

} // namespace hsmu
