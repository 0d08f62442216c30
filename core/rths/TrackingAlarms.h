#pragma once
// TrackingAlarms: the live J1 (delay) and J2 (tracking error) of an RTHS run against the
// operator's thresholds (docs/rths.md, "Live tracking"). Each index has a warning and a
// critical level; an estimate past a level raises one alarm of that severity (kind
// TrackingError, code "rths-j1-warning" / "-critical", "rths-j2-...", arguments value and
// limit) when the index rises to it, once per excursion: nothing more while it stays there, and
// it leaves a level only below (1 - kRearm) of its threshold, so an index hovering at a
// threshold raises one alarm, not one per estimate (a warning again after the index fell below
// 0.9 x warning; a critical one after it fell below 0.9 x critical).
// Thresholds may change between estimates (effective at the next one).

#include "core/rths/TrackingWindow.h"
#include "core/util/Alarm.h"

#include <string>
#include <vector>

namespace hsmu::rths {

struct TrackingLimits {
    double j1Warning = 2.0;   ///< [ms]
    double j1Critical = 5.0;  ///< [ms]
    double j2Warning = 5.0;   ///< [%]
    double j2Critical = 10.0; ///< [%]
};

/// "" when usable: each level finite, >= 0, warning <= critical; else what is wrong.
std::string checkTrackingLimits(const TrackingLimits& limits);

class TrackingAlarms {
public:
    static constexpr double kRearm = 0.1; ///< a level is left below (1 - kRearm) x its threshold [-]

    explicit TrackingAlarms(const TrackingLimits& limits = {});
    /// Throws std::invalid_argument when checkTrackingLimits fails (the old limits kept).
    void setLimits(const TrackingLimits& limits);
    const TrackingLimits& limits() const { return m_limits; }
    /// Judge one estimate; the alarms it raises are appended to `out` (J1's first). An
    /// estimate the window gated (valid false) raises nothing and leaves the levels as they are.
    void judge(const TrackingEstimate& e, std::vector<Alarm>& out);
    /// 0 below warning, 1 warning, 2 critical, per index (after the last judge()).
    int j1Level() const { return m_j1; }
    int j2Level() const { return m_j2; }
    void reset() { m_j1 = m_j2 = 0; }

private:
    TrackingLimits m_limits;
    int m_j1 = 0, m_j2 = 0;
};

} // namespace hsmu::rths
