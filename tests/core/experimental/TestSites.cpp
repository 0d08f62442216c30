// Sites in core (docs/configuration.md "Sites"): Structure::setTrial sends every specimen's
// target before it awaits any measurement, and Structure::commit sends every commit before it
// awaits any acknowledgement; a failed send or measurement still drains the targets already
// sent; SiteStatus groups specimens by site (slowest round trip, links, faults); a
// configuration without "sites" puts every specimen on the site "controller".

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/experimental/ExperimentalElement.h"
#include "core/experimental/SiteStatus.h"
#include "core/hysteresis/LinearElastic.h"
#include "core/structure/SpringElement.h"
#include "core/structure/Structure.h"

#include <QtTest>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

using namespace hsmu;

namespace {

// Appends "set NAME", "measure NAME", "begin NAME", "commit NAME" to a shared log.
class LoggingControl final : public ExperimentalControl {
public:
    LoggingControl(std::string name, std::vector<std::string>& log, double latency)
        : m_name(std::move(name)), m_log(log), m_latency(latency) {}
    std::string description() const override { return "logging control " + m_name; }
    ControlResult prepare(double) override { return ControlResult::success(); }
    ControlResult setTarget(double d) override {
        m_log.push_back("set " + m_name);
        m_d = d;
        return failSend ? ControlResult::fault("send refused") : ControlResult::success();
    }
    ControlResult measure(ControlMeasurement& out) override {
        m_log.push_back("measure " + m_name);
        out = {m_d, 100.0 * m_d};
        return failMeasure ? ControlResult::fault("no measurement") : ControlResult::success();
    }
    ControlResult beginCommit() override {
        m_log.push_back("begin " + m_name);
        return ControlResult::success();
    }
    ControlResult commit() override {
        m_log.push_back("commit " + m_name);
        return ControlResult::success();
    }
    void hold(const std::string&) override {}
    void resume() override {}
    bool connected() const override { return up; }
    double replyLatency() const override { return m_latency; }

    bool failSend = false, failMeasure = false, up = true;

private:
    std::string m_name;
    std::vector<std::string>& m_log;
    double m_d = 0.0;
    double m_latency;
};

struct Rig {
    std::vector<std::string> log;
    Structure s;
    std::vector<LoggingControl*> controls;
    std::vector<ExperimentalElement*> specimens;

    // Three specimens on DOFs 0..2 (sites: A -> "north", B and C -> "south") and a numerical
    // spring on DOF 0; latencies 1, 2 and 5 ms.
    Rig() {
        for (int i = 0; i < 3; ++i)
            s.addDof("DOF " + std::to_string(i), 1.0);
        s.addElement(SpringElement::lateral("N", 0, std::make_unique<LinearElastic>(10.0)));
        const char* names[3] = {"A", "B", "C"};
        const double latency[3] = {1e-3, 2e-3, 5e-3};
        for (int i = 0; i < 3; ++i) {
            auto c = std::make_unique<LoggingControl>(names[i], log, latency[i]);
            controls.push_back(c.get());
            auto e = std::make_unique<ExperimentalElement>(
                names[i], "lateralSpring", std::vector<DofTerm>{{i, 1.0}}, std::move(c),
                SafetyLimits{}, 100.0);
            e->setSite(i == 0 ? "north" : "south");
            specimens.push_back(e.get());
            s.addElement(std::move(e));
        }
        s.finalize();
    }
};

} // namespace

class TestSites : public QObject {
    Q_OBJECT
private slots:
    void everyTargetIsSentBeforeAnyMeasurementIsAwaited() {
        Rig r;
        QVERIFY(r.s.setTrial(Eigen::Vector3d(0.01, 0.02, 0.03)).ok);
        const std::vector<std::string> expected{"set A",     "set B",     "set C",
                                                "measure A", "measure B", "measure C"};
        QCOMPARE(r.log, expected);
        QCOMPARE(r.specimens[2]->force(), 100.0 * 0.03);
        r.log.clear();
        QVERIFY(r.s.commit().ok);
        const std::vector<std::string> commits{"begin A",  "begin B",  "begin C",
                                               "commit A", "commit B", "commit C"};
        QCOMPARE(r.log, commits);
    }

