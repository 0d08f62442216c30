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
                               [&](const SiteStatus& s) { return s.name == x->siteName(); });
        if (it == sites.end()) {
            SiteStatus s;
            s.name = x->siteName();
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

void refreshSiteHealth(std::vector<SiteStatus>& sites,
                       const std::vector<ExperimentalElement*>& specimens)
{
    for (SiteStatus& s : sites) {
        s.connected = true;
        s.lastRoundTrip = std::numeric_limits<double>::quiet_NaN();
        s.faults = 0;
    }
    for (const ExperimentalElement* x : specimens) {
        auto it = std::find_if(sites.begin(), sites.end(),
                               [&](const SiteStatus& s) { return s.name == x->siteName(); });
        if (it == sites.end())
            continue;
        it->connected = it->connected && x->control().connected();
        const double rt = x->lastRoundTrip();
        if (std::isfinite(rt) && !(rt <= it->lastRoundTrip))
            it->lastRoundTrip = rt;
        it->faults += x->faults();
        if (!x->lastFault().empty() && x->faults() > 0)
            it->lastFault = x->name() + ": " + x->lastFault();
    }
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

void SiteMonitor::update(const std::vector<SiteStatus>& sites, bool holding)
{
    std::lock_guard lock(m_mutex);
    m_sites = sites;
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
