#include "gui/app/SiteHealthLabel.h"

#include "gui/app/SitePoll.h"


#include <cmath>

namespace hsmu::gui {

QString siteHealthText(const SiteStatus& site) {
    QString text = !site.connected                  ? SiteHealthLabel::tr("down")
                   : std::isfinite(site.lastRoundTrip) ? SiteHealthLabel::tr("%1 ms").arg(
                                                           site.lastRoundTrip * 1e3, 0, 'f', 2)
                                                     : QStringLiteral("-");
    if (site.faults > 0)
        text += SiteHealthLabel::tr(" (faults: %1)").arg(site.faults);
    return text;
}

SiteHealthLabel::SiteHealthLabel(QWidget* parent) : QLabel(parent) {
    setObjectName(QStringLiteral("statusSites"));
    setFrameShape(QFrame::StyledPanel);
    setMaximumWidth(320);
    m_poll = new SitePoll(250, this);
    connect(m_poll, &SitePoll::poll, this, &SiteHealthLabel::refresh);
    hide();
}

void SiteHealthLabel::setMonitor(std::shared_ptr<const SiteMonitor> monitor) {
    m_poll->setMonitor(std::move(monitor)); // refreshes at once
}

void SiteHealthLabel::refresh() {
    const SiteMonitor* monitor = m_poll->monitor();
    const std::vector<SiteStatus> sites = monitor ? monitor->sites() : std::vector<SiteStatus>{};
    setVisible(!sites.empty());
    if (sites.empty())
        return;
    QStringList parts, tips;
    bool alarm = monitor->holding();
    for (const SiteStatus& s : sites) {
        const QString name = QString::fromStdString(s.name);
        parts << name + QLatin1Char(' ') + siteHealthText(s);
        QStringList elements;
        for (const std::string& x : s.elements)
            elements << QString::fromStdString(x);
        QString tip = tr("%1: %2 (%3) - %4")
                          .arg(name, QString::fromStdString(s.description),
                               elements.join(QStringLiteral(", ")), siteHealthText(s));
        if (!s.lastFault.empty())
            tip += QLatin1Char('\n') + tr("last fault: %1").arg(QString::fromStdString(s.lastFault));
        tips << tip;
        alarm = alarm || !s.connected;
    }
    setText(tr("sites: %1").arg(parts.join(QStringLiteral(" | "))));
    setToolTip(tips.join(QLatin1Char('\n')));
    setStyleSheet(alarm ? QStringLiteral("color: white; background: #c62828;") : QString());
}

} // namespace hsmu::gui
