// Issue 24 item 4 on a real hsmu-controller process: the two-actuator column frame's specimen
// simulated as a whole behind its setup (a cantilever column: Bouc-Wen moment-rotation hinge,
// elastic axial, P-Delta from the held 500 kN; docs/setups.md "The specimen as a whole"), its
// lateral actuator lagging and its vertical one delayed (per-channel actuator models), runs
// over the native protocol and over OpenFresco's SimApp and GenericTCP (hsmu-controller
// --protocol simapp|generictcp) equal to the in-process virtual lab to 1e-9; the controller still
// checks each channel's limits (a tighter lateral stroke limit in its file trips there, naming
// the channel, and the test holds with every step recorded once).
#include "comms/link/ControlFactory.h"

#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "MultiActuatorFixture.h"
#include "OfRawPeer.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;
using namespace multiactuator;
using namespace ofpeer;

namespace {

/// The preset with its left column as a whole: Bouc-Wen hinge (1.6e5 kN m/rad, yield near
/// 150 kN m), elastic axial 2e5 kN/m, EI 2e5 kN m^2; lateral lag 5 ms, vertical delay 20 ms.
/// The controller's loop at 100 Hz, one tick per 10 ms step: each channel's actuator model,
/// run at the loop rate with its command reaching the target at the step's one tick, is then
/// the in-process lab's once-per-step model (lag exp(-h/tau) with h = dt; delay 2 ticks = 2
/// steps), so both runs must agree (TestChannelLoops checks the loop rate's own closed form).
nlohmann::json wholeFrame(double duration) {
    nlohmann::json doc = preset(duration);
    nlohmann::json& col = doc["structure"]["elements"][0];
    col["specimen"] = {
        {"type", "cantileverColumn"},
        {"hinge", {{"law", "boucWen"}, {"alpha", 0.05}, {"uRef", 0.001875}, {"fRef", 300.0}}},
        {"axial", {{"law", "elastic"}, {"k", 2e5}}},
        {"ei", 2e5}};
    for (auto& a : col["actuators"])
        a.erase("material");
    col["actuators"][0]["actuator"] = {{"type", "delay"}, {"delay", 0.02}};
    col["actuators"][1]["actuator"] = {{"type", "lag"}, {"timeConstant", 0.005}};
    doc["controller"]["rate"] = 100.0;
    return doc;
}

} // namespace

class TestWholeSpecimenLink : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::string m_config;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_config = writeConfig(m_dir.path(), "whole.json", wholeFrame(5.0));
    }

    void runEqualsInProcessLab_data() {
        QTest::addColumn<QString>("protocol");
        QTest::newRow("native") << "native";
        QTest::newRow("simapp") << "simapp";
        QTest::newRow("generictcp") << "generictcp";
    }

    void runEqualsInProcessLab() {
        QFETCH(QString, protocol);
        ControllerProcess ctl({"--config", QString::fromStdString(m_config), "--protocol", protocol,
                               "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const TestConfig cfg = loadConfigFile(m_config);
        const auto kind = protocol == "simapp"       ? LinkAddress::Kind::SimApp
                          : protocol == "generictcp" ? LinkAddress::Kind::GenericTcp
                                                     : LinkAddress::Kind::Tcp;
        const Run linked = runTest(
            cfg, makeControlFactory(LinkAddress{kind, "127.0.0.1", ctl.port()}, patientOptions()));
        QVERIFY2(linked.state == HybridTest::State::Finished, linked.error.c_str());
        QCOMPARE(linked.records.size(), std::size_t(501));
        QVERIFY(everyStepOnce(linked));
        const Run inProcess = runTest(cfg, {});
        QCOMPARE(inProcess.state, HybridTest::State::Finished);
        double peak = 0;
        for (const auto& r : inProcess.records)
            peak = std::max(peak, std::abs(r.elements[0].force));
        const double diff = maxDifference(inProcess, linked);
        qInfo("whole specimen over %s: peak shear %.6g kN, max |diff| to the in-process lab %.3g",
              qPrintable(protocol), peak, diff);
        QVERIFY(peak > 40.0); // the hinge yielded (M_y / L near 50 kN)
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
    }

    void controllerChecksEachChannelsLimits() {
        nlohmann::json tight = wholeFrame(5.0);
        tight["structure"]["elements"][0]["actuators"][1]["limits"]["deformation"] = 0.004;
        const std::string path = writeConfig(m_dir.path(), "tight.json", tight);
        ControllerProcess ctl({"--config", QString::fromStdString(path), "--pace", "fast"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const Run run =
            runTest(loadConfigFile(m_config),
                    makeControlFactory(LinkAddress{LinkAddress::Kind::Tcp, "127.0.0.1", ctl.port()},
                                       patientOptions()));
        QCOMPARE(run.state, HybridTest::State::Holding);
        QVERIFY(run.records.size() > 10);
        QVERIFY(everyStepOnce(run));
        QVERIFY2(run.error.find("channel 2 'lateral'") != std::string::npos, run.error.c_str());
        QVERIFY(std::abs(run.records.back().elements[0].commanded) <= 0.004);
        QVERIFY2(ctl.waitForLog("channel 2 'lateral'"), qPrintable(ctl.log()));
    }
};

QTEST_MAIN(TestWholeSpecimenLink)
#include "TestWholeSpecimenLink.moc"
