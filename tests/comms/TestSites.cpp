// Sites (docs/configuration.md "Sites"): the paper-bridge-two-labs preset with bearings D and C
// on two real hsmu-controller processes (TCP, fast pace), A and B numerical and updated from D.
//   - the run over the two sites equals the single-process (virtual) run to 1e-9, every step
//     once, with a round trip per site and step;
//   - killing one site's controller (SIGKILL) holds both sites (the other controller logs the
//     console's hold); restarting it with its state file resumes both, and the test completes
//     with every step recorded once and the uninterrupted run's result;
//   - a site in process (builtin) and an OpenFresco SimApp site in one test, same result;
//   - the configuration's site mapping is checked (names, elements, addresses).
#include "comms/link/ControlFactory.h"
#include "core/config/ConfigLoader.h"
#include "core/config/JsonCursor.h"

#include "ControllerProcess.h"
#include "LinkFixture.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <fstream>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;

namespace {

TcpControlOptions patientOptions() {
    TcpControlOptions o; // generous: a loaded 2-core CI machine
    o.connectTimeout = 20.0;
    o.stepDeadline = 30.0;
    o.silenceTimeout = 30.0;
    o.reconnectAttempts = 5;
    o.reconnectDelay = 0.2;
    return o;
}

nlohmann::json twoLabs(double duration) {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) +
                     "/resources/presets/paper-bridge-two-labs.json");
    nlohmann::json j = nlohmann::json::parse(in);
    j["analysis"]["duration"] = duration;
    return j;
}

/// The configuration with its sites pointed at the two controllers' ports.
TestConfig withPorts(nlohmann::json j, quint16 portD, quint16 portC, const std::string& path) {
    for (auto& site : j["sites"]) {
        const bool d = site["name"] == "Lab D";
        site["address"] = "tcp://127.0.0.1:" + std::to_string(d ? portD : portC);
    }
    std::ofstream(path) << j.dump(2);
    return loadConfigFile(path);
}

} // namespace

