#include "core/rths/DamperTwin.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>

namespace hsmu::rths {

namespace {

const char* kTwin = "damper twin";

std::vector<int> lawIndices(const MrDamper& law, const std::vector<std::string>& names)
{
    const std::vector<std::string> known = law.parameterNames();
    std::vector<int> out;
    out.reserve(names.size());
    for (const std::string& n : names) {
        const auto it = std::find(known.begin(), known.end(), n);
        out.push_back(it == known.end() ? -1 : int(it - known.begin()));
    }
    return out;
}

} // namespace

std::string checkTwinUpdate(const DamperSettings& s, const TwinUpdate& u)
{
    if (!s.enabled)
        return "this RTHS run has no damper twin to update";
    if (u.names.empty() || u.names.size() != u.values.size())
        return "an update needs one value per parameter name (at least one)";
    const MrDamper law(s.twin);
    const std::vector<int> index = lawIndices(law, u.names);
    std::ostringstream o;
    o.precision(6);
    for (std::size_t i = 0; i < u.names.size(); ++i) {
        const std::string& n = u.names[i];
        if (index[i] < 0) {
            o << "unknown parameter '" << n << "' of the mrDamper twin";
            return o.str();
        }
        if (std::count(u.names.begin(), u.names.end(), n) > 1)
            return "parameter '" + n + "' given twice";
        if (!std::isfinite(u.values[i]))
            return "parameter '" + n + "' is not finite";
        if (const auto b = s.box.find(n); b != s.box.end() && !b->second.contains(u.values[i])) {
            o << n << " = " << u.values[i] << " is outside the parameter box [" << b->second.lower
              << ", " << b->second.upper << "]";
            return o.str();
        }
    }
    MrDamper trial(s.twin);
    const int refused = trial.setParameterValues(index, u.values, true);
    if (refused >= 0) {
        o << "the mrDamper law refuses " << u.names[std::size_t(refused)] << " = "
          << u.values[std::size_t(refused)] << " (with the twin's other parameters)";
        return o.str();
    }
    return "";
}

TwinParameterUnit twinParameterUnit(const std::string& name)
{
    if (name == "c0" || name == "c1")
        return TwinParameterUnit::NewtonSecondPerMetre;
    if (name == "k0" || name == "k1" || name == "alpha")
        return TwinParameterUnit::NewtonPerMetre;
    if (name == "f0" || name == "fRef")
        return TwinParameterUnit::Newton;
    if (name == "uRef")
        return TwinParameterUnit::Metre;
    return TwinParameterUnit::Dimensionless;
}

double twinParameterFactor(const std::string& name, double uRef, double fRef)
{
    switch (twinParameterUnit(name)) {
    case TwinParameterUnit::NewtonSecondPerMetre:
    case TwinParameterUnit::NewtonPerMetre: return fRef / uRef;
    case TwinParameterUnit::Newton: return name == "f0" ? fRef : 1.0;
    default: return 1.0;
    }
}

DamperTwin::DamperTwin(const DamperSettings& s, double h) : m_s(s), m_law(s.twin)
{
    m_law.setTimeIncrement(h);
}

double DamperTwin::step(double drift)
{
    if (m_law.setTrialDeformation(drift) != LawStatus::Ok) {
        m_law.revert();
        return m_law.committedForce();
    }
    m_law.commit();
    return m_law.committedForce();
}

UpdateEvent DamperTwin::apply(const TwinUpdate& u, long tick, double t)
{
    const ParameterLayout names(u.names);
    if (const std::string why = checkTwinUpdate(m_s, u); !why.empty()) {
        UpdateEvent ev{int(tick), t, kTwin, names, u.values, false, u.source + ": " + why + "; nothing applied"};
        ev.decision = UpdateDecision::Refused;
        ev.proposal = u.proposal;
        return ev;
    }
    const std::vector<int> index = lawIndices(m_law, u.names);
    UpdateEvent ev = applyParameterUpdate(&m_law, kTwin, names, index, u.values, int(tick), t);
    if (ev.ok)
        ev.message = u.source;
    ev.proposal = u.proposal;
    return ev;
}

ScheduledTwinUpdates::ScheduledTwinUpdates(std::vector<TwinUpdate> updates)
{
    std::stable_sort(updates.begin(), updates.end(),
                     [](const TwinUpdate& a, const TwinUpdate& b) { return a.due < b.due; });
    m_updates.assign(updates.begin(), updates.end());
}

ScheduledTwinUpdates ScheduledTwinUpdates::fromEvents(const std::vector<UpdateEvent>& events)
{
    std::vector<TwinUpdate> out;
    for (const UpdateEvent& e : events)
        if (e.decision == UpdateDecision::Applied)
            out.push_back(TwinUpdate{e.parameters.names(), e.applied, "replay", long(e.step)});
    return ScheduledTwinUpdates(std::move(out));
}

bool ScheduledTwinUpdates::next(long k, TwinUpdate& out)
{
    if (m_updates.empty() || m_updates.front().due > k)
        return false;
    out = std::move(m_updates.front());
    m_updates.pop_front();
    return true;
}

void PostedTwinUpdates::post(TwinUpdate u)
{
    std::lock_guard lock(m_mutex);
    m_posted.push_back(std::move(u));
}

bool PostedTwinUpdates::next(long, TwinUpdate& out)
{
    std::unique_lock lock(m_mutex, std::defer_lock);
    if (m_blocking)
        lock.lock();
    else if (!lock.try_lock())
        return false;
    if (m_posted.empty())
        return false;
    out = std::move(m_posted.front());
    m_posted.pop_front();
    return true;
}

std::vector<TwinUpdate> PostedTwinUpdates::takeAll()
{
    std::lock_guard lock(m_mutex);
    std::vector<TwinUpdate> out(std::make_move_iterator(m_posted.begin()),
                                std::make_move_iterator(m_posted.end()));
    m_posted.clear();
    return out;
}

std::string describeTwinUpdate(const UpdateEvent& e)
{
    std::ostringstream o;
    o.precision(6);
    if (e.decision == UpdateDecision::Proposed || e.decision == UpdateDecision::Rejected ||
        e.decision == UpdateDecision::Superseded) {
        o << "damper twin proposal #" << e.proposal << " " << updateDecisionName(e.decision)
          << " before tick " << e.step << " (t = " << e.time << " s): " << e.message << ":";
        for (std::size_t i = 0; i < e.parameters.size() && i < e.applied.size(); ++i)
            o << (i ? ", " : " ") << e.parameters.name(i) << " = " << e.applied[i];
        return o.str();
    }
    if (!e.ok) {
        o << "damper twin update refused before tick " << e.step << " (t = " << e.time
          << " s): " << e.message;
        return o.str();
    }
    o << "damper twin updated before tick " << e.step << " (t = " << e.time << " s; "
      << e.message << "):";
    for (std::size_t i = 0; i < e.parameters.size() && i < e.applied.size(); ++i)
        o << (i ? ", " : " ") << e.parameters.name(i) << " = " << e.applied[i];
    return o.str();
}

bool TwinUpdateSources::next(long k, TwinUpdate& out)
{
    for (TwinUpdateSource* s : m_sources)
        if (s->next(k, out))
            return true;
    return false;
}

bool TwinUpdateSources::nextEvent(long k, UpdateEvent& out)
{
    for (TwinUpdateSource* s : m_sources)
        if (s->nextEvent(k, out))
            return true;
    return false;
}

void TwinUpdateSources::observe(long k, double deformation, double force)
{
    for (TwinUpdateSource* s : m_sources)
        s->observe(k, deformation, force);
}

} // namespace hsmu::rths
