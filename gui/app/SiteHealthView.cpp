#include "gui/app/SiteHealthView.h"

#include "gui/app/LiveText.h"
#include "gui/app/SitePoll.h"

#include "gui/app/SiteHealthLabel.h"

#include <QHeaderView>
#include <QTableWidget>
#include <QVBoxLayout>

namespace hsmu::gui {

namespace {
constexpr int kDefaultSiteRole = Qt::UserRole; // on the address of the row without a site
} // namespace

SiteHealthView::SiteHealthView(QWidget* parent) : QGroupBox(parent) {
    setObjectName(QStringLiteral("sitesBox"));
    auto* layout = new QVBoxLayout(this);
    m_table = new QTableWidget(0, 4, this);
    m_table->setObjectName(QStringLiteral("sitesTable"));
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    // The address whole: two labs on one host differ only in the port ("tcp://127.0.0.1:51..."
    // hid it); the other columns share the rest.
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setMaximumHeight(130);
    // Were an address ever cut, it keeps its port ("tcp://...:5101").
    m_table->setTextElideMode(Qt::ElideMiddle);
    layout->addWidget(m_table);
    m_poll = new SitePoll(500, this);
    connect(m_poll, &SitePoll::poll, this, &SiteHealthView::refresh);
    hide();
    LiveText::bind(this, [this] {
        setTitle(tr("Sites"));
        m_table->setHorizontalHeaderLabels(
            {tr("Site"), tr("Address"), tr("Specimens"), tr("Health")});
        for (int row = 0; row < m_table->rowCount(); ++row)
            if (m_table->item(row, 1)->data(kDefaultSiteRole).toBool())
                m_table->item(row, 1)->setText(tr("the controller above"));
    });
}

void SiteHealthView::setConfig(const TestConfig& cfg) {
    m_table->setRowCount(0);
    auto addRow = [this](const QString& name, const QString& address, const QString& elements) {
        const int row = m_table->rowCount();
        m_table->insertRow(row);
        m_table->setItem(row, 0, new QTableWidgetItem(name));
        m_table->setItem(row, 1, new QTableWidgetItem(address));
        m_table->item(row, 1)->setToolTip(address);
        m_table->setItem(row, 2, new QTableWidgetItem(elements));
        m_table->setItem(row, 3, new QTableWidgetItem(QStringLiteral("-")));
    };
    for (const SiteSpec& s : cfg.sites) {
        QStringList names;
        for (const std::string& e : s.elements)
            names << QString::fromStdString(e);
        addRow(QString::fromStdString(s.name), QString::fromStdString(s.address),
               names.join(QStringLiteral(", ")));
    }
    QStringList rest;
    for (const ElementSpec& e : cfg.elements)
        if (e.experimental && e.site.empty())
            rest << QString::fromStdString(e.name);
    if (!cfg.sites.empty() && !rest.isEmpty())
        addRow(QString::fromLatin1(kDefaultSiteName), tr("the controller above"),
               rest.join(QStringLiteral(", ")));
    if (!cfg.sites.empty() && !rest.isEmpty())
        m_table->item(m_table->rowCount() - 1, 1)->setData(kDefaultSiteRole, true);
    setVisible(!cfg.sites.empty());
    refresh();
}

void SiteHealthView::setMonitor(std::shared_ptr<const SiteMonitor> monitor) {
    m_poll->setMonitor(std::move(monitor)); // refreshes at once
}

void SiteHealthView::refresh() {
    const SiteMonitor* monitor = m_poll->monitor();
    if (!monitor)
        return;
    for (const SiteStatus& s : monitor->sites()) {
        const QString name = QString::fromStdString(s.name);
        for (int row = 0; row < m_table->rowCount(); ++row) {
            if (m_table->item(row, 0)->text() != name)
                continue;
            QTableWidgetItem* item = m_table->item(row, 3);
            item->setText(siteHealthText(s));
            item->setToolTip(QString::fromStdString(s.lastFault));
            item->setForeground(s.connected ? palette().text().color() : QColor(0xc6, 0x28, 0x28));
        }
    }
}

} // namespace hsmu::gui
