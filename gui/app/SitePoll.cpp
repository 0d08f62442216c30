#include "gui/app/SitePoll.h"

#include <QTimer>

namespace hsmu::gui {

SitePoll::SitePoll(int intervalMs, QObject* parent) : QObject(parent) {
    m_timer = new QTimer(this);
    m_timer->setInterval(intervalMs);
    connect(m_timer, &QTimer::timeout, this, &SitePoll::poll);
}

void SitePoll::setMonitor(std::shared_ptr<const SiteMonitor> monitor) {
    m_monitor = std::move(monitor);
    if (m_monitor)
        m_timer->start();
    else
        m_timer->stop();
    emit poll();
}

} // namespace hsmu::gui
