#pragma once
// SiteStatus: the health of one site (a lab, a controller, the built-in virtual lab) as the
// test sees it: the experimental elements it answers for, whether their links are up, the
// last step's round trip (the slowest of its elements: target sent -> measurement received)
// and the control faults so far. Sites are named by the configuration's "sites" section
// (docs/configuration.md); elements not mapped to one belong to the site "controller" (the
// front end's --controller address, or the built-in virtual lab).
// SiteMonitor: the latest statuses, written by the test's thread after every step, hold and
// resume (HybridTest), read from any thread (the console's status bar and setup panel).

#include <limits>
#include <mutex>
#include <string>
#include <vector>

namespace hsmu {

class ExperimentalElement;
class Structure;

struct SiteStatus {
    std::string name;
    std::string description;           ///< the first element's control, e.g. "TCP link tcp://..."
    std::vector<std::string> elements; ///< experimental elements served, model order
    bool connected = true;             ///< every element's link is up
    double lastRoundTrip = std::numeric_limits<double>::quiet_NaN(); ///< [s]; NaN: none yet
    int faults = 0;                    ///< control faults of its elements so far
    std::string lastFault;             ///< the latest one's text ("" if none)
};

/// The sites of a structure's experimental elements, in order of their first element.
std::vector<SiteStatus> siteStatuses(const Structure& structure);
/// The same from the experimental elements themselves (the test's cached list).
std::vector<SiteStatus> siteStatuses(const std::vector<ExperimentalElement*>& specimens);
/// Refresh the per-step fields (connected, lastRoundTrip, faults, lastFault) of sites made by
/// siteStatuses(specimens) from the same specimens, without rebuilding names, descriptions
/// and element lists (no allocation in a step without faults).
void refreshSiteHealth(std::vector<SiteStatus>& sites,
                       const std::vector<ExperimentalElement*>& specimens);
/// Just the names, same order (RunLayout::sites, the record's /sites columns).
std::vector<std::string> siteNames(const Structure& structure);

class SiteMonitor {
public:
    /// Copy-assigns (reuses the strings' storage: no allocation per step).
    void update(const std::vector<SiteStatus>& sites, bool holding);
    std::vector<SiteStatus> sites() const;
    /// Whether the test holds (a fault at any site holds every site).
    bool holding() const;

private:
    mutable std::mutex m_mutex;
    std::vector<SiteStatus> m_sites;
    bool m_holding = false;
};

} // namespace hsmu
