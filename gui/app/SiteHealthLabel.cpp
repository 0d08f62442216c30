#include "gui/app/SiteHealthLabel.h"

#include "gui/app/SitePoll.h"

#include <QEvent>

#include <algorithm>
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

namespace {
// "connected", "connected, 0.62 ms", "down (faults: 2)": the link's own words.
QString linkHealth(const SiteStatus& s) {
    QString text = !s.connected ? SiteHealthLabel::tr("down")
                   : std::isfinite(s.lastRoundTrip)
                       ? SiteHealthLabel::tr("connected, %1 ms").arg(s.lastRoundTrip * 1e3, 0, 'f', 2)
                       : SiteHealthLabel::tr("connected");
    if (s.faults > 0)
        text += SiteHealthLabel::tr(" (faults: %1)").arg(s.faults);
    return text;
}
} // namespace

SiteHealthLabel::SiteHealthLabel(QWidget* parent) : QLabel(parent) {
    setObjectName(QStringLiteral("statusLink"));
    setFrameShape(QFrame::StyledPanel);
    setMinimumWidth(160);
    setMaximumWidth(420); // long addresses: cut, in full in the tool tip
    m_poll = new SitePoll(250, this);
    connect(m_poll, &SitePoll::poll, this, &SiteHealthLabel::refresh);
    refresh();
}

void SiteHealthLabel::setSites(const QList<Site>& sites) {
    m_sites = sites;
    refresh();
}

void SiteHealthLabel::setMonitor(std::shared_ptr<const SiteMonitor> monitor) {
    m_poll->setMonitor(std::move(monitor)); // refreshes at once
}

void SiteHealthLabel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        refresh();
    QLabel::changeEvent(event);
}

void SiteHealthLabel::refresh() {
    const SiteMonitor* monitor = m_poll->monitor();
    const std::vector<SiteStatus> statuses =
        monitor ? monitor->sites() : std::vector<SiteStatus>{};
    if (m_sites.isEmpty()) {
        setText(tr("link: %1").arg(tr("no link")));
        setToolTip(text());
        setStyleSheet(QString());
        return;
    }
    QStringList parts, tips;
    bool down = false;
    const bool several = m_sites.size() > 1;
    for (const Site& site : m_sites) {
        const auto st = std::find_if(statuses.begin(), statuses.end(), [&](const SiteStatus& s) {
            return QString::fromStdString(s.name) == site.name;
        });
        const bool known = st != statuses.end();
        QString health;
        if (site.builtin)
            health = known && !st->connected ? linkHealth(*st) : QString();
        else
            health = known ? linkHealth(*st) : tr("(connects at start)");
        down = down || (known && !st->connected);
        const QString who = site.builtin ? tr("built-in virtual lab")
                                         : (several ? site.name : site.address);
        parts << (health.isEmpty() ? who : who + QLatin1Char(' ') + health);
        QString tip = site.builtin ? tr("%1: built-in virtual lab").arg(site.name)
                                   : tr("%1: %2").arg(site.name, site.address);
        if (!site.detail.isEmpty())
            tip += QLatin1Char(' ') + site.detail;
        if (known) {
            QStringList elements;
            for (const std::string& x : st->elements)
                elements << QString::fromStdString(x);
            tip += QStringLiteral(" - ") + (health.isEmpty() ? linkHealth(*st) : health) +
                   QStringLiteral(" (") + elements.join(QStringLiteral(", ")) +
                   QStringLiteral(")");
            if (!st->lastFault.empty())
                tip += QLatin1Char('\n') +
                       tr("last fault: %1").arg(QString::fromStdString(st->lastFault));
        }
        tips << tip;
    }
    setText(tr("link: %1").arg(parts.join(QStringLiteral(" | "))));
    setToolTip(tips.join(QLatin1Char('\n')));
    setStyleSheet(down ? QStringLiteral("color: white; background: #c62828;") : QString());
}

} // namespace hsmu::gui
