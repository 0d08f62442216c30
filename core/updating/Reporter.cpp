#include "core/updating/Reporter.h"

#include "core/hysteresis/HysteresisLaw.h"
#include "core/structure/Link2dKinematics.h"
#include "core/structure/Structure.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

HysteresisLaw* reporterTargetLaw(Element* e, int basicDof)
{
    if (!e)
        return nullptr;
    if (basicDof < 0)
        return e->law();
    return basicDof < e->basicDofCount() ? e->basicLaw(basicDof) : nullptr;
}

const HysteresisLaw* reporterTargetLaw(const Element* e, int basicDof)
{
    return reporterTargetLaw(const_cast<Element*>(e), basicDof);
}

bool swapReporterTargetLaw(Element& e, int basicDof, std::unique_ptr<HysteresisLaw>& law)
{
    return basicDof < 0 ? e.swapLaw(law) : e.swapBasicLaw(basicDof, law);
}

namespace {

// Why target `t` has no law to update in `e` (null: no such element).
std::string noTargetLaw(const ReporterTarget& t, Element* e)
{
    const std::string what = "updating: target '" + t.element + "'";
    if (!e || t.basicDof < 0 || e->isExperimental())
        return what + " is not a numerical element with a law";
    const int n = e->basicDofCount();
    if (t.basicDof >= n)
        return what + ": basic DOF " + std::to_string(t.basicDof) + " is out of range: a " +
               e->typeName() + " has " + std::to_string(n) + " (0 .. " + std::to_string(n - 1) +
               ")";
    const std::string name = n == 3 ? std::string(" (") + link2dBasicDofName(t.basicDof) + ")" : "";
    return what + ": basic DOF " + std::to_string(t.basicDof) + name +
           " carries no hysteretic law (a held force or a free DOF): nothing to update";
}

} // namespace

Reporter::Reporter(std::vector<ReporterTarget> targets, ReporterPolicy policy, int everyN)
    : m_targets(std::move(targets)), m_policy(policy), m_everyN(everyN < 1 ? 1 : everyN),
      m_lastForce(m_targets.size(), 0.0),
      m_lastProposal(m_targets.size(), std::numeric_limits<double>::quiet_NaN())
{
}

void Reporter::setPolicy(ReporterPolicy p, int everyN)
{
    m_policy = p;
    m_everyN = everyN < 1 ? 1 : everyN;
}

bool Reporter::bind(Structure& structure, const ParameterLayout& identified, std::string* error)
{
    m_bound.clear();
    bool ok = true;
    for (const ReporterTarget& t : m_targets) {
        Element* e = structure.element(t.element);
        BoundTarget& b = m_bound.emplace_back();
        b.law = reporterTargetLaw(e, t.basicDof);
        if (!b.law && ok) {
            ok = false;
            if (error)
                *error = noTargetLaw(t, e);
        }
        if (b.law && ok) { // a name the target's law does not have: refused with the name
            const ParameterLayout lawNames(b.law->parameterNames());
            std::vector<std::string> named = t.parameters;
            for (const auto& [name, factor] : t.scale)
                named.push_back(name);
            for (const auto& name : named) {
                try {
                    lawNames.indexOf(name, "updating: target '" + t.element + "'");
                } catch (const std::invalid_argument& e) {
                    ok = false;
                    if (error)
                        *error = e.what();
                    break;
                }
            }
        }
        std::vector<std::string> names;
        for (const auto& name : t.parameters)
            if (identified.find(name))
                names.push_back(name);
        std::sort(names.begin(), names.end());
        names.erase(std::unique(names.begin(), names.end()), names.end());
        for (const auto& name : names) {
            auto s = t.scale.find(name);
            b.identifiedIndex.push_back(static_cast<int>(*identified.find(name)));
            b.lawIndex.push_back(b.law ? b.law->parameterIndex(name) : -1);
            b.scale.push_back(s == t.scale.end() ? 1.0 : s->second);
        }
        b.values.resize(b.identifiedIndex.size());
        b.names = ParameterLayout(std::move(names));
    }
    m_identified = identified;
    m_boundStructure = &structure;
    return ok;
}

