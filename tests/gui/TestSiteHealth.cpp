// The console's per-site health (sites: docs/configuration.md): the status bar's link label
// (SiteHealthLabel) reads a SiteMonitor (each site's address or name, connected with its
// round trip in ms, down, faults, the alarm colour while a link is down); the setup panel's SiteHealthView lists
// the configuration's sites (address, specimens, the default site for unlisted specimens) and
// fills each site's health from the monitor. Offscreen.

#include "core/config/ConfigLoader.h"
#include "gui/app/SiteHealthLabel.h"
#include "gui/app/SiteHealthView.h"

#include <QTableWidget>
#include <QtTest>

#include <fstream>

using namespace hsmu;
using namespace hsmu::gui;

namespace {

SiteStatus site(const std::string& name, bool connected, double roundTrip, int faults) {
    SiteStatus s;
    s.name = name;
    s.description = "TCP link to " + name;
    s.elements = {"Bearing " + name.substr(name.size() - 1)};
    s.connected = connected;
    s.lastRoundTrip = roundTrip;
    s.faults = faults;
    if (faults > 0)
        s.lastFault = s.elements[0] + ": link lost";
    return s;
}

nlohmann::json twoLabs() {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) +
                     "/resources/presets/paper-bridge-two-labs.json");
    return nlohmann::json::parse(in);
}

} // namespace

class TestSiteHealth : public QObject {
    Q_OBJECT
private slots:
    // The status bar's one link label (issue 25 item 1): every site of the test from the
    // monitor, by address (one site) or name (several), "(connects at start)" before any
    // state, red while one is down.
    void statusBarLabelShowsEverySite() {
        auto monitor = std::make_shared<SiteMonitor>();
        SiteHealthLabel label;
        QCOMPARE(label.text(), QStringLiteral("link: no link"));
        label.setSites({{QStringLiteral("Lab C"), QStringLiteral("tcp://127.0.0.1:5102"), false, {}},
                        {QStringLiteral("Lab D"), QStringLiteral("tcp://127.0.0.1:5101"), false, {}}});
        QCOMPARE(label.text(),
                 QStringLiteral("link: Lab C (connects at start) | Lab D (connects at start)"));
        monitor->update({site("Lab C", true, 0.62e-3, 0), site("Lab D", true, 1.5e-3, 0)}, false);
        label.setMonitor(monitor);
        QCOMPARE(label.text(),
                 QStringLiteral("link: Lab C connected, 0.62 ms | Lab D connected, 1.50 ms"));
        QVERIFY(label.styleSheet().isEmpty());
        QVERIFY2(label.toolTip().contains(QStringLiteral("Lab D: tcp://127.0.0.1:5101")) &&
                     label.toolTip().contains(QStringLiteral("Bearing D")),
                 qPrintable(label.toolTip()));

        monitor->update({site("Lab C", false, 0.62e-3, 1), site("Lab D", true, 1.5e-3, 0)}, true);
        label.refresh();
        QCOMPARE(label.text(),
                 QStringLiteral("link: Lab C down (faults: 1) | Lab D connected, 1.50 ms"));
        QVERIFY(label.styleSheet().contains(QStringLiteral("#c62828")));
        QVERIFY(label.toolTip().contains(QStringLiteral("last fault: Bearing C: link lost")));

        // One site: its address; the built-in virtual lab by name.
        label.setSites({{QStringLiteral("controller"), QStringLiteral("tcp://127.0.0.1:5600"), false, {}}});
        monitor->update({site("controller", true, 1e-3, 0)}, false);
        label.refresh();
        QCOMPARE(label.text(), QStringLiteral("link: tcp://127.0.0.1:5600 connected, 1.00 ms"));
        QVERIFY(label.styleSheet().isEmpty());
        label.setSites({{QStringLiteral("controller"), QStringLiteral("builtin"), true, {}}});
        QCOMPARE(label.text(), QStringLiteral("link: built-in virtual lab"));

        SiteStatus fresh = site("Lab C", true, std::nan(""), 0);
        QCOMPARE(siteHealthText(fresh), QStringLiteral("-"));
    }

    void setupPanelListsTheConfiguredSites() {
        nlohmann::json j = twoLabs();
        // Bearing C on no site: it goes to the default site "controller".
        j["sites"].erase(1);
        const TestConfig cfg = parseConfig(j, "two-labs.json");
        SiteHealthView view;
        view.setConfig(cfg);
        QVERIFY(!view.isHidden());
        auto* table = view.findChild<QTableWidget*>(QStringLiteral("sitesTable"));
        QVERIFY(table);
        QCOMPARE(table->rowCount(), 2);
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("Lab D"));
        QCOMPARE(table->item(0, 1)->text(), QStringLiteral("tcp://127.0.0.1:5101"));
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("Bearing D"));
        QCOMPARE(table->item(1, 0)->text(), QStringLiteral("controller"));
        QCOMPARE(table->item(1, 2)->text(), QStringLiteral("Bearing C"));
        QCOMPARE(table->item(0, 3)->text(), QStringLiteral("-"));

        auto monitor = std::make_shared<SiteMonitor>();
        SiteStatus d = site("Lab D", true, 2.25e-3, 0), c = site("controller", false, 1e-3, 2);
        monitor->update({c, d}, true);
        view.setMonitor(monitor);
        QCOMPARE(table->item(0, 3)->text(), QStringLiteral("2.25 ms"));
        QCOMPARE(table->item(1, 3)->text(), QStringLiteral("down (faults: 2)"));

        // Without sites the box is hidden (one site: the controller above).
        nlohmann::json plain = twoLabs();
        plain.erase("sites");
        view.setConfig(parseConfig(plain, "plain.json"));
        QVERIFY(view.isHidden());
        QCOMPARE(table->rowCount(), 0);
    }
};

QTEST_MAIN(TestSiteHealth)
#include "TestSiteHealth.moc"
