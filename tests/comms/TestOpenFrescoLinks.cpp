// The OpenFresco links (docs/openfresco.md) end to end: each console client (SimApp,
// GenericTCP) against each of hsmu-controller's OpenFresco servers (a real process), equal to
// the in-process run; the client's bytes checked frame by frame by a raw socket peer written
// here; and the failure cases: a wrong dataSize, a peer that closes mid-step, an interlock.
// The servers' replies to a raw client: TestOpenFrescoServers.
#include "comms/link/ControlFactory.h"
#include "comms/openfresco/GenericTcpControl.h"
#include "comms/openfresco/OfFrame.h"
#include "comms/openfresco/OfSocket.h"
#include "comms/openfresco/SimAppControl.h"
#include "core/hysteresis/HysteresisLaw.h"

#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "OfRawPeer.h"

#include <QTemporaryDir>
#include <QtTest>

#include <atomic>
#include <condition_variable>
#include <cstring>
#include <mutex>
#include <thread>

using namespace hsmu;
using namespace hsmu::comms;
using namespace hsmu::comms::of;
using namespace linkfixture;

using namespace ofpeer;

class TestOpenFrescoLinks : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::string m_config; // condition 3, 1 s, noise and a fracture event
    std::string m_quiet;  // noise-free, for values computed here

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_config = writeConfig(m_dir.path(), "c3.json", condition3(1.0));
        m_quiet = writeConfig(m_dir.path(), "quiet.json", quietCondition3());
    }

    void simAppClientEqualsInProcessRun() {
        ControllerProcess ctl = ofController(m_config, "simapp");
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        QVERIFY2(ctl.log().contains("simapp element server, dataSize 256"), qPrintable(ctl.log()));
        const TestConfig cfg = loadConfigFile(m_config);
        const Run linked = runTest(
            cfg, makeControlFactory(LinkAddress{LinkAddress::Kind::SimApp, "127.0.0.1", ctl.port()},
                                    patientOptions(), cfg.link));
        QVERIFY2(linked.prepared, linked.error.c_str());
        QCOMPARE(linked.state, HybridTest::State::Finished);
        QCOMPARE(linked.records.size(), std::size_t(101));
        QVERIFY(everyStepOnce(linked));
        const double diff = maxDifference(runTest(cfg, {}), linked);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
        ctl.stop();
        QVERIFY2(ctl.log().contains("terminated by the client (99)"), qPrintable(ctl.log()));
    }

    void genericTcpClientWithInitLinesEqualsInProcessRun() {
        // tcp:// with controller.protocol = generictcp in the configuration, on both sides.
        nlohmann::json j = condition3(1.0);
        j["controller"] = {{"protocol", "generictcp"}, {"dataSize", 64}};
        const std::string path = writeConfig(m_dir.path(), "gtcp.json", j);
        ControllerProcess ctl(
            QStringList{"--config", QString::fromStdString(path), "--pace", "fast"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        QVERIFY2(ctl.log().contains("generictcp server, dataSize 64"), qPrintable(ctl.log()));
        TestConfig cfg = loadConfigFile(path);
        cfg.link.initLines = {"# lab controller init", "loadConfig lab-42"};
        const Run linked = runTest(
            cfg, makeControlFactory(LinkAddress{LinkAddress::Kind::Tcp, "127.0.0.1", ctl.port()},
                                    patientOptions(), cfg.link));
        QVERIFY2(linked.state == HybridTest::State::Finished, linked.error.c_str());
        QVERIFY(everyStepOnce(linked));
        const double diff = maxDifference(runTest(cfg, {}), linked);
        QVERIFY2(diff <= 1e-9, qPrintable(QString::number(diff)));
        ctl.stop();
        QVERIFY2(ctl.log().contains("init line: loadConfig lab-42"), qPrintable(ctl.log()));
    }

    void genericTcpClientRefusesOurSimAppServer() {
        // GenericTCP sends no commit: against hsmu-controller --protocol simapp the specimens
        // would never be committed. The server's mark on the probe reply (OfFrame.h) tells it
        // apart: the console refuses at connect and names the fix; the server's session ends
        // with the client's 99.
        ControllerProcess ctl = ofController(m_quiet, "simapp");
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const TestConfig cfg = loadConfigFile(m_quiet);
        const Run linked = runTest(
            cfg,
            makeControlFactory(LinkAddress{LinkAddress::Kind::GenericTcp, "127.0.0.1", ctl.port()},
                               patientOptions(), cfg.link));
        QVERIFY(!linked.prepared);
        QVERIFY2(linked.error.find("refused: this server is hsmu-controller serving SimApp") !=
                         std::string::npos &&
                     linked.error.find("simapp://127.0.0.1:" + std::to_string(ctl.port())) !=
                         std::string::npos &&
                     linked.error.find("--protocol generictcp") != std::string::npos,
                 linked.error.c_str());
        ctl.stop();
        QVERIFY2(ctl.log().contains("terminated by the client (99)"), qPrintable(ctl.log()));
    }

    void genericTcpClientTrustsOurGenericTcpServer() {
        // hsmu-controller --protocol generictcp commits each trial when the next arrives: no
        // pairing warning, no alarm; the probe reply's mark is the only difference on the wire.
        ControllerProcess ctl = ofController(m_quiet, "generictcp");
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        GenericTcpControl c("127.0.0.1", ctl.port(), "Element 1", ofOptions());
        const ControlResult r = c.prepare(0.01);
        QVERIFY2(r.ok, r.reason.c_str());
        QVERIFY2(c.pairingWarning().empty(), c.pairingWarning().c_str());
        QVERIFY(c.takeNotice().empty());
        ctl.stop();
    }

    void realTimePaceGivesTheSameResult() {
        // Wall clock at the 1024 Hz loop, ~10 ms per step, each step's ticks run when its
        // trial arrives: with an ideal actuator the result is still the in-process one.
        const std::string path = writeConfig(m_dir.path(), "short.json", condition3(0.3));
        ControllerProcess ctl(QStringList{"--config", QString::fromStdString(path), "--pace",
                                          "realtime", "--protocol", "simapp"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const TestConfig cfg = loadConfigFile(path);
        const Run linked = runTest(
            cfg, makeControlFactory(LinkAddress{LinkAddress::Kind::SimApp, "127.0.0.1", ctl.port()},
                                    patientOptions(), cfg.link));
        QVERIFY2(linked.state == HybridTest::State::Finished, linked.error.c_str());
        QCOMPARE(linked.records.size(), std::size_t(31));
        QVERIFY(maxDifference(runTest(cfg, {}), linked) <= 1e-9);
        ctl.stop();
        // 30 steps of round(0.01 s * 1024 Hz) = 10 ticks
        QVERIFY2(ctl.log().contains("stopped; 300 ticks"), qPrintable(ctl.log()));
    }

    // OpenFresco has no hold message: the emergency hold (another thread) shuts the connection
    // down while measure() is blocked on a site that read [6] and stays silent; the site sees
    // the connection closed before measure() has returned, and measure() returns the hold
    // (not its 30 s deadline).
    void emergencyHoldClosesABlockedSimAppRead() {
        constexpr int N = 16;
        std::mutex mu;
        std::condition_variable cv;
        bool askedForDaq = false;
        std::atomic<bool> measureReturned{false};
        ScriptedServer server([&](OfSocket& sock, std::vector<std::string>& notes) {
            std::vector<std::uint8_t> b;
            if (!readBytes(sock, b, 44, notes, "header") || !readBytes(sock, b, N * 8, notes, "probe"))
                return;
            std::string e;
            auto f = frame({0.0, 0.0}, N);
            sock.write(f.data(), f.size(), kWait, e);
            if (!readBytes(sock, b, N * 8, notes, "trial") || !readBytes(sock, b, N * 8, notes, "get"))
                return;
            {
                std::lock_guard lock(mu);
                askedForDaq = true;
            }
            cv.notify_all();
            std::uint8_t extra;
            const bool more = sock.read(&extra, 1, kWait, e); // silent: wait for the client
            notes.push_back(more ? "extra bytes"
                                 : measureReturned ? "closed after measure() returned"
                                                   : "closed while measure() was blocked");
        });
        QVERIFY(server.ok());
        SimAppControl c("127.0.0.1", server.port(), "Element 1", ofOptions(N));
        const ControlResult p = c.prepare(0.02);
        QVERIFY2(p.ok, p.reason.c_str());
        QVERIFY(c.setTarget(0.002).ok);
        ControlResult r;
        std::thread measuring([&] {
            ControlMeasurement m;
            r = c.measure(m);
            measureReturned = true;
        });
        {
            std::unique_lock lock(mu);
            QVERIFY(cv.wait_for(lock, std::chrono::duration<double>(kWait),
                                [&] { return askedForDaq; }));
        }
        c.emergencyHold("test");
        measuring.join();
        server.join();
        QVERIFY(!r.ok);
        QVERIFY2(r.reason.find("emergency hold: test") != std::string::npos, r.reason.c_str());
        // The site sees the connection closed (no further bytes). Since setTarget() sends the
        // response request with the trial (send-all / acquire-all, sites), the server's "get"
        // no longer proves that measure() is already blocked in its read, so either order of
        // the close and measure()'s return is accepted here; the blocked case itself is
        // asserted over the native link by test_comms_emergency_hold.
        QCOMPARE(server.notes.size(), std::size_t(1));
        QVERIFY2(server.notes[0] != "extra bytes", server.notes[0].c_str());
        QVERIFY(!c.setTarget(0.003).ok); // held until resumed; then the link is down
        c.hold("test");
        c.resume();
        const ControlResult again = c.setTarget(0.003);
        QVERIFY(!again.ok);
        QVERIFY2(again.reason.find("restart the test") != std::string::npos, again.reason.c_str());
    }

    void simAppClientFramesByteByByte() {
        constexpr int N = 24;
        ScriptedServer server([](OfSocket& s, std::vector<std::string>& notes) {
            std::vector<std::uint8_t> b;
            if (!readBytes(s, b, 44, notes, "header"))
                return;
            for (int i = 0; i < 11; ++i) {
                std::int32_t v;
                std::memcpy(&v, b.data() + 4 * i, 4);
                notes.push_back(std::to_string(v).insert(0, 1, 'h'));
            }
            auto expectFrame = [&](const char* what) -> std::vector<double> {
                if (!readBytes(s, b, N * 8, notes, what))
                    return {};
                return doubles(b);
            };
            auto reply = [&](std::vector<double> v) {
                const auto f = frame(std::move(v), N);
                std::string e;
                s.write(f.data(), f.size(), kWait, e);
            };
            auto describe = [&](const std::vector<double>& v) {
                std::string t;
                bool padded = true;
                for (std::size_t i = 0; i < v.size(); ++i)
                    if (i >= 3 && v[i] != 0.0)
                        padded = false;
                if (v.empty())
                    return std::string("none");
                t = std::to_string(static_cast<int>(v[0])) + (padded ? " padded" : " NOT padded");
                return t;
            };
            auto f = expectFrame("probe");
            notes.push_back("probe " + describe(f));
            reply({0.0, 0.0});
            f = expectFrame("trial");
            notes.push_back("trial " + describe(f));
            notes.push_back("d " + std::to_string(f.size() > 1 ? f[1] : -1));
            notes.push_back("t " + std::to_string(f.size() > 2 ? f[2] : -1));
            f = expectFrame("get");
            notes.push_back("get " + describe(f));
            reply({0.00195, 12.5});
            f = expectFrame("commit");
            notes.push_back("commit " + describe(f));
            f = expectFrame("end");
            notes.push_back("end " + describe(f));
            std::uint8_t extra;
            std::string e;
            notes.push_back(s.read(&extra, 1, kWait, e) ? "extra bytes" : "closed");
        });
        QVERIFY(server.ok());
        {
            OfControlOptions o = ofOptions(N);
            o.sizes.ctrl = {1, 0, 0, 0, 1}; // disp and time
            SimAppControl c("127.0.0.1", server.port(), "Element 1", o);
            const ControlResult p = c.prepare(0.02);
            QVERIFY2(p.ok, p.reason.c_str());
            QVERIFY(c.setTarget(0.002).ok);
            ControlMeasurement m;
            const ControlResult r = c.measure(m);
            QVERIFY2(r.ok, r.reason.c_str());
            QCOMPARE(m.deformation, 0.00195); // reply index 0 = daq disp
            QCOMPARE(m.force, 12.5);          // daq force after disp (vel, accel sizes 0)
            QVERIFY(c.commit().ok);
        } // the destructor sends 99 and closes
        server.join();
        const std::vector<std::string> expected = {"h1",
                                                   "h0",
                                                   "h0",
                                                   "h0",
                                                   "h1",
                                                   "h1",
                                                   "h0",
                                                   "h0",
                                                   "h1",
                                                   "h0",
                                                   "h24",
                                                   "probe 6 padded",
                                                   "trial 3 padded",
                                                   "d 0.002000",
                                                   "t 0.020000",
                                                   "get 6 padded",
                                                   "commit 5 padded",
                                                   "end 99 padded",
                                                   "closed"};
        QVERIFY2(server.notes == expected, joined(server.notes).c_str());
    }

    void genericTcpClientSendsInitLinesAndNoCommit() {
        constexpr int N = 16;
        ScriptedServer server([](OfSocket& s, std::vector<std::string>& notes) {
            std::vector<std::uint8_t> b;
            if (!readBytes(s, b, 44, notes, "header"))
                return;
            for (int i = 0; i < 2; ++i) {
                if (!readBytes(s, b, kInitLineBytes, notes, "init line"))
                    return;
                notes.push_back("line '" + decodeInitLine(b.data()) + "'");
            }
            for (int k = 0; k < 5; ++k) {
                if (!readBytes(s, b, N * 8, notes, "frame"))
                    return;
                const auto v = doubles(b);
                notes.push_back(std::to_string(static_cast<int>(v[0])));
                if (v[0] == 6.0) {
                    const auto f = frame({v.size() > 1 ? 0.001 * k : 0.0, 1.0 * k}, N);
                    std::string e;
                    s.write(f.data(), f.size(), kWait, e);
                }
            }
        });
        QVERIFY(server.ok());
        {
            OfControlOptions o = ofOptions(N);
            o.initLines = {"loadConfig lab", ""};
            GenericTcpControl c("127.0.0.1", server.port(), "Element 1", o);
            QVERIFY(c.prepare(0.01).ok);
            ControlMeasurement m;
            QVERIFY(c.setTarget(0.001).ok);
            QVERIFY(c.measure(m).ok);
            QVERIFY(c.commit().ok); // nothing on the wire
            QVERIFY(c.setTarget(0.002).ok);
            // A measured step cannot be repeated on GenericTCP.
            QVERIFY(c.measure(m).ok);
            c.hold("test");
            c.resume();
            const ControlResult again = c.setTarget(0.002);
            QVERIFY(!again.ok);
            QVERIFY2(again.reason.find("no commit") != std::string::npos, again.reason.c_str());
        }
        server.join();
        const std::vector<std::string> expected = {
            "line 'loadConfig lab'", "line ''", "6", "3", "6", "3", "6"};
        QVERIFY2(server.notes == expected, joined(server.notes).c_str());
    }

    void wrongDataSizeIsReportedAtConnect() {
        ControllerProcess ctl = ofController(m_quiet, "simapp");
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        SimAppControl c("127.0.0.1", ctl.port(), "Element 1", ofOptions(128));
        const ControlResult r = c.prepare(0.01);
        QVERIFY(!r.ok);
        // The server answers the probe with NaN (a polite refusal) instead of closing.
        QVERIFY2(r.reason.find("dataSize 128") != std::string::npos &&
                     r.reason.find("refused the sizes header") != std::string::npos,
                 r.reason.c_str());
        QVERIFY(!c.linkUp());
        // Sizes that do not match the specimens (2 ctrl displacements for 1 specimen).
        OfControlOptions o = ofOptions();
        o.sizes.ctrl = {2, 0, 0, 0, 0};
        SimAppControl two("127.0.0.1", ctl.port(), "Element 1", o);
        QVERIFY(!two.prepare(0.01).ok);
        ctl.stop();
        QVERIFY2(ctl.log().contains("the client's dataSize is 128, this server's 256") &&
                     ctl.log().contains("the client has 2 control DOFs (ctrl disp 2), this "
                                        "server serves 1 (1 DOF per specimen (1 specimen))") &&
                     ctl.log().contains("controller.serverDofs"),
                 qPrintable(ctl.log()));
    }

    void silentServerIsAFaultNotAHang() {
        // A server that takes the header and the probe but never answers (as one with a larger
        // dataSize would): prepare() fails at its deadline and says why.
        ScriptedServer server([](OfSocket& s, std::vector<std::string>& notes) {
            std::vector<std::uint8_t> b;
            if (!readBytes(s, b, 44 + 256 * 8, notes, "header and probe"))
                return;
            std::uint8_t more;
            std::string e;
            notes.push_back(s.read(&more, 1, kWait, e) ? "more bytes" : "client closed");
        });
        QVERIFY(server.ok());
        OfControlOptions o = ofOptions();
        o.stepDeadline = 0.5;
        SimAppControl c("127.0.0.1", server.port(), "Element 1", o);
        const ControlResult r = c.prepare(0.01);
        QVERIFY(!r.ok);
        QVERIFY2(r.reason.find("no answer to the first getDaqResponse") != std::string::npos,
                 r.reason.c_str());
        QVERIFY(!c.linkUp()); // closed: a late reply can never be read as a later one
        server.join();
        QCOMPARE(server.notes.back(), std::string("client closed"));
    }

    void peerClosingMidStepHoldsTheTest() {
        ScriptedServer server([](OfSocket& s, std::vector<std::string>& notes) {
            std::vector<std::uint8_t> b;
            if (!readBytes(s, b, 44, notes, "header") || !readBytes(s, b, 256 * 8, notes, "probe"))
                return;
            const auto f = frame({0.0, 0.0}, 256);
            std::string e;
            s.write(f.data(), f.size(), kWait, e);
            if (!readBytes(s, b, 256 * 8, notes, "trial"))
                return;
            notes.push_back("closing after the trial");
            s.close(); // mid-step: the measurement never comes
        });
        QVERIFY(server.ok());
        const TestConfig cfg = loadConfigFile(m_quiet);
        const Run run = runTest(cfg, makeControlFactory(LinkAddress{LinkAddress::Kind::SimApp,
                                                                    "127.0.0.1", server.port()},
                                                        patientOptions(), cfg.link));
        server.join();
        QVERIFY2(run.prepared, run.error.c_str());
        QCOMPARE(run.state, HybridTest::State::Holding);
        QVERIFY2(run.error.find("closed the connection") != std::string::npos, run.error.c_str());
        QCOMPARE(run.records.size(), std::size_t(1)); // step 0 only, nothing invented
        QCOMPARE(run.holds, 1);
        QCOMPARE(server.notes.back(), std::string("closing after the trial"));
    }

    void interlockTripEndsTheSessionAndTheTestHolds() {
        // The controller's own interlock at half the peak deformation of the free run; the
        // console's limits are removed so that only the controller guards.
        nlohmann::json j = condition3(1.0);
        auto& el = j["structure"]["elements"][0];
        el.erase("limits");
        const std::string free = writeConfig(m_dir.path(), "free.json", j);
        double peak = 0.0;
        for (const StepRecord& r : runTest(loadConfigFile(free), {}).records)
            peak = std::max(peak, std::abs(r.elements[0].deformation));
        QVERIFY(peak > 0.0);
        el["specimen"]["interlock"] = {{"deformation", 0.5 * peak}};
        const std::string path = writeConfig(m_dir.path(), "tight.json", j);
        ControllerProcess ctl = ofController(path, "simapp");
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const TestConfig cfg = loadConfigFile(path);
        const Run run = runTest(
            cfg, makeControlFactory(LinkAddress{LinkAddress::Kind::SimApp, "127.0.0.1", ctl.port()},
                                    patientOptions(), cfg.link));
        QCOMPARE(run.state, HybridTest::State::Holding);
        QVERIFY2(run.error.find("closed the connection") != std::string::npos, run.error.c_str());
        QVERIFY(run.records.size() > 1);
        for (const StepRecord& r : run.records)
            QVERIFY(std::abs(r.elements[0].deformation) <= 0.5 * peak);
        ctl.stop();
        QVERIFY2(ctl.log().contains("interlock") && ctl.log().contains("session closed"),
                 qPrintable(ctl.log()));
    }
};

QTEST_GUILESS_MAIN(TestOpenFrescoLinks)
#include "TestOpenFrescoLinks.moc"
