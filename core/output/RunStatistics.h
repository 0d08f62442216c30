#pragma once
// RunStatistics: a StepObserver keeping what a run's summary reports: the number of records,
// the last record (final state) and peak absolute values over every committed step:
//   displacement per DOF [m], force and deformation per element (the element's units,
//   measured for a specimen), ground acceleration [m/s^2], and per channel of a multi-DOF
//   element (every basic DOF and actuator, RunLayout::channels; their units).
// Non-finite values are ignored for the peaks. For each specimen (an experimental element) it
// also keeps the commanded and measured deformation of every step after the initial state, for
// the tracking criteria of the summary (core/rths/TrackingMetrics.h: J1-J3, M5, M6).
//
// Thread rules: onStep() runs on the test's thread; read the results once the test stopped
// stepping (or on that thread).

#include "core/output/RunLayout.h"
#include "core/experiment/StepRecord.h"
#include "core/rths/TrackingMetrics.h"

#include <optional>

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
    /// Peak |value| per multi-DOF element channel (layout().channels order, their units).
    const std::vector<double>& peakChannel() const { return m_peakChannel; }
    /// Element i's commanded / measured deformation from step 1 on (its units); empty for a
    /// numerical element.
    const std::vector<double>& commanded(std::size_t i) const { return m_commanded[i]; }
    const std::vector<double>& measured(std::size_t i) const { return m_measured[i]; }
    /// Element i's tracking (rths::trackingReport of the histories above, sampled at dt [s]),
    /// computed once and kept; nullptr for an element with fewer than two samples. Call once
    /// the test stopped stepping.
    const rths::TrackingReport* tracking(std::size_t i, double dt) const;

private:
    RunLayout m_layout;
    int m_count = 0;
    StepRecord m_last;
    std::vector<double> m_peakU, m_peakForce, m_peakDeformation, m_peakChannel;
    double m_peakAg = 0.0;
    std::vector<std::vector<double>> m_commanded, m_measured;
    mutable std::vector<std::optional<rths::TrackingReport>> m_tracking;
};

} // namespace hsmu
