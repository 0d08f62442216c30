#pragma once
// SitePoll: a core SiteMonitor read on a timer, for the views of the sites' health (the
// status bar's SiteHealthLabel and the setup panel's SiteHealthView). setMonitor() keeps the
// monitor, starts (or, for nullptr, stops) the timer and polls once at once; poll() is
// emitted on every tick, the owner reads monitor() then.
// Thread rules: GUI thread only (the monitor itself is thread-safe).

#include "core/experimental/SiteStatus.h"

#include <QObject>

#include <memory>

class QTimer;

namespace hsmu::gui {

class SitePoll : public QObject {
    Q_OBJECT
public:
    /// Poll every intervalMs [ms] while a monitor is set.
    SitePoll(int intervalMs, QObject* parent);
    void setMonitor(std::shared_ptr<const SiteMonitor> monitor);
    /// The monitor polled, or nullptr.
    const SiteMonitor* monitor() const { return m_monitor.get(); }

signals:
    void poll();

private:
    std::shared_ptr<const SiteMonitor> m_monitor;
    QTimer* m_timer = nullptr;
};

} // namespace hsmu::gui
