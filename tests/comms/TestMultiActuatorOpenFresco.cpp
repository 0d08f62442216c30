// Issue 24's acceptance over OpenFresco's protocols: the one-bay frame whose left column is the
// two-actuator specimen (preset two-actuator-column-frame: a force-controlled vertical actuator
// holding 500 kN, a displacement-controlled lateral one) runs end to end on a real
// `hsmu-controller --protocol simapp` (and generictcp) process with OpenFresco's sizes for a
// setup of two actuators (ctrl disp 2, ctrl force 2, daq disp 2, daq force 2), and equals the
// in-process virtual lab and the all-numerical frame to 1e-9 of the peak. An emergency hold and
// a dropped link each leave every actuator holding at its committed command (the controller's
// log, checked against the console's record or against frames built here from the documented
// layout), and the record keeps every step exactly once. Sizes that cannot carry the
// force-controlled channel are refused on both sides with the fix named. The real OpenSees /
// OpenFresco kit (../shared/tools/opensees; skipped where absent) drives the two actuators of
// hsmu-controller's GenericTCP server through `expControl GenericTCP -ctrlModes 1 0 0 1 0` and
// `expSetup NoTransformation -dir 1 2`, i.e. with OpenFresco's own sizes for the setup.
#include "comms/link/ControlFactory.h"
#include "comms/openfresco/SimAppControl.h"

#include "ControllerProcess.h"
#include "MultiActuatorFixture.h"
#include "OfRawPeer.h"
#include "OpenSeesRunner.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;
using namespace multiactuator;
using namespace ofpeer;

namespace {

LinkAddress address(LinkAddress::Kind kind, quint16 port) {
    return LinkAddress{kind, "127.0.0.1", port};
}

// OpenSees + OpenFresco: a twoNodeLink on 2 DOFs behind `expSetup NoTransformation -dir 1 2`
// and `expControl GenericTCP` with disp + force control and daq (OpenFresco's sizes for two
// actuators: ctrl disp 2, ctrl force 2, daq disp 2, daq force 2); dir 2 (the lateral actuator)
// pushed 1 mm per step, dir 1 (the force-controlled vertical actuator) free and unloaded:
// OpenFresco sends the element's trial forces (0) in the ctrl force entries.
const char* const kKitScript = R"(model BasicBuilder -ndm 2 -ndf 2
loadPackage OpenFrescoTcl
node 1 0.0 0.0
node 2 0.0 0.0
fix 1 1 1
expControl GenericTCP 1 127.0.0.1 PORT -ctrlModes 1 0 0 1 0 -daqModes 1 0 0 1 0
expSetup NoTransformation 1 -control 1 -dir 1 2 -sizeTrialOut 2 2
expSite LocalSite 1 1
expElement twoNodeLink 1 1 2 -dir 1 2 -site 1 -initStif 200000.0 0.0 0.0 1000.0
timeSeries Linear 1
pattern Plain 1 1 { sp 2 2 0.001 }
recorder Element -precision 16 -file force.out -time -ele 1 basicForce
recorder Element -precision 16 -file daqDisp.out -time -ele 1 daqDisp
constraints Transformation
numberer Plain
system FullGeneral
test NormDispIncr 1e-12 10
algorithm Newton
integrator LoadControl 1.0
analysis Static
analyze 4
wipeExp
wipe
exit
)";

QString number(double x) {
    char v[40];
    std::snprintf(v, sizeof v, "%.17g", x);
    return QString::fromLatin1(v);
}

/// The controller's line for a specimen holding at a committed step (OfServer.h).
QString holdsLine(int step, double vertical, double lateral) {
    return QString("specimen 'Column L' holds at its committed step %1, channel commands [%2, %3]")
        .arg(step)
        .arg(number(vertical), number(lateral));
}

} // namespace

