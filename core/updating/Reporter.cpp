#include "core/updating/Reporter.h"

#include "core/hysteresis/HysteresisLaw.h"
#include "core/structure/Structure.h"

#include <algorithm>
#include <cmath>

namespace hsmu {

const char* reporterPolicyName(ReporterPolicy p)
{
    switch (p) {
    case ReporterPolicy::EveryStep: return "everyStep";
    case ReporterPolicy::ZeroCrossing: return "zeroCrossing";
    case ReporterPolicy::EveryNSteps: return "everyNSteps";
    case ReporterPolicy::OnApproval: return "onApproval";
    }
    return "?";
}

std::optional<ReporterPolicy> parseReporterPolicy(const std::string& text)
{
    for (ReporterPolicy p : {ReporterPolicy::EveryStep, ReporterPolicy::ZeroCrossing,
                             ReporterPolicy::EveryNSteps, ReporterPolicy::OnApproval})
        if (text == reporterPolicyName(p))
            return p;
    return std::nullopt;
}

const char* updateDecisionName(UpdateDecision d)
{
    switch (d) {
    case UpdateDecision::Applied: return "applied";
    case UpdateDecision::Refused: return "refused";
    case UpdateDecision::Rejected: return "rejected";
    case UpdateDecision::NotQueued: return "notQueued";
    }
    return "?";
}

Reporter::Reporter(std::vector<ReporterTarget> targets, ReporterPolicy policy, int everyN)
    : m_targets(std::move(targets)), m_policy(policy), m_everyN(everyN < 1 ? 1 : everyN),
      m_lastForce(m_targets.size(), 0.0)
{
}

void Reporter::setPolicy(ReporterPolicy p, int everyN)
{
    m_policy = p;
    m_everyN = everyN < 1 ? 1 : everyN;
}

ParameterValues Reporter::proposalFor(const ReporterTarget& t,
                                      const ParameterValues& identified) const
{
    ParameterValues out;
    for (const auto& name : t.parameters) {
        auto it = identified.find(name);
        if (it == identified.end())
            continue;
        auto s = t.scale.find(name);
        out[name] = it->second * (s == t.scale.end() ? 1.0 : s->second);
    }
    return out;
}

UpdateEvent Reporter::apply(const std::string& element, const ParameterValues& values,
                            Structure& structure, int step, double time)
{
    UpdateEvent ev{step, time, element, values, true, {}};
    Element* e = structure.element(element);
    HysteresisLaw* law = e ? e->law() : nullptr;
    if (!law) {
        ev.ok = false;
        ev.decision = UpdateDecision::Refused;
        ev.message = "no numerical element '" + element + "' with a law to update";
        return ev;
    }
    for (const auto& [name, v] : values) {
        if (!std::isfinite(v)) {
            ev.ok = false;
            ev.decision = UpdateDecision::Refused;
            ev.message = element + ": identified " + name + " is not finite; nothing applied";
            return ev;
        }
    }
    // All or nothing: keep the old values to restore if the law refuses one.
    ParameterValues old;
    for (const auto& [name, v] : values)
        old[name] = law->parameter(name).value_or(v);
    for (const auto& [name, v] : values) {
        if (!law->setParameter(name, v)) {
            for (const auto& [n, o] : old)
                law->setParameter(n, o);
            ev.ok = false;
            ev.decision = UpdateDecision::Refused;
            ev.message = element + ": the law refused " + name + " = " + std::to_string(v);
            return ev;
        }
    }
    ++m_applied;
    return ev;
}

bool Reporter::dueNow(std::size_t i, int step, double force)
{
    const double previous = m_lastForce[i];
    m_lastForce[i] = force;
    switch (m_policy) {
    case ReporterPolicy::EveryStep: return true;
    case ReporterPolicy::ZeroCrossing:
        return (previous < 0.0 && force >= 0.0) || (previous > 0.0 && force <= 0.0);
    case ReporterPolicy::EveryNSteps: return step % m_everyN == 0;
    case ReporterPolicy::OnApproval: return false;
    }
    return false;
}

void Reporter::queueProposal(const ReporterTarget& t, int step, double time,
                             const ParameterValues& identified, const HysteresisLaw* law,
                             std::vector<UpdateEvent>& events)
{
    if (static_cast<int>(m_pending.size()) >= m_maxPending) {
        ++m_notQueued;
        UpdateEvent& ev = events.emplace_back();
        ev.step = step;
        ev.time = time;
        ev.element = t.element;
        ev.applied = proposalFor(t, identified);
        ev.ok = false;
        ev.decision = UpdateDecision::NotQueued;
        ev.message = "approval queue full (" + std::to_string(m_maxPending) +
                     " proposals pending): not queued";
        return;
    }
    UpdateProposal p{m_nextId++, step, time, t.element, proposalFor(t, identified), {}, m_fitError};
    if (law)
        for (const auto& [name, v] : p.proposed)
            p.current[name] = law->parameter(name).value_or(v);
    m_pending.push_back(std::move(p));
}

std::vector<UpdateEvent> Reporter::offer(int step, double time, const ParameterValues& identified,
                                         Structure& structure)
{
    std::vector<UpdateEvent> events;
    for (std::size_t i = 0; i < m_targets.size(); ++i) {
        const ReporterTarget& t = m_targets[i];
        Element* e = structure.element(t.element);
        const double force = e && e->law() ? e->law()->committedForce() : 0.0;
        if (m_policy == ReporterPolicy::OnApproval) {
            m_lastForce[i] = force;
            queueProposal(t, step, time, identified, e ? e->law() : nullptr, events);
        } else if (dueNow(i, step, force)) {
            events.push_back(apply(t.element, proposalFor(t, identified), structure, step, time));
        }
    }
    return events;
}

bool Reporter::bind(Structure& structure, const std::vector<std::string>& identifiedNames,
                    std::string* error)
{
    m_boundStructure = nullptr;
    m_bound.clear();
    for (const ReporterTarget& t : m_targets) {
        Element* e = structure.element(t.element);
        BoundTarget b;
        b.law = e ? e->law() : nullptr;
        if (!b.law) {
            m_bound.clear();
            if (error)
                *error = "updating: target '" + t.element + "' is not a numerical element with a law";
            return false;
        }
        // The names proposalFor() keeps, in its map's order (the order apply() sets them in).
        std::vector<std::string> names;
        for (const auto& name : t.parameters)
            if (std::find(identifiedNames.begin(), identifiedNames.end(), name) !=
                identifiedNames.end())
                names.push_back(name);
        std::sort(names.begin(), names.end());
        names.erase(std::unique(names.begin(), names.end()), names.end());
        for (const auto& name : names) {
            const auto at = std::find(identifiedNames.begin(), identifiedNames.end(), name);
            auto s = t.scale.find(name);
            b.identifiedIndex.push_back(static_cast<int>(at - identifiedNames.begin()));
            b.lawIndex.push_back(b.law->parameterIndex(name));
            b.scale.push_back(s == t.scale.end() ? 1.0 : s->second);
        }
        b.values.resize(b.identifiedIndex.size());
        b.names = std::move(names);
        m_bound.push_back(std::move(b));
    }
    m_boundNames = identifiedNames;
    m_boundStructure = &structure;
    return true;
}

ParameterValues Reporter::identifiedMap(std::span<const double> identified) const
{
    ParameterValues out;
    for (std::size_t k = 0; k < m_boundNames.size() && k < identified.size(); ++k)
        out[m_boundNames[k]] = identified[k];
    return out;
}

int Reporter::offerValues(int step, double time, std::span<const double> identified,
                          Structure& structure, std::vector<UpdateEvent>& events)
{
    if (m_boundStructure != &structure || m_bound.size() != m_targets.size() ||
        identified.size() != m_boundNames.size()) {
        int applied = 0;
        for (UpdateEvent& ev : offer(step, time, identifiedMap(identified), structure)) {
            applied += ev.ok;
            events.push_back(std::move(ev));
        }
        return applied;
    }
    int applied = 0;
    for (std::size_t i = 0; i < m_targets.size(); ++i) {
        BoundTarget& b = m_bound[i];
        const double force = b.law->committedForce();
        if (m_policy == ReporterPolicy::OnApproval) {
            m_lastForce[i] = force;
            queueProposal(m_targets[i], step, time, identifiedMap(identified), b.law, events);
            continue;
        }
        if (!dueNow(i, step, force))
            continue;
        bool finite = true;
        for (std::size_t k = 0; k < b.values.size(); ++k) {
            b.values[k] = identified[static_cast<std::size_t>(b.identifiedIndex[k])] * b.scale[k];
            finite = finite && std::isfinite(b.values[k]);
        }
        const int refusedAt = finite ? b.law->setParameterValues(b.lawIndex, b.values, true) : 0;
        if (finite && refusedAt < 0) {
            ++m_applied;
            ++applied;
            // The record's event row, equal to what offer() returns (proposalFor's values).
            UpdateEvent& ev = events.emplace_back();
            ev.step = step;
            ev.time = time;
            ev.element = m_targets[i].element;
            for (std::size_t k = 0; k < b.values.size(); ++k)
                ev.applied.emplace_hint(ev.applied.end(), b.names[k], b.values[k]);
            continue;
        }
        // The rare path: let apply() say why (it repeats the checks and leaves the law as is).
        UpdateEvent ev = apply(m_targets[i].element, proposalFor(m_targets[i], identifiedMap(identified)),
                               structure, step, time);
        applied += ev.ok;
        events.push_back(std::move(ev));
    }
    return applied;
}

std::optional<UpdateEvent> Reporter::approve(int id, Structure& structure, int step, double time)
{
    for (auto it = m_pending.begin(); it != m_pending.end(); ++it) {
        if (it->id == id) {
            UpdateProposal p = *it;
            m_pending.erase(it);
            UpdateEvent ev = apply(p.element, p.proposed, structure, step, time);
            ev.proposal = p.id;
            return ev;
        }
    }
    return std::nullopt;
}

bool Reporter::reject(int id)
{
    return rejectProposal(id, 0, 0.0).has_value();
}

std::optional<UpdateEvent> Reporter::rejectProposal(int id, int step, double time)
{
    for (auto it = m_pending.begin(); it != m_pending.end(); ++it) {
        if (it->id == id) {
            UpdateEvent ev{step, time, it->element, it->proposed, false, "rejected by the operator",
                           UpdateDecision::Rejected, id};
            m_pending.erase(it);
            return ev;
        }
    }
    return std::nullopt;
}

std::vector<UpdateEvent> Reporter::resolveAll(bool approveAll, Structure& structure, int step,
                                              double time)
{
    std::vector<UpdateEvent> events;
    while (!m_pending.empty()) {
        const int id = m_pending.front().id;
        if (approveAll)
            events.push_back(*approve(id, structure, step, time));
        else
            events.push_back(*rejectProposal(id, step, time));
    }
    return events;
}

} // namespace hsmu
