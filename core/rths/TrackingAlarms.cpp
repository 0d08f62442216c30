#include "core/rths/TrackingAlarms.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace hsmu::rths {

namespace {

std::string number(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

/// The level of value against (warning, critical), from the level held so far: a level is
/// entered above its threshold and left only below (1 - kRearm) of it (no chatter of an index
/// that hovers at a threshold).
int levelOf(double value, double warning, double critical, int held)
{
    const int entered = value > critical ? 2 : value > warning ? 1 : 0;
    if (entered >= held)
        return entered;
    const double keep = 1.0 - TrackingAlarms::kRearm;
    if (held == 2 && value > keep * critical)
        return 2;
    return value > keep * warning ? std::max(entered, 1) : entered;
}

void judgeOne(const char* code, const char* what, const char* unit, double value, double warning,
              double critical, int& level, const TrackingEstimate& e, std::vector<Alarm>& out)
{
    const int now = levelOf(value, warning, critical, level);
    if (now > level) {
        const bool crit = now == 2;
        const double limit = crit ? critical : warning;
        out.emplace_back(e.time, int(e.tick), crit ? AlarmSeverity::Critical : AlarmSeverity::Warning,
                         AlarmKind::TrackingError,
                         std::string(what) + " = " + number(value) + " " + unit + " over the " +
                             (crit ? "critical" : "warning") + " threshold " + number(limit) + " " + unit,
                         std::string(code) + (crit ? "-critical" : "-warning"),
                         std::vector<std::string>{number(value), number(limit)});
    }
    level = now;
}

} // namespace

std::string checkTrackingLimits(const TrackingLimits& l)
{
    for (double v : {l.j1Warning, l.j1Critical, l.j2Warning, l.j2Critical})
        if (!std::isfinite(v) || v < 0.0)
            return "tracking thresholds must be finite and >= 0";
    if (l.j1Warning > l.j1Critical)
        return "J1: the warning threshold is above the critical one";
    if (l.j2Warning > l.j2Critical)
        return "J2: the warning threshold is above the critical one";
    return {};
}

TrackingAlarms::TrackingAlarms(const TrackingLimits& limits)
{
    setLimits(limits);
}

void TrackingAlarms::setLimits(const TrackingLimits& limits)
{
    if (const std::string e = checkTrackingLimits(limits); !e.empty())
        throw std::invalid_argument(e);
    m_limits = limits;
}

void TrackingAlarms::judge(const TrackingEstimate& e, std::vector<Alarm>& out)
{
    if (!e.valid)
        return; // no estimate (too quiet): nothing raised, the levels kept
    judgeOne("rths-j1", "live delay J1", "ms", e.delay, m_limits.j1Warning, m_limits.j1Critical, m_j1, e, out);
    judgeOne("rths-j2", "live tracking error J2", "%", e.j2, m_limits.j2Warning, m_limits.j2Critical, m_j2, e, out);
}

} // namespace hsmu::rths
