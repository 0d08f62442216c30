#include "core/experimental/SiteStatus.h"

#include "core/experimental/ExperimentalElement.h"
#include "core/structure/Structure.h"

#include <algorithm>
#include <cmath>

namespace hsmu {

std::vector<SiteStatus> siteStatuses(const Structure& structure)
{
    std::vector<ExperimentalElement*> specimens;
    for (const auto& e : structure.elements())
        if (auto* x = dynamic_cast<ExperimentalElement*>(e.get()))
            specimens.push_back(x);
    return siteStatuses(specimens);
}

std::vector<SiteStatus> siteStatuses(const std::vector<ExperimentalElement*>& specimens)
{
    std::vector<SiteStatus> sites;
    for (const ExperimentalElement* x : specimens) {
        auto it = std::find_if(sites.begin(), sites.end(),
                               [&](const SiteStatus& s) { return s.name == x->site(); });
        if (it == sites.end()) {
            SiteStatus s;
            s.name = x->site();
            s.description = x->control().description();
            sites.push_back(std::move(s));
            it = sites.end() - 1;
        }
        it->elements.push_back(x->name());
        it->connected = it->connected && x->control().connected();
        const double rt = x->lastRoundTrip();
        if (std::isfinite(rt) && !(rt <= it->lastRoundTrip)) // NaN or smaller: take rt
            it->lastRoundTrip = rt;
        it->faults += x->faults();
        if (!x->lastFault().empty())
            it->lastFault = x->name() + ": " + x->lastFault();
    }
    return sites;
}

std::vector<std::string> siteNames(const Structure& structure)
{
    std::vector<std::string> names;
    for (const auto& e : structure.elements())
        if (e->isExperimental() &&
            std::find(names.begin(), names.end(), e->site()) == names.end())
            names.push_back(e->site());
    return names;
}

void SiteMonitor::update(std::vector<SiteStatus> sites, bool holding)
{
    std::lock_guard lock(m_mutex);
    m_sites = std::move(sites);
    m_holding = holding;
}

std::vector<SiteStatus> SiteMonitor::sites() const
{
    std::lock_guard lock(m_mutex);
    return m_sites;
}

bool SiteMonitor::holding() const
{
    std::lock_guard lock(m_mutex);
    return m_holding;
}

} // namespace hsmu
