#pragma once
// SiteHealthLabel: the status bar's one link label, per site (sites: docs/configuration.md),
// with a single source of truth: the test's SiteMonitor (written by the test's thread after
// every step, hold and resume). Each site is shown by its address (one site) or its name
// (several, addresses in the tool tip) with its health: "connected, 0.62 ms", "down (faults:
// 2)", "(connects at start)" before the test is prepared, e.g.
//   "link: tcp://127.0.0.1:5600 connected, 0.62 ms"
//   "link: Lab D connected, 0.62 ms | Lab C down (faults: 2)"
//   "link: built-in virtual lab"
// in the alarm colour while a site's link is down. Polls the monitor every 250 ms; the tool
// tip lists every site with its address, description, elements and last fault.
// siteHealthText() formats one site's health for the setup panel's SiteHealthView.
// Thread rules: GUI thread only (the monitor itself is thread-safe).

#include "core/experimental/SiteStatus.h"

#include <QLabel>
#include <QList>

#include <memory>

namespace hsmu::gui {

class SitePoll;

/// "0.62 ms", "down", "down (faults: 2)", "0.62 ms (faults: 1)", "-" before the first step.
QString siteHealthText(const SiteStatus& site);

class SiteHealthLabel : public QLabel {
    Q_OBJECT
public:
    /// A site of the loaded test: its name (the monitor's) and its address as the operator
    /// knows it ("tcp://127.0.0.1:5101"); builtin: the built-in virtual lab.
    struct Site {
        QString name;
        QString address;
        bool builtin = false;
        QString detail; ///< more for the tool tip (e.g. OpenFresco's sizes), may be empty
    };

    explicit SiteHealthLabel(QWidget* parent = nullptr);
    /// The loaded test's sites (empty: no test, "no link").
    void setSites(const QList<Site>& sites);
    /// The test's monitor (nullptr: none yet; every remote site "connects at start").
    void setMonitor(std::shared_ptr<const SiteMonitor> monitor);
    /// Read the monitor now (the timer does it every 250 ms).
    void refresh();

protected:
    void changeEvent(QEvent* event) override;

private:
    QList<Site> m_sites;
    SitePoll* m_poll = nullptr;
};

} // namespace hsmu::gui
