// Model updates reaching a running RTHS loop on a real hsmu-controller --rths process
// (docs/rths.md, "A damper and its twin"; docs/protocol.md, rths-update): benchmark case 1 at
// 1024 Hz with an MR damper in the specimen and its twin on floor 2.
//  - The monitor's rths-update reaches the loop before a tick K (rths-update-applied names it);
//    the controller's run equals the local run with the same update before the same tick, every
//    telemetry frame bit for bit. An update outside the parameter box, naming an unknown
//    parameter or carrying a NaN is refused at once (Error(UpdateRefused), the connection kept,
//    nothing applied) and the loop runs to its end.
//  - The online identification on the controller (fast pace): its updates and every telemetry
//    frame equal the local run's with the same identification, bit for bit.
#include "ControllerProcess.h"
#include "RawClient.h"

#include "core/config/RthsConfig.h"
#include "core/rths/RthsBenchmark.h"
#include "core/updating/TwinIdentification.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace hsmu;
using namespace hsmu::comms;

namespace {

/// A 1.5 Hz sine of up to 1.2 m/s^2 swelling and fading (period 4 s), sampled at 100 Hz.
QString writeSwellingSine(const QString& dir, double seconds) {
    const QString path = dir + QStringLiteral("/sine.txt");
    QFile f(path);
    f.open(QIODevice::WriteOnly | QIODevice::Text);
    QString text;
    for (int i = 0; i <= int(std::lround(seconds * 100)); ++i) {
        const double t = 0.01 * i;
        const double a = 1.2 * (0.6 - 0.4 * std::cos(2 * M_PI * t / 4.0)) * std::sin(2 * M_PI * 1.5 * t);
        text += QStringLiteral("%1 %2\n").arg(t, 0, 'g', 17).arg(a, 0, 'g', 17);
    }
    f.write(text.toUtf8());
    return path;
}

/// The configuration: the 0.88 V record's damper (N) in the specimen, the twin from the law's
/// defaults in its scales, alpha and c1 boxed; identification on or off.
QString writeConfig(const QString& dir, double seconds, bool identify) {
    const QString path = dir + QStringLiteral("/damper.json");
    QFile f(path);
    f.open(QIODevice::WriteOnly | QIODevice::Text);
    f.write(QStringLiteral(R"({"name": "MR damper on case 1", "rths": {"rate": 1024,
      "structure": {"benchmarkCase": 1, "specimenDof": 0},
      "sensors": {"noise": true, "seed": 5},
      "controller": {"kp": 2.0, "ki": 95.0},
      "compensation": {"type": "none", "lead": {"enabled": true}},
      "holdAfterMisses": 0,
      "damper": {"specimen": {"c0": 0.0236, "c1": 3.29, "k0": 0.016, "k1": 0.0083, "f0": -0.069,
                              "alpha": 72.1, "beta": 2.41, "gamma": 8.96, "n": 0.521,
                              "uRef": 0.0054, "fRef": 320},
                 "twin": {"uRef": 0.0054, "fRef": 320}, "twinDof": 1,
                 "bounds": {"alpha": [0, 500], "c1": [0.01, 100]},
                 "identification": {"enabled": %2, "decimation": 4, "interval": 1.0, "latency": 0.25}},
      "groundMotion": {"file": "%1", "scale": 1.0, "unit": "m/s^2"}}})")
                .arg(writeSwellingSine(dir, seconds), identify ? QStringLiteral("true") : QStringLiteral("false"))
                .toUtf8());
    return path;
}

/// The local run of the configuration (as `hsmu rths` and the controller prepare it).
rths::RthsRun localRun(const QString& config, rths::TwinUpdateSource* updates) {
    const RthsConfig cfg = loadRthsConfig(config.toStdString());
    rths::RthsSettings s = cfg.settings;
    rths::fitToNominalLoop(s);
    return rths::runRths(cfg.partition(), loadRthsGroundMotion(cfg, "", cfg.groundMotionScale), s,
                         nullptr, 0.0, nullptr, updates);
}

bool startRun(RawClient& c, std::uint32_t decimation) {
    if (!c.hello(7) || !c.send(RthsStartMsg{decimation, 0.0}))
        return false;
    for (;;) {
        const auto m = c.receive();
        if (!m)
            return false;
        if (const auto* a = std::get_if<AckMsg>(&*m))
            return a->acked == MessageType::RthsStart;
        if (!std::holds_alternative<TelemetryMsg>(*m))
            return false;
    }
}

struct Monitored {
    std::vector<TelemetryMsg> telemetry;
    std::vector<RthsUpdateAppliedMsg> updates;
    std::vector<ErrorMsg> errors;
    std::vector<AckMsg> acks;
    std::optional<RthsEndMsg> end;
};

/// Receive until rths-end; onFirst(client) once, after the first telemetry frame.
template <class OnFirst> Monitored monitor(RawClient& c, OnFirst onFirst) {
    Monitored m;
    for (int i = 0; i < 2000000 && !m.end; ++i) {
        const auto msg = c.receive();
        if (!msg)
            break;
        if (const auto* t = std::get_if<TelemetryMsg>(&*msg)) {
            m.telemetry.push_back(*t);
            if (m.telemetry.size() == 1)
                onFirst();
        } else if (const auto* u = std::get_if<RthsUpdateAppliedMsg>(&*msg)) {
            m.updates.push_back(*u);
        } else if (const auto* e = std::get_if<ErrorMsg>(&*msg)) {
            m.errors.push_back(*e);
        } else if (const auto* a = std::get_if<AckMsg>(&*msg)) {
            m.acks.push_back(*a);
        } else if (const auto* e = std::get_if<RthsEndMsg>(&*msg)) {
            m.end = *e;
        }
    }
    return m;
}

