#pragma once
// SiteHealthView: the setup panel's "Sites" box (sites: docs/configuration.md): one row per
// site of the loaded configuration (name, address, the experimental elements it serves) and,
// once a test is loaded, each site's health (link up, last round trip, faults) from the
// test's SiteMonitor, refreshed every 500 ms. The site "controller" is the controller chosen
// above (the elements no site lists). Hidden when the configuration has no "sites".
// Thread rules: GUI thread only.

#include "core/config/TestConfig.h"
#include "core/experimental/SiteStatus.h"

#include <QGroupBox>

#include <memory>

class QTableWidget;

namespace hsmu::gui {

class SitePoll;

class SiteHealthView : public QGroupBox {
    Q_OBJECT
public:
    explicit SiteHealthView(QWidget* parent = nullptr);
    void setConfig(const TestConfig& cfg);
    void setMonitor(std::shared_ptr<const SiteMonitor> monitor);
    void refresh();

private:
    QTableWidget* m_table = nullptr;
    SitePoll* m_poll = nullptr;
};

} // namespace hsmu::gui