class TestSites : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::string m_config; // what both controllers serve (both specimens; each console uses one)
    Run m_reference;      // the single-process run

    QStringList controllerArgs(const QString& state = {}) const {
        QStringList a{"--config", QString::fromStdString(m_config), "--pace", "fast"};
        if (!state.isEmpty())
            a << "--state" << state;
        return a;
    }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_config = writeConfig(m_dir.path(), "two-labs.json", twoLabs(1.5));
        m_reference = runTest(loadConfigFile(m_config), {});
        QCOMPARE(m_reference.state, HybridTest::State::Finished);
        QCOMPARE(m_reference.records.size(), std::size_t(301));
    }

    void presetMapsTwoSites() {
        const TestConfig cfg = loadConfigFile(m_config);
        QCOMPARE(cfg.sites.size(), std::size_t(2));
        QCOMPARE(cfg.sites[0].name, std::string("Lab D"));
        QCOMPARE(cfg.sites[0].elements, std::vector<std::string>{"Bearing D"});
        QCOMPARE(cfg.sites[1].elements, std::vector<std::string>{"Bearing C"});
        int experimental = 0;
        for (const ElementSpec& e : cfg.elements) {
            if (!e.experimental)
                continue;
            ++experimental;
            QCOMPARE(e.site, e.name == "Bearing D" ? std::string("Lab D") : std::string("Lab C"));
        }
        QCOMPARE(experimental, 2);
        QCOMPARE(cfg.updating.targets.size(), std::size_t(2)); // A and B
    }

    void badSitesAreRefusedNamingTheField() {
        const auto refused = [this](const std::function<void(nlohmann::json&)>& edit,
                                    const char* expected) {
            nlohmann::json j = twoLabs(1.0);
            edit(j);
            try {
                parseConfig(j, "bad.json");
            } catch (const ConfigError& e) {
                return QString(e.what()).contains(expected);
            }
            return false;
        };
        QVERIFY(refused([](auto& j) { j["sites"][1]["elements"] = {"Bearing D"}; },
                        "already served by site 'Lab D'"));
        QVERIFY(refused([](auto& j) { j["sites"][1]["elements"] = {"Bearing A"}; },
                        "'Bearing A' is numerical"));
        QVERIFY(refused([](auto& j) { j["sites"][1]["elements"] = {"Bearing Z"}; },
                        "no element named 'Bearing Z'"));
        QVERIFY(refused([](auto& j) { j["sites"][1]["name"] = "Lab D"; }, "two sites are named"));
        QVERIFY(refused([](auto& j) { j["sites"][1]["address"] = "lab-c:5102"; }, "address"));
        QVERIFY(refused([](auto& j) { j["sites"][0]["stepDeadline"] = -1; }, "stepDeadline"));
        QVERIFY(refused([](auto& j) { j["sites"][0]["tokenFile"] = "/nonexistent/t"; },
                        "tokenFile"));
        QVERIFY(refused([](auto& j) { j["sites"][0]["colour"] = 1; }, "colour"));
        // A token file that other users can read is refused (issue 26, D3); 0600 is read.
        QTemporaryDir tokens;
        const std::string open = tokens.filePath("open").toStdString();
        std::ofstream(open) << "lab-token\n";
        QFile::setPermissions(QString::fromStdString(open),
                              QFile::ReadOwner | QFile::WriteOwner | QFile::ReadOther);
        QVERIFY(refused([&](auto& j) { j["sites"][0]["tokenFile"] = open; },
                        "readable by other users (mode 0604); a secret others can read is no "
                        "secret: chmod 600"));
        QFile::setPermissions(QString::fromStdString(open), QFile::ReadOwner | QFile::WriteOwner);
        nlohmann::json withToken = twoLabs(1.0);
        withToken["sites"][0]["tokenFile"] = open;
        QCOMPARE(parseConfig(withToken, "ok.json").sites[0].token, std::string("lab-token"));
        // An address comms cannot parse is refused when the links are built, naming the site.
        nlohmann::json j = twoLabs(1.0);
        j["sites"][1]["address"] = "tcp://127.0.0.1:99999";
        const TestConfig cfg = parseConfig(j, "bad-port.json");
        bool threw = false;
        try {
            makeControlFactory(LinkAddress{}, patientOptions(), cfg);
        } catch (const ConfigError& e) {
            threw = QString(e.what()).contains("sites 'Lab C': address");
        }
        QVERIFY(threw);
    }

    void twoLabsEqualTheSingleProcessRun() {
        ControllerProcess labD(controllerArgs()), labC(controllerArgs());
        QVERIFY2(labD.start(), qPrintable(labD.log()));
        QVERIFY2(labC.start(), qPrintable(labC.log()));
        const TestConfig cfg = withPorts(twoLabs(1.5), labD.port(), labC.port(),
                                         m_dir.filePath("ports.json").toStdString());
        const Run linked = runTest(cfg, makeControlFactory(LinkAddress{}, patientOptions(), cfg));
        QVERIFY2(linked.prepared, linked.error.c_str());
        QCOMPARE(linked.state, HybridTest::State::Finished);
        QVERIFY(everyStepOnce(linked));
        const double diff = maxDifference(m_reference, linked);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
        // A round trip per site and step (a real one: > 0 and below the step deadline).
        for (std::size_t i = 1; i < linked.records.size(); ++i) {
            const auto& rt = linked.records[i].siteRoundTrips;
            QCOMPARE(rt.size(), std::size_t(2));
            for (double t : rt)
                QVERIFY2(t > 0.0 && t < 30.0, qPrintable(QString::number(t)));
        }
        QVERIFY(std::isnan(linked.records[0].siteRoundTrips[0]));
        // Each controller served one specimen: its own.
        labD.stop();
        labC.stop();
        QVERIFY2(labD.log().contains("on specimen 'Bearing D'") &&
                     !labD.log().contains("on specimen 'Bearing C'"),
                 qPrintable(labD.log()));
        QVERIFY2(labC.log().contains("on specimen 'Bearing C'") &&
                     !labC.log().contains("on specimen 'Bearing D'"),
                 qPrintable(labC.log()));
    }

    void aVirtualLabAndAnOpenFrescoSiteInOneTest() {
        // Lab D in process (builtin), Lab C an OpenFresco SimApp element server (hsmu-controller
        // --protocol simapp serving Bearing C only): the same result as the single process.
        nlohmann::json cOnly = twoLabs(1.5);
        for (auto& e : cOnly["structure"]["elements"])
            if (e["name"] == "Bearing D") {
                e.erase("experimental");
                e.erase("specimen");
                e.erase("limits");
            }
        cOnly.erase("sites"); // the controller's own file: Bearing C its only specimen
        cOnly.erase("updating");
        const std::string cPath = writeConfig(m_dir.path(), "c-only.json", cOnly);
        ControllerProcess labC({"--config", QString::fromStdString(cPath), "--pace", "fast",
                                "--protocol", "simapp"});
        QVERIFY2(labC.start(), qPrintable(labC.log()));
        nlohmann::json j = twoLabs(1.5);
        j["sites"][0]["address"] = "builtin";
        j["sites"][1]["address"] = "simapp://127.0.0.1:" + std::to_string(labC.port());
        const std::string path = writeConfig(m_dir.path(), "mixed.json", j);
        const TestConfig cfg = loadConfigFile(path);
        const Run mixed = runTest(cfg, makeControlFactory(LinkAddress{}, patientOptions(), cfg));
        QVERIFY2(mixed.prepared, mixed.error.c_str());
        QCOMPARE(mixed.state, HybridTest::State::Finished);
        QVERIFY(everyStepOnce(mixed));
        const double diff = maxDifference(m_reference, mixed);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
        for (std::size_t i = 1; i < mixed.records.size(); ++i)
            for (double t : mixed.records[i].siteRoundTrips)
                QVERIFY(t >= 0.0 && t < 30.0);
        labC.stop();
        QVERIFY2(labC.log().contains("simapp element server"), qPrintable(labC.log()));
    }

    void killingOneLabHoldsBothAndARestartResumesBoth() {
        const QString stateD = m_dir.filePath("lab-d.state"), stateC = m_dir.filePath("lab-c.state");
        ControllerProcess labD(controllerArgs(stateD)), labC(controllerArgs(stateC));
        QVERIFY2(labD.start(), qPrintable(labD.log()));
        QVERIFY2(labC.start(), qPrintable(labC.log()));
        const quint16 portC = labC.port();
        const TestConfig cfg = withPorts(twoLabs(1.5), labD.port(), portC,
                                         m_dir.filePath("ports-kill.json").toStdString());
        auto test = buildHybridTest(cfg, makeControlFactory(LinkAddress{}, patientOptions(), cfg));
        Recorder rec;
        rec.onStepHook = [&](int step) {
            if (step == 120)
                labC.kill(); // SIGKILL between steps 120 and 121
        };
        test->addObserver(&rec);
        QVERIFY2(test->prepare(), test->lastError().c_str());
        int holds = 0;
        for (int guard = 0; guard < 10000; ++guard) {
            const auto r = test->step();
            if (r == HybridTest::StepResult::Finished)
                break;
            if (r != HybridTest::StepResult::Held)
                continue;
            ++holds;
            QCOMPARE(holds, 1);
            QCOMPARE(test->currentStep(), 120);
            // Both sites hold: the monitor says so, Lab C is down, Lab D was told to hold.
            const auto monitor = test->siteMonitor();
            QVERIFY(monitor->holding());
            const auto sites = monitor->sites();
            QCOMPARE(sites.size(), std::size_t(2));
            // Sites in the order of their first element in the model: C, then D.
            const SiteStatus &c = sites[0], &d = sites[1];
            QCOMPARE(c.name, std::string("Lab C"));
            QCOMPARE(d.name, std::string("Lab D"));
            QVERIFY(d.connected);
            QCOMPARE(d.faults, 0);
            QVERIFY(!c.connected);
            QVERIFY(c.faults >= 1);
            QVERIFY2(c.lastFault.find("Bearing C") == 0, c.lastFault.c_str());
            QVERIFY(test->alarms().back().message.find("Bearing C") != std::string::npos);
            QVERIFY(QTest::qWaitFor([&] { return labD.log().contains("holds at the console's "
                                                                     "request"); },
                                    10000));
            QVERIFY2(labC.start(portC), qPrintable(labC.log()));
            test->resume();
        }
        QCOMPARE(holds, 1);
        QCOMPARE(test->state(), HybridTest::State::Finished);
        QVERIFY(!test->siteMonitor()->holding());
        for (const SiteStatus& s : test->siteMonitor()->sites())
            QVERIFY(s.connected);
        test->removeObserver(&rec);
        Run run;
        run.records = rec.records;
        QVERIFY(everyStepOnce(run));
        const double diff = maxDifference(m_reference, run);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
        test.reset();
        labC.stop();
        QVERIFY2(labC.log().contains("continues after step 120"), qPrintable(labC.log()));
    }
};

QTEST_GUILESS_MAIN(TestSites)
#include "TestSites.moc"
