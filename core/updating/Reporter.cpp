#include "core/updating/Reporter.h"

#include "core/hysteresis/HysteresisLaw.h"
#include "core/structure/Structure.h"

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
        ev.message = "no numerical element '" + element + "' with a law to update";
        return ev;
    }
    for (const auto& [name, v] : values) {
        if (!std::isfinite(v)) {
            ev.ok = false;
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
            ev.message = element + ": the law refused " + name + " = " + std::to_string(v);
            return ev;
        }
    }
    ++m_applied;
    return ev;
}

std::vector<UpdateEvent> Reporter::offer(int step, double time, const ParameterValues& identified,
                                         Structure& structure)
{
    std::vector<UpdateEvent> events;
    for (std::size_t i = 0; i < m_targets.size(); ++i) {
        const ReporterTarget& t = m_targets[i];
        Element* e = structure.element(t.element);
        const double force = e && e->law() ? e->law()->committedForce() : 0.0;
        const double previous = m_lastForce[i];
        m_lastForce[i] = force;
        bool now = false;
        switch (m_policy) {
        case ReporterPolicy::EveryStep: now = true; break;
        case ReporterPolicy::ZeroCrossing:
            now = (previous < 0.0 && force >= 0.0) || (previous > 0.0 && force <= 0.0);
            break;
        case ReporterPolicy::EveryNSteps: now = step % m_everyN == 0; break;
        case ReporterPolicy::OnApproval: {
            UpdateProposal p{m_nextId++, step, time, t.element, proposalFor(t, identified), {}};
            if (e && e->law())
                for (const auto& [name, v] : p.proposed)
                    p.current[name] = e->law()->parameter(name).value_or(v);
            for (auto it = m_pending.begin(); it != m_pending.end();)
                it = it->element == t.element ? m_pending.erase(it) : it + 1;
            m_pending.push_back(std::move(p));
            break;
        }
        }
        if (now)
            events.push_back(apply(t.element, proposalFor(t, identified), structure, step, time));
    }
    return events;
}

std::optional<UpdateEvent> Reporter::approve(int id, Structure& structure, int step, double time)
{
    for (auto it = m_pending.begin(); it != m_pending.end(); ++it) {
        if (it->id == id) {
            UpdateProposal p = *it;
            m_pending.erase(it);
            return apply(p.element, p.proposed, structure, step, time);
        }
    }
    return std::nullopt;
}

bool Reporter::reject(int id)
{
    for (auto it = m_pending.begin(); it != m_pending.end(); ++it) {
        if (it->id == id) {
            m_pending.erase(it);
            return true;
        }
    }
    return false;
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
            reject(id);
    }
    return events;
}

} // namespace hsmu
