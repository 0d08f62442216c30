#include "core/updating/TwinProposals.h"

#include <algorithm>
#include <utility>

namespace hsmu::rths {

namespace {
const char* kTwin = "damper twin";

/// "proposal #ID" + rest (appended: GCC 12 warns, -Wrestrict, on "..." + std::string).
std::string proposal(int id, const std::string& rest = {})
{
    std::string s = "proposal #";
    s += std::to_string(id);
    s += rest;
    return s;
}
} // namespace

TwinProposals::TwinProposals(TwinUpdateSource& offers, const DamperSettings& damper, double rate, bool blocking)
    : m_offers(offers), m_damper(damper), m_h(1.0 / rate), m_blocking(blocking)
{
}

UpdateEvent TwinProposals::event(const UpdateProposal& p, UpdateDecision d, const std::string& message) const
{
    UpdateEvent e{p.step, p.time, kTwin, p.parameters, p.proposed, false, message, d, p.id};
    return e;
}

bool TwinProposals::next(long k, TwinUpdate& out)
{
    std::unique_lock lock(m_mutex, std::defer_lock);
    if (m_blocking)
        lock.lock();
    else if (!lock.try_lock())
        return false;
    // The offers due now become proposals; each supersedes the one pending (one per target).
    for (TwinUpdate u; m_offers.next(k, u);) {
        UpdateProposal p{m_nextId++, int(k), double(k) * m_h, kTwin, ParameterLayout(u.names), u.values, {},
                         std::numeric_limits<double>::quiet_NaN(), -1};
        if (!m_pending.empty()) {
            const UpdateProposal& old = m_pending.front();
            std::string why = "superseded by ";
            why += proposal(p.id);
            m_events.push_back(event(old, UpdateDecision::Superseded, why));
            m_superseded.emplace_back(old.id, p.id);
            m_pending.clear();
        }
        m_events.push_back(event(p, UpdateDecision::Proposed, u.source + ", waiting for the operator"));
        m_pending.push_back(std::move(p));
    }
    if (m_approved.empty())
        return false;
    out = std::move(m_approved.front());
    m_approved.pop_front();
    return true;
}

bool TwinProposals::nextEvent(long k, UpdateEvent& out)
{
    std::unique_lock lock(m_mutex, std::defer_lock);
    if (m_blocking)
        lock.lock();
    else if (!lock.try_lock())
        return false;
    if (m_events.empty())
        return false;
    out = std::move(m_events.front());
    m_events.pop_front();
    out.step = int(k); // decided before this tick (a proposal's own tick is its step already)
    out.time = double(k) * m_h;
    return true;
}

std::string TwinProposals::notPending(int id) const
{
    for (const auto& [older, newer] : m_superseded)
        if (older == id)
            return proposal(id, " was superseded by ") + proposal(newer);
    std::string none = "no pending ";
    none += proposal(id);
    return none;
}

std::string TwinProposals::approve(int id)
{
    std::lock_guard lock(m_mutex);
    const auto it = std::find_if(m_pending.begin(), m_pending.end(), [id](const UpdateProposal& p) { return p.id == id; });
    if (it == m_pending.end())
        return notPending(id);
    UpdateProposal p = std::move(*it);
    m_pending.erase(it);
    std::string source = "approved ";
    source += proposal(id);
    TwinUpdate u{p.parameters.names(), p.proposed, source, 0, id};
    if (const std::string why = checkTwinUpdate(m_damper, u); !why.empty()) {
        const std::string message = source + " refused: " + why + "; nothing applied";
        m_events.push_back(event(p, UpdateDecision::Refused, message));
        return message;
    }
    m_approved.push_back(std::move(u));
    return "";
}

std::string TwinProposals::reject(int id)
{
    std::lock_guard lock(m_mutex);
    const auto it = std::find_if(m_pending.begin(), m_pending.end(), [id](const UpdateProposal& p) { return p.id == id; });
    if (it == m_pending.end())
        return notPending(id);
    m_events.push_back(event(*it, UpdateDecision::Rejected, "rejected by the operator"));
    m_pending.erase(it);
    return "";
}

std::vector<UpdateProposal> TwinProposals::pending() const
{
    std::lock_guard lock(m_mutex);
    return {m_pending.begin(), m_pending.end()};
}

} // namespace hsmu::rths