UpdateEvent Reporter::apply(HysteresisLaw* law, const std::string& element,
                            const ParameterLayout& names, std::span<const int> lawIndex,
                            std::span<const double> values, int step, double time)
{
    UpdateEvent ev = applyParameterUpdate(law, element, names, lawIndex, values, step, time);
    if (ev.ok)
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

namespace {
constexpr double kTimeTolerance = 1e-6; // [s] test times are step x dt, within rounding
} // namespace

void Reporter::queueProposal(std::size_t i, int step, double time, std::vector<UpdateEvent>& events)
{
    BoundTarget& b = m_bound[i];
    b.offered = true;
    // One proposal per interval: the pending one stays until the interval has passed.
    if (!std::isnan(m_lastProposal[i]) &&
        time - m_lastProposal[i] < m_proposalInterval - kTimeTolerance)
        return;
    const std::string& element = m_targets[i].element;
    const auto old = std::find_if(m_pending.begin(), m_pending.end(),
                                  [&](const UpdateProposal& p) { return p.element == element; });
    if (old == m_pending.end() && static_cast<int>(m_pending.size()) >= m_maxPending) {
        ++m_notQueued;
        UpdateEvent& ev = events.emplace_back();
        ev.step = step;
        ev.time = time;
        ev.element = element;
        ev.parameters = b.names;
        ev.applied = b.values;
        ev.ok = false;
        ev.decision = UpdateDecision::NotQueued;
        ev.message = "approval queue full (" + std::to_string(m_maxPending) +
                     " proposals pending): not queued";
        return;
    }
    UpdateProposal p{m_nextId++, step, time, element, b.names, b.values, {}, m_fitError,
                     m_targets[i].basicDof};
    if (b.law)
        for (std::size_t k = 0; k < b.values.size(); ++k)
            p.current.push_back(b.lawIndex[k] >= 0 ? b.law->parameterValue(b.lawIndex[k])
                                                   : b.values[k]);
    m_lastProposal[i] = time;
    if (old == m_pending.end()) {
        m_pending.push_back(std::move(p));
        return;
    }
    // The newer estimate replaces the pending proposal in its place; the old one's fate is
    // in the record.
    UpdateEvent& ev = events.emplace_back();
    ev.step = step;
    ev.time = time;
    ev.element = element;
    ev.parameters = old->parameters;
    ev.applied = old->proposed;
    ev.ok = false;
    ev.decision = UpdateDecision::Superseded;
    ev.proposal = old->id;
    ev.message = "superseded by proposal #";
    ev.message += std::to_string(p.id); // appended: GCC 12 warns (-Wrestrict) on "..." + s
    m_superseded.emplace_back(old->id, p.id);
    if (m_superseded.size() > 256)
        m_superseded.pop_front();
    *old = std::move(p);
}

bool Reporter::stale(const UpdateProposal& p, double time, double interval)
{
    const double age = time - p.time;
    return interval > 0.0 ? age >= interval - kTimeTolerance : age > kTimeTolerance;
}

std::optional<int> Reporter::supersededBy(int id) const
{
    for (const auto& [older, newer] : m_superseded)
        if (older == id)
            return newer;
    return std::nullopt;
}

std::span<const double> Reporter::latestOffer(const std::string& element) const
{
    for (std::size_t i = 0; i < m_targets.size() && i < m_bound.size(); ++i)
        if (m_targets[i].element == element && m_bound[i].offered)
            return m_bound[i].values;
    return {};
}

int Reporter::offer(int step, double time, std::span<const double> identified,
                    Structure& structure, std::vector<UpdateEvent>& events)
{
    if (m_boundStructure != &structure)
        bind(structure, m_identified, nullptr);
    int applied = 0;
    for (std::size_t i = 0; i < m_targets.size(); ++i) {
        BoundTarget& b = m_bound[i];
        const double force = b.law ? b.law->committedForce() : 0.0;
        const bool approval = m_policy == ReporterPolicy::OnApproval;
        if (approval)
            m_lastForce[i] = force;
        else if (!dueNow(i, step, force))
            continue;
        for (std::size_t k = 0; k < b.values.size(); ++k) {
            const auto at = static_cast<std::size_t>(b.identifiedIndex[k]);
            b.values[k] = (at < identified.size() ? identified[at] : NAN) * b.scale[k];
        }
        if (approval) {
            queueProposal(i, step, time, events);
            continue;
        }
        events.push_back(apply(b.law, m_targets[i].element, b.names, b.lawIndex, b.values, step,
                               time));
        applied += events.back().ok;
    }
    return applied;
}

std::optional<UpdateEvent> Reporter::approve(int id, Structure& structure, int step, double time)
{
    for (auto it = m_pending.begin(); it != m_pending.end(); ++it) {
        if (it->id == id) {
            if (stale(*it, time))
                return std::nullopt; // an old estimate: the next offer renews it
            UpdateProposal p = std::move(*it);
            m_pending.erase(it);
            // The target as it is now, its parameters resolved by name (an operator's
            // decision, not a step: no need for the bound positions).
            Element* e = structure.element(p.element);
            HysteresisLaw* law = reporterTargetLaw(e, p.basicDof);
            std::vector<int> lawIndex;
            for (const std::string& name : p.parameters.names())
                lawIndex.push_back(law ? law->parameterIndex(name) : -1);
            UpdateEvent ev =
                apply(law, p.element, p.parameters, lawIndex, p.proposed, step, time);
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
            UpdateEvent ev{step,  time, it->element, it->parameters, it->proposed,
                           false, "rejected by the operator", UpdateDecision::Rejected, id};
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