void sameTicks(const std::vector<TelemetryMsg>& tel, const rths::RthsRun& local) {
    QVERIFY(!tel.empty());
    for (const TelemetryMsg& t : tel) {
        const auto k = std::size_t(t.tick);
        QVERIFY(k < local.time.size());
        QVERIFY(t.desired == local.desired[k]);
        QVERIFY(t.command == local.command[k]);
        QVERIFY(t.measured == local.measured[k]);
        QVERIFY(t.force == local.force[k]);
    }
}

} // namespace

class TestRthsTwinUpdates : public QObject {
    Q_OBJECT
private slots:
    void theMonitorsUpdateReachesTheRunningLoop() {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 4.0, false);
        // The real-time pace: the run is still going when the first frame arrives.
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("realtime")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY2(startRun(c, 16), qPrintable(ctl.log()));
        const Monitored m = monitor(c, [&] {
            c.send(RthsUpdateMsg{{"alpha"}, {900.0}});              // outside the box
            c.send(RthsUpdateMsg{{"c9"}, {1.0}});                   // unknown
            c.send(RthsUpdateMsg{{"c0"}, {std::nan("")}});          // not finite
            c.send(RthsUpdateMsg{{"alpha", "c0"}, {80.0, 0.03}});   // applied
        });
        QVERIFY2(m.end.has_value(), qPrintable(ctl.log()));
        QCOMPARE(m.end->hold, std::string());
        QCOMPARE(m.end->ticks, std::uint64_t(4097));
        QCOMPARE(m.errors.size(), std::size_t(3));
        for (const ErrorMsg& e : m.errors) {
            QCOMPARE(e.code, ErrorCode::UpdateRefused);
            QVERIFY2(e.reason.find("nothing applied") != std::string::npos, e.reason.c_str());
        }
        QVERIFY(m.errors[0].reason.find("alpha = 900 is outside the parameter box [0, 500]") != std::string::npos);
        QVERIFY(m.errors[1].reason.find("'c9'") != std::string::npos);
        QVERIFY(m.errors[2].reason.find("'c0' is not finite") != std::string::npos);
        QCOMPARE(m.acks.size(), std::size_t(1));
        QCOMPARE(m.acks[0].acked, MessageType::RthsUpdate);
        QCOMPARE(m.updates.size(), std::size_t(1));
        const RthsUpdateAppliedMsg& u = m.updates[0];
        QVERIFY(u.applied);
        QCOMPARE(u.message, std::string("operator"));
        QVERIFY(u.tick > 0 && u.tick < 4097);
        QVERIFY2(ctl.waitForLog(QStringLiteral("damper twin updated before tick %1").arg(u.tick)), qPrintable(ctl.log()));
        // The local run with the same update before the same tick: the same ticks, bit for bit.
        rths::ScheduledTwinUpdates same({{u.names, u.values, "replay", long(u.tick)}});
        const rths::RthsRun local = localRun(cfg, &same);
        QCOMPARE(local.updates.size(), std::size_t(1));
        QVERIFY(local.twin && local.twin->alpha == 80.0 && local.twin->c0 == 0.03);
        sameTicks(m.telemetry, local);
        QCOMPARE(m.end->j[5], local.criteria.j[5]);
        // ... and it mattered: without it, floor 2 (the twin's storey) moves otherwise.
        const rths::RthsRun plain = localRun(cfg, nullptr);
        QVERIFY(plain.criteria.j[5] != local.criteria.j[5]);
    }

    void theControllersIdentificationEqualsTheLocalRun() {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 6.0, true);
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("fast")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY2(startRun(c, 8), qPrintable(ctl.log()));
        const Monitored m = monitor(c, [] {});
        QVERIFY2(m.end.has_value(), qPrintable(ctl.log()));
        QCOMPARE(m.end->hold, std::string());
        // The local run with the same identification (the simulated pace waits for it).
        const RthsConfig parsed = loadRthsConfig(cfg.toStdString());
        rths::TwinIdentificationSettings is = parsed.identification;
        is.wait = true;
        rths::TwinIdentification id(parsed.settings.damper, is, parsed.settings.rate);
        const rths::RthsRun local = localRun(cfg, &id);
        qInfo("%zu updates from the controller's identification, %zu locally", m.updates.size(),
              local.updates.size());
        QVERIFY(m.updates.size() >= 2);
        QCOMPARE(m.updates.size(), local.updates.size());
        for (std::size_t i = 0; i < m.updates.size(); ++i) {
            QVERIFY(m.updates[i].applied);
            QCOMPARE(m.updates[i].message, std::string("identification"));
            QCOMPARE(long(m.updates[i].tick), long(local.updates[i].step));
            QVERIFY(m.updates[i].values == local.updates[i].applied);
        }
        sameTicks(m.telemetry, local);
        for (int i = 0; i < 9; ++i)
            QCOMPARE(m.end->j[i], local.criteria.j[std::size_t(i)]);
    }
};

QTEST_GUILESS_MAIN(TestRthsTwinUpdates)
#include "TestRthsTwinUpdates.moc"