    void aFailedSendStillDrainsTheTargetsSent() {
        Rig r;
        r.controls[1]->failSend = true;
        const ElementStatus st = r.s.setTrial(Eigen::Vector3d(0.01, 0.02, 0.03));
        QVERIFY(!st.ok);
        QVERIFY2(st.message.find("B: send refused") == 0, st.message.c_str());
        // C is never sent; A's measurement is read so its link has no reply in flight.
        const std::vector<std::string> expected{"set A", "set B", "measure A"};
        QCOMPARE(r.log, expected);
        QCOMPARE(r.specimens[0]->faults(), 0);
        QCOMPARE(r.specimens[1]->faults(), 1);
        QCOMPARE(r.specimens[1]->lastFault(), std::string("send refused"));
    }

    void aFailedMeasurementStillReadsTheOthers() {
        Rig r;
        r.controls[0]->failMeasure = true;
        const ElementStatus st = r.s.setTrial(Eigen::Vector3d(0.01, 0.02, 0.03));
        QVERIFY(!st.ok);
        QVERIFY2(st.message.find("A: no measurement") == 0, st.message.c_str());
        const std::vector<std::string> expected{"set A",     "set B",     "set C",
                                                "measure A", "measure B", "measure C"};
        QCOMPARE(r.log, expected);
    }

    void siteStatusGroupsBySite() {
        Rig r;
        QCOMPARE(siteNames(r.s), (std::vector<std::string>{"north", "south"}));
        auto sites = siteStatuses(r.s);
        QCOMPARE(sites.size(), std::size_t(2));
        QVERIFY(std::isnan(sites[0].lastRoundTrip)); // nothing measured yet
        QVERIFY(r.s.setTrial(Eigen::Vector3d(0.01, 0.02, 0.03)).ok);
        r.controls[2]->up = false;
        sites = siteStatuses(r.s);
        QCOMPARE(sites[0].name, std::string("north"));
        QCOMPARE(sites[0].elements, std::vector<std::string>{"A"});
        QCOMPARE(sites[0].lastRoundTrip, 1e-3);
        QVERIFY(sites[0].connected);
        QCOMPARE(sites[1].elements, (std::vector<std::string>{"B", "C"}));
        QCOMPARE(sites[1].lastRoundTrip, 5e-3); // the slowest of B and C
        QVERIFY(!sites[1].connected);
        QCOMPARE(sites[1].description, std::string("logging control B"));

        SiteMonitor monitor;
        monitor.update(sites, true);
        QVERIFY(monitor.holding());
        QCOMPARE(monitor.sites().size(), std::size_t(2));
    }

    void withoutSitesEverySpecimenIsOnTheControllerSite() {
        std::ifstream in(std::string(HSMU_SOURCE_DIR) +
                         "/resources/presets/paper-bridge-two-labs.json");
        nlohmann::json j = nlohmann::json::parse(in);
        j.erase("sites");
        const TestConfig cfg = parseConfig(j, "no-sites.json");
        QVERIFY(cfg.sites.empty());
        const auto s = buildStructure(cfg);
        QCOMPARE(siteNames(*s), std::vector<std::string>{kDefaultSiteName});
        // With the preset's sites (each a lab of its own) but the in-process specimens.
        const TestConfig two = parseConfig(
            nlohmann::json::parse(std::ifstream(std::string(HSMU_SOURCE_DIR) +
                                                "/resources/presets/paper-bridge-two-labs.json")),
            "two.json");
        QCOMPARE(siteNames(*buildStructure(two)), (std::vector<std::string>{"Lab C", "Lab D"}));
    }
};

QTEST_APPLESS_MAIN(TestSites)
#include "TestSites.moc"
