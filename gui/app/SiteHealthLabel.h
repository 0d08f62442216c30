#pragma once
// SiteHealthLabel: the status bar's per-site health (sites: docs/configuration.md), e.g.
// "sites: Lab C 0.62 ms | Lab D down (faults: 2)", in the alarm colour when a site's link is
// down or the test holds. Polls a core SiteMonitor (written by the test's thread) every
// 250 ms; the tool tip lists every site with its description, elements and last fault.
// siteHealthText() formats one site for this label and the setup panel's SiteHealthView.
// Thread rules: GUI thread only (the monitor itself is thread-safe).

#include "core/experimental/SiteStatus.h"

#include <QLabel>

#include <memory>


namespace hsmu::gui {

class SitePoll;

/// "0.62 ms", "down", "down (faults: 2)", "0.62 ms (faults: 1)", "-" before the first step.
QString siteHealthText(const SiteStatus& site);

class SiteHealthLabel : public QLabel {
    Q_OBJECT
public:
    explicit SiteHealthLabel(QWidget* parent = nullptr);
    /// nullptr: nothing to show (hidden).
    void setMonitor(std::shared_ptr<const SiteMonitor> monitor);
    /// Read the monitor now (the timer does it every 250 ms).
    void refresh();

private:
    SitePoll* m_poll = nullptr;
};

} // namespace hsmu::gui
