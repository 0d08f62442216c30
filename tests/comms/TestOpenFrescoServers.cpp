// hsmu-controller's OpenFresco servers (docs/openfresco.md) seen by a raw client written here
// (frames from the documented layout): replies at index 0 with the specimen's values, a site
// server that answers no matrices, code 99, one client at a time (an idle session gives way),
// a client vanishing mid-frame. The console's own clients: TestOpenFrescoLinks.
#include "comms/link/ControlFactory.h"
#include "core/hysteresis/HysteresisLaw.h"

#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "OfRawPeer.h"

#include <QTemporaryDir>
#include <QtTest>

#include <chrono>
#include <thread>

using namespace hsmu;
using namespace hsmu::comms;
using namespace linkfixture;
using namespace ofpeer;

class TestOpenFrescoServers : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::string m_quiet; // noise-free condition 3, for values computed here

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_quiet = writeConfig(m_dir.path(), "quiet.json", quietCondition3());
    }

    void simAppServerRepliesAtIndexZero() {
        ControllerProcess ctl = ofController(m_quiet, "simapp", {"--data-size", "32"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        const TestConfig cfg = loadConfigFile(m_quiet);
        auto law = buildLaw(cfg.elements[0].specimen.trueMaterial, "test");
        RawPeer p;
        QVERIFY2(p.socket.connect("127.0.0.1", ctl.port(), kWait, p.error), p.error.c_str());
        QVERIFY(p.send(header({1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 32})));
        const double d = 0.004;
        QVERIFY(p.send(frame({3.0, d}, 32)));
        QVERIFY(p.send(frame({6.0}, 32)));
        auto r = p.receive(32);
        QVERIFY2(r, p.error.c_str());
        law->setTrialDeformation(d);
        QCOMPARE((*r)[0], d);                       // daq disp
        QCOMPARE((*r)[1], law->trialForce());       // daq force
        QCOMPARE((*r)[2], cfg.analysis.dt);         // daq time: step 1
        for (std::size_t i = 3; i < r->size(); ++i) // padding
            QCOMPARE((*r)[i], 0.0);
        QVERIFY(p.send(frame({10.0}, 32))); // getForce alone, at index 0
        r = p.receive(32);
        QVERIFY2(r, p.error.c_str());
        QCOMPARE((*r)[0], law->trialForce());
        QCOMPARE((*r)[1], 0.0);
        QVERIFY(p.send(frame({12.0}, 32))); // 1 x 1 initial stiffness
        r = p.receive(32);
        QVERIFY2(r, p.error.c_str());
        QCOMPARE((*r)[0], law->initialTangent());
        QVERIFY(p.send(frame({14.0}, 32))); // damping: zero
        r = p.receive(32);
        QVERIFY2(r && (*r)[0] == 0.0, p.error.c_str());
        QVERIFY(p.send(frame({5.0}, 32)));  // commit: no reply
        QVERIFY(p.send(frame({99.0}, 32))); // terminate: the server closes
        std::uint8_t byte;
        QVERIFY(!p.socket.read(&byte, 1, kWait, p.error));
        QVERIFY2(p.socket.closedByPeer(), p.error.c_str());

        // The next session is admitted and starts from a fresh specimen.
        RawPeer q;
        QVERIFY2(q.socket.connect("127.0.0.1", ctl.port(), kWait, q.error), q.error.c_str());
        QVERIFY(q.send(header({1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 32})));
        QVERIFY(q.send(frame({6.0}, 32)));
        r = q.receive(32);
        QVERIFY2(r && (*r)[0] == 0.0 && (*r)[1] == 0.0, q.error.c_str());
        ctl.stop();
        QVERIFY2(ctl.log().contains("terminated by the client (99)"), qPrintable(ctl.log()));
    }


    void siteServerDoesNotAnswerMatrices() {
        ControllerProcess ctl = ofController(m_quiet, "simapp", {"--simapp-site"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawPeer p;
        QVERIFY2(p.socket.connect("127.0.0.1", ctl.port(), kWait, p.error), p.error.c_str());
        QVERIFY(p.send(header({1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 256})));
        QVERIFY(p.send(frame({3.0, 0.002}, 256)));
        QVERIFY(p.send(frame({12.0}, 256))); // no reply from a site server
        QVERIFY(p.send(frame({6.0}, 256)));
        const auto r = p.receive(256);
        QVERIFY2(r, p.error.c_str());
        QCOMPARE((*r)[0], 0.002); // the first frame back is the daq reply, not a matrix
    }


    // One client at a time: an idle session (no frame for controller.idleTimeout) gives way
    // to a client that is waiting to connect; with nobody waiting it may idle on.
    void idleSessionGivesWayToAWaitingClient() {
        nlohmann::json j = condition3(0.2);
        j["structure"]["elements"][0]["specimen"]["forceNoiseStd"] = 0.0;
        j["controller"]["idleTimeout"] = 1.0;
        const std::string path = writeConfig(m_dir.path(), "idle.json", j);
        ControllerProcess ctl = ofController(path, "simapp", {"--data-size", "32"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawPeer a;
        QVERIFY2(a.socket.connect("127.0.0.1", ctl.port(), kWait, a.error), a.error.c_str());
        QVERIFY(a.send(header({1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 32})));
        QVERIFY(a.send(frame({3.0, 0.002}, 32)));
        QVERIFY(a.send(frame({6.0}, 32)));
        auto r = a.receive(32);
        QVERIFY2(r && (*r)[0] == 0.002, a.error.c_str());
        // Idle past the timeout with nobody else waiting (the idle time itself, not a
        // synchronisation): the session is kept and answers.
        std::this_thread::sleep_for(std::chrono::milliseconds(2500));
        QVERIFY(a.send(frame({6.0}, 32)));
        r = a.receive(32);
        QVERIFY2(r && (*r)[0] == 0.002, a.error.c_str());
        // Now a second client connects while the first idles: it is served (within the idle
        // timeout plus the server's 0.2 s poll; kWait bounds it) and the first is closed.
        RawPeer b;
        QVERIFY2(b.socket.connect("127.0.0.1", ctl.port(), kWait, b.error), b.error.c_str());
        QVERIFY(b.send(header({1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 32})));
        QVERIFY(b.send(frame({6.0}, 32)));
        r = b.receive(32);
        QVERIFY2(r, b.error.c_str());
        QCOMPARE((*r)[0], 0.0); // a fresh specimen: the new session starts from zero
        std::uint8_t byte;
        QVERIFY(!a.socket.read(&byte, 1, kWait, a.error));
        QVERIFY2(a.socket.closedByPeer(), a.error.c_str());
        ctl.stop();
        QVERIFY2(ctl.log().contains("idle for 1 s while another client waits"),
                 qPrintable(ctl.log()));
    }


    void clientVanishingMidFrameFreesTheServer() {
        ControllerProcess ctl = ofController(m_quiet, "simapp");
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        {
            RawPeer p;
            QVERIFY2(p.socket.connect("127.0.0.1", ctl.port(), kWait, p.error), p.error.c_str());
            QVERIFY(p.send(header({1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 256})));
            auto half = frame({3.0, 0.001}, 256);
            half.resize(100);
            QVERIFY(p.send(half));
        } // closed mid-frame
        const TestConfig cfg = loadConfigFile(m_quiet);
        const Run linked = runTest(
            cfg, makeControlFactory(LinkAddress{LinkAddress::Kind::SimApp, "127.0.0.1", ctl.port()},
                                    patientOptions(), cfg.link));
        QVERIFY2(linked.state == HybridTest::State::Finished, linked.error.c_str());
        QVERIFY(maxDifference(runTest(cfg, {}), linked) <= 1e-9);
        ctl.stop();
        QVERIFY2(ctl.log().contains("in the middle of a frame (100 of 2048 bytes)"),
                 qPrintable(ctl.log()));
    }
};

QTEST_GUILESS_MAIN(TestOpenFrescoServers)
#include "TestOpenFrescoServers.moc"