class TestMultiActuatorOpenFresco : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::string m_config;

    ControllerProcess* controller(const char* protocol, bool quiet = true) {
        QStringList args{
            "--config", QString::fromStdString(m_config), "--protocol", protocol, "--pace", "fast"};
        if (quiet)
            args << "--quiet";
        return new ControllerProcess(args);
    }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_config = writeConfig(m_dir.path(), "frame.json", preset(5.0));
    }

    void runEqualsNumericalFrame_data() {
        QTest::addColumn<QString>("protocol");
        QTest::newRow("simapp") << "simapp";
        QTest::newRow("generictcp") << "generictcp";
    }

    void runEqualsNumericalFrame() {
        QFETCH(QString, protocol);
        std::unique_ptr<ControllerProcess> ctl(controller(qPrintable(protocol), false));
        QVERIFY2(ctl->start(), qPrintable(ctl->log()));
        const auto kind =
            protocol == "simapp" ? LinkAddress::Kind::SimApp : LinkAddress::Kind::GenericTcp;
        const TestConfig cfg = loadConfigFile(m_config);
        const Run linked =
            runTest(cfg, makeControlFactory(address(kind, ctl->port()), patientOptions()));
        QVERIFY2(linked.state == HybridTest::State::Finished, linked.error.c_str());
        QCOMPARE(linked.records.size(), std::size_t(501));
        QVERIFY(everyStepOnce(linked));
        QVERIFY2(ctl->waitForLog("2 actuator channels of 'Column L'"), qPrintable(ctl->log()));
        QVERIFY2(ctl->waitForLog("sizes ctrl [disp 2, vel 0, accel 0, force 2, time 0], daq [disp "
                                 "2, vel 0, accel 0, force 2, time 0]"),
                 qPrintable(ctl->log()));
        const Run inProcess = runTest(cfg, {});
        const Run numerical = runTest(parseConfig(numericalTwin(preset(5.0)), "twin.json"), {});
        QCOMPARE(numerical.state, HybridTest::State::Finished);
        const double vsLab = maxDifference(inProcess, linked);
        const double vsNumerical = relativeDifference(numerical, linked);
        qInfo("over %s: max |diff| to the in-process lab %.3g, relative to the numerical frame "
              "%.3g",
              qPrintable(protocol), vsLab, vsNumerical);
        QVERIFY2(vsLab <= 1e-9, qPrintable(QString::number(vsLab)));
        QVERIFY2(vsNumerical <= 1e-9, qPrintable(QString::number(vsNumerical)));
    }

    void emergencyHoldHoldsEveryActuator() {
        std::unique_ptr<ControllerProcess> ctl(controller("simapp", false));
        QVERIFY2(ctl->start(), qPrintable(ctl->log()));
        const TestConfig cfg = loadConfigFile(m_config);
        auto test =
            buildHybridTest(cfg, makeControlFactory(address(LinkAddress::Kind::SimApp, ctl->port()),
                                                    patientOptions()));
        Recorder rec;
        test->addObserver(&rec);
        QVERIFY(test->prepare());
        int guard = 0;
        while (test->step() == HybridTest::StepResult::Advanced && ++guard < 100) {
        }
        test->emergencyHold("operator: emergency stop");
        QCOMPARE(test->step(), HybridTest::StepResult::Held);
        QCOMPARE(rec.records.size(), std::size_t(101));
        // The controller sees its client gone: every actuator holds at its committed command,
        // the console's last recorded one (the lateral channel: the shear DOF's stroke).
        const QString line = holdsLine(100, -500.0, rec.records.back().elements[0].commanded);
        QVERIFY2(ctl->waitForLog(line), qPrintable(line + "\n" + ctl->log()));
        // OpenFresco has no session to resume: the test stays held, nothing recorded twice.
        test->resume();
        QVERIFY(test->step() != HybridTest::StepResult::Advanced);
        test->removeObserver(&rec);
        Run run;
        run.records = rec.records;
        QCOMPARE(run.records.size(), std::size_t(101));
        QVERIFY(everyStepOnce(run));
    }

    void droppedLinkHoldsEveryActuator() {
        // A client built from the documented layout: [3, ctrl disp 1, 2, ctrl force 1, 2].
        std::unique_ptr<ControllerProcess> ctl(controller("simapp", false));
        QVERIFY2(ctl->start(), qPrintable(ctl->log()));
        RawPeer p;
        QVERIFY(p.socket.connect("127.0.0.1", ctl->port(), kWait, p.error));
        QVERIFY(p.send(header({2, 0, 0, 2, 0, 2, 0, 0, 2, 0, 256})));
        // Step 1: the vertical actuator holds -500 kN (its ctrl disp is ignored), the lateral
        // one moves to 2 mm; measured [disp 1, disp 2, force 1, force 2].
        QVERIFY(p.send(frame({3, 0.123, 0.002, -500.0, 77.0}, 256)));
        QVERIFY(p.send(frame({6}, 256)));
        const auto r1 = p.receive(256);
        QVERIFY2(r1, p.error.c_str());
        QCOMPARE((*r1)[1], 0.002);  // the lateral stroke, as commanded (ideal)
        QCOMPARE((*r1)[2], -500.0); // the vertical force, as commanded
        QVERIFY(std::abs((*r1)[0] + 500.0 / 200000.0) < 1e-14); // elastic k 200000 kN/m
        QVERIFY(p.send(frame({5}, 256)));
        // Step 2 measured, never committed: then the link drops.
        QVERIFY(p.send(frame({3, 0.0, 0.004, -500.0, 0.0}, 256)));
        QVERIFY(p.send(frame({6}, 256)));
        const auto r2 = p.receive(256);
        QVERIFY2(r2 && (*r2)[1] == 0.004, p.error.c_str());
        p.socket.close();
        const QString line = holdsLine(1, -500.0, 0.002);
        QVERIFY2(ctl->waitForLog(line), qPrintable(line + "\n" + ctl->log()));
    }

    void sizesThatCannotCarryAForceChannelAreRefused() {
        std::unique_ptr<ControllerProcess> ctl(controller("simapp", false));
        QVERIFY2(ctl->start(), qPrintable(ctl->log()));
        // The server: ctrl force 0 cannot carry the vertical actuator's force -> NaN, logged.
        RawPeer p;
        QVERIFY(p.socket.connect("127.0.0.1", ctl->port(), kWait, p.error));
        QVERIFY(p.send(header({2, 0, 0, 0, 0, 2, 0, 0, 2, 0, 256})));
        QVERIFY(p.send(frame({6}, 256)));
        const auto r = p.receive(256);
        QVERIFY2(r && std::isnan((*r)[0]), p.error.c_str());
        QVERIFY2(ctl->waitForLog("channel(s) 1 'vertical' are force-controlled: their commands "
                                 "travel in the ctrl force entries, so ctrl force must be 2"),
                 qPrintable(ctl->log()));
        p.socket.close();
        // The console: the same sizes are refused before anything is sent.
        OfControlOptions o = ofOptions();
        o.channelModes = {ActuatorMode::Force, ActuatorMode::Displacement};
        o.sizes.ctrl = {2, 0, 0, 0, 0};
        o.sizes.daq = {2, 0, 0, 2, 0};
        SimAppControl c("127.0.0.1", ctl->port(), "Column L", o);
        const ControlResult pr = c.prepare(0.01);
        QVERIFY(!pr.ok);
        QVERIFY2(pr.reason.find("channel 1 is force-controlled: its command travels in the ctrl "
                                "force entries, so ctrl force must be 2") != std::string::npos,
                 pr.reason.c_str());
        QVERIFY(!c.linkUp());
    }

    void openFrescoKitDrivesBothActuatorsOverGenericTcp() {
        if (!opensees::available())
            QSKIP(qPrintable(opensees::reason()));
        // The lateral actuator elastic (k 1000 kN/m): every force is known in closed form.
        nlohmann::json j = preset(5.0);
        j["structure"]["elements"][0]["actuators"][1]["material"] = {{"law", "elastic"},
                                                                     {"k", 1000.0}};
        const std::string path = writeConfig(m_dir.path(), "kit.json", j);
        ControllerProcess ctl({"--config", QString::fromStdString(path), "--protocol", "generictcp",
                               "--pace", "fast"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const QString script = QString(kKitScript).replace("PORT", QString::number(ctl.port()));
        // ECGenericTCP::setup waits for two <Enter> on stdin.
        const auto r = opensees::run(m_dir.path(), "kit.tcl", script, 60000, "\n\n");
        QVERIFY2(r.finished, qPrintable(r.output));
        QVERIFY2(ctl.waitForLog("sizes ctrl [disp 2, vel 0, accel 0, force 2, time 0], daq [disp "
                                "2, vel 0, accel 0, force 2, time 0]"),
                 qPrintable(ctl.log()));
        QVERIFY2(ctl.waitForLog("terminated by the client (99)"), qPrintable(ctl.log()));
        const auto force = opensees::table(m_dir.path() + "/force.out");
        const auto disp = opensees::table(m_dir.path() + "/daqDisp.out");
        QCOMPARE(force.size(), std::size_t(4));
        QCOMPARE(disp.size(), std::size_t(4));
        for (std::size_t i = 0; i < 4; ++i) {
            const double d = 0.001 * static_cast<double>(i + 1); // [m] the lateral stroke
            QVERIFY2(force[i].size() == 3 && disp[i].size() == 3, qPrintable(r.output));
            QVERIFY(std::abs(disp[i][2] - d) <= 1e-12);          // measured lateral stroke
            QVERIFY(std::abs(force[i][2] - 1000.0 * d) <= 1e-9); // k d [kN]
            QVERIFY(std::abs(force[i][1]) <= 1e-9);              // the vertical force held: 0
        }
    }

    void linkWithOtherSpecimensOrServerDofsIsRefusedAtStart() {
        nlohmann::json j = preset(5.0);
        j["controller"]["serverDofs"] = nlohmann::json::array({{{"specimen", "Column L"}}});
        const std::string path = writeConfig(m_dir.path(), "dofs.json", j);
        ControllerProcess ctl(
            {"--config", QString::fromStdString(path), "--protocol", "simapp", "--pace", "fast"});
        QVERIFY(!ctl.start(0, 20000));
        QVERIFY2(ctl.log().contains("is served over --protocol simapp alone") &&
                     ctl.log().contains("remove controller.serverDofs"),
                 qPrintable(ctl.log()));
    }
};

QTEST_MAIN(TestMultiActuatorOpenFresco)
#include "TestMultiActuatorOpenFresco.moc"
