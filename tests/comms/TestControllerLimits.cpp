// Limits no client can lower or bypass (issue 14, item 1): a real hsmu-controller with the
// preset's element limits (0.15 rad, increment 0.01 rad) driven with random walks and wild
// targets over each protocol (native, simapp, generictcp). A client that configures limits of
// 0 does not switch them off; every target past the limit is refused (native: Error(Interlock);
// OpenFresco: the session ends, the console's step fails) and nothing measured ever lies
// outside the limit.
#include "comms/openfresco/GenericTcpControl.h"
#include "comms/openfresco/SimAppControl.h"

#include "ControllerProcess.h"
#include "LinkFixture.h"
#include "RawClient.h"

#include <QTemporaryDir>
#include <QtTest>

#include <random>

using namespace hsmu;
using namespace hsmu::comms;
using namespace hsmu::comms::of;
using namespace linkfixture;

namespace {

constexpr double kLimit = 0.15, kIncrement = 0.01; // the preset's element limits [rad]
constexpr double kWait = 20.0;                     // [s] every socket wait

/// The next target of a random walk from `last`, or (one time in six) a wild one.
double nextTarget(std::mt19937_64& rng, double last, int k) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    static const double wild[] = {100.0, -100.0, 0.1501, -0.2, 1e300, 5.0};
    if (k % 6 == 5)
        return wild[(k / 6) % 6];
    return std::clamp(last + 0.9 * kIncrement * u(rng), -0.9 * kLimit, 0.9 * kLimit);
}

} // namespace

class TestControllerLimits : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    std::string m_config;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        nlohmann::json j = condition3(60.0);
        auto& sp = j["structure"]["elements"][0]["specimen"];
        sp["forceNoiseStd"] = 0.0;
        sp.erase("fracture");
        j["structure"]["elements"][0]["limits"]["force"] = 1e6; // deformation limits only
        m_config = writeConfig(m_dir.path(), "c3.json", j);
    }

    void nativeClientCannotLowerTheLimits() {
        ControllerProcess ctl(
            {"--config", QString::fromStdString(m_config), "--pace", "fast", "--quiet"});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY(c.hello(1));
        ConfigureMsg cfg{0.01};
        cfg.maxDeformation = 0.0; // "no limit" from the client: ignored
        cfg.maxForce = 0.0;
        cfg.maxIncrement = 0.0;
        QVERIFY(c.send(cfg));
        QVERIFY(c.expect<AckMsg>());
        std::mt19937_64 rng(141);
        double last = 0.0;
        int refused = 0, measured = 0;
        for (std::uint64_t n = 1, k = 0; k < 120; ++k) {
            const double d = nextTarget(rng, last, int(k));
            QVERIFY(c.send(TargetMsg{n, d}));
            const auto m = c.receive();
            QVERIFY(m);
            if (std::abs(d) > kLimit) {
                const auto* e = std::get_if<ErrorMsg>(&*m);
                QVERIFY2(e && e->code == ErrorCode::Interlock,
                         qPrintable(QString("target %1 was not refused").arg(d)));
                ++refused;
                QVERIFY(c.send(ResumeMsg{}));
                QVERIFY(c.expect<AckMsg>());
                continue;
            }
            const auto* mm = std::get_if<MeasurementMsg>(&*m);
            QVERIFY2(mm, qPrintable(QString("target %1 not measured").arg(d)));
            QVERIFY(std::abs(mm->commanded) <= kLimit && std::abs(mm->deformation) <= kLimit);
            QVERIFY(c.send(CommitMsg{n}));
            QVERIFY(c.expect<AckMsg>());
            last = d;
            ++n;
            ++measured;
        }
        QCOMPARE(refused, 20);
        QCOMPARE(measured, 100);
    }

    void openFrescoClientsCannotBypassTheLimits_data() {
        QTest::addColumn<QString>("protocol");
        QTest::newRow("simapp") << "simapp";
        QTest::newRow("generictcp") << "generictcp";
    }
    void openFrescoClientsCannotBypassTheLimits() {
        QFETCH(QString, protocol);
        ControllerProcess ctl({"--config", QString::fromStdString(m_config), "--pace", "fast",
                               "--protocol", protocol});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        OfControlOptions o;
        o.connectTimeout = kWait;
        o.stepDeadline = kWait;
        o.logConnect = false;
        const auto connect = [&]() -> std::unique_ptr<OpenFrescoControl> {
            if (protocol == "simapp")
                return std::make_unique<SimAppControl>("127.0.0.1", ctl.port(), "Element 1", o);
            return std::make_unique<GenericTcpControl>("127.0.0.1", ctl.port(), "Element 1", o);
        };
        std::mt19937_64 rng(142);
        int refused = 0, measured = 0;
        double last = 0.0;
        auto control = connect();
        QVERIFY(control->prepare(0.01).ok);
        for (int k = 0; k < 60; ++k) {
            const double d = nextTarget(rng, last, k);
            ControlMeasurement m;
            const bool ok = control->setTarget(d).ok && control->measure(m).ok;
            if (std::abs(d) > kLimit) {
                QVERIFY2(!ok, qPrintable(QString("target %1 was measured").arg(d)));
                ++refused;
                // The controller ended the session; a new one starts from a fresh specimen.
                control = connect();
                QVERIFY(control->prepare(0.01).ok);
                last = 0.0;
                continue;
            }
            QVERIFY2(ok, qPrintable(QString("target %1 not measured").arg(d)));
            QVERIFY2(std::abs(m.deformation) <= kLimit, qPrintable(QString::number(m.deformation)));
            QVERIFY(control->commit().ok);
            last = d;
            ++measured;
        }
        QCOMPARE(refused, 10);
        QCOMPARE(measured, 50);
        control.reset();
        ctl.stop();
        QVERIFY2(ctl.log().contains("interlock"), qPrintable(ctl.log()));
    }
};

QTEST_GUILESS_MAIN(TestControllerLimits)
#include "TestControllerLimits.moc"
