// hsmu-controller --rths (docs/rths.md, "The loop on the controller"): a real controller
// process runs the RTHS loop; the test is its monitor over the native protocol (RawClient).
// At the fast pace the controller's run equals core's runRths of the same configuration in
// this process (the local `hsmu rths`): every telemetry frame's tick, desired, command,
// measured and force, and the end's J1..J9 bit for bit (the same code, the same noise seed;
// the protocol carries binary64). Telemetry: one frame every decimation ticks, none dropped.
// Holds (hold, emergency hold, the monitor's link lost) hold the loop before a tick, the end
// says so and carries the ticks before it; they are asked after the first telemetry frame,
// on a 30 s record at the real-time pace (so the run is still going; nothing is timed).
// --record DIR: the controller writes every tick of each run to DIR/record.h5 through core's
// RthsRecord writer (the second run to record-2.h5): its rows are the local run's ticks bit
// for bit (time, desired, command, measured, force, floors), a hold is its critical alarm at
// the last tick; --record without --rths is refused.
// A 2 s real-time run reports its deadline misses (printed, not asserted: the machine is
// shared).
// Resume (docs/rths.md, "Hold and resume"): a fast run held by the monitor before tick K and
// resumed goes on from K: every tick's telemetry once (0..K-1 before the hold, K.. after), the
// second end's J1..J9 equal the unheld local run's bit for bit, its record every tick once
// with the hold's alarm at K-1 and the resume's note at K; a stroke-limit hold's resume is
// refused (Error(holding), the channel named) and the run stays held; resume with no held run
// is a protocol violation.
#include "ControllerProcess.h"
#include "RawClient.h"

#include "core/config/RthsConfig.h"
#include "core/record/RecordReader.h"
#include "core/rths/RthsBenchmark.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace hsmu;
using namespace hsmu::comms;

namespace {

/// A 2 Hz sine of 0.8 m/s^2 over `seconds`, sampled at 100 Hz.
QString writeSine(const QString& dir, double seconds) {
    const QString path = dir + QStringLiteral("/sine.txt");
    QFile f(path);
    f.open(QIODevice::WriteOnly | QIODevice::Text);
    QString text;
    for (int i = 0; i <= int(std::lround(seconds * 100)); ++i) {
        const double t = 0.01 * i;
        text += QStringLiteral("%1 %2\n").arg(t, 0, 'g', 17).arg(0.8 * std::sin(2 * M_PI * 2.0 * t), 0, 'g', 17);
    }
    f.write(text.toUtf8());
    return path;
}

/// limits: "" or the configuration's "limits" object's members (e.g. "\"stroke\": 1e-4").
QString writeConfig(const QString& dir, double seconds, const QString& limits = {}) {
    const QString path = dir + QStringLiteral("/rths.json");
    QFile f(path);
    f.open(QIODevice::WriteOnly | QIODevice::Text);
    f.write(QStringLiteral(R"({"name": "sine on case 1", "rths": {"rate": 1024,
      "structure": {"benchmarkCase": 1, "specimenDof": 0},
      "sensors": {"noise": true, "seed": 3},
      "controller": {"kp": 2.0, "ki": 95.0},
      "compensation": {"type": "ats", "lead": {"enabled": true}, "fitToLoop": true},
      "holdAfterMisses": 0,%2
      "groundMotion": {"file": "%1", "scale": 1.0, "unit": "m/s^2"}}})")
                .arg(writeSine(dir, seconds))
                .arg(limits.isEmpty() ? QString() : QStringLiteral(" \"limits\": {%1},").arg(limits))
                .toUtf8());
    return path;
}

/// The local run: what `hsmu rths CONFIG` runs (RthsCommand: load, fitToNominalLoop, runRths).
rths::RthsRun localRun(const QString& config) {
    const RthsConfig cfg = loadRthsConfig(config.toStdString());
    rths::RthsSettings s = cfg.settings;
    rths::fitToNominalLoop(s);
    return rths::runRths(cfg.partition(), loadRthsGroundMotion(cfg, "", cfg.groundMotionScale), s);
}

struct Monitored {
    std::vector<TelemetryMsg> telemetry;
    std::optional<RthsEndMsg> end;
};

/// Receive telemetry until rths-end (bounded); onFirst runs once, after the first frame.
template <class OnFirst> Monitored monitor(RawClient& c, OnFirst onFirst) {
    Monitored m;
    for (int i = 0; i < 1000000 && !m.end; ++i) {
        const auto msg = c.receive();
        if (!msg)
            break;
        if (const auto* t = std::get_if<TelemetryMsg>(&*msg)) {
            m.telemetry.push_back(*t);
            if (m.telemetry.size() == 1)
                onFirst();
        } else if (const auto* e = std::get_if<RthsEndMsg>(&*msg)) {
            m.end = *e;
        }
    }
    return m;
}

bool startRun(RawClient& c, std::uint32_t decimation, double duration = 0.0) {
    if (!c.hello(7) || !c.send(RthsStartMsg{decimation, duration}))
        return false;
    for (;;) { // the ack, possibly after telemetry already on its way
        const auto m = c.receive();
        if (!m)
            return false;
        if (const auto* a = std::get_if<AckMsg>(&*m))
            return a->acked == MessageType::RthsStart;
        if (!std::holds_alternative<TelemetryMsg>(*m))
            return false;
    }
}

/// Every telemetry frame equals the local run's tick, bit for bit.
void sameTicks(const std::vector<TelemetryMsg>& tel, const rths::RthsRun& local) {
    for (const TelemetryMsg& t : tel) {
        const auto k = std::size_t(t.tick);
        QVERIFY(k < local.time.size());
        QCOMPARE(t.time, local.time[k]);
        QVERIFY(t.desired == local.desired[k]);
        QVERIFY(t.command == local.command[k]);
        QVERIFY(t.measured == local.measured[k]);
        QVERIFY(t.force == local.force[k]);
    }
}

} // namespace

class TestRthsController : public QObject {
    Q_OBJECT
private slots:
    void fastPaceRunEqualsTheLocalRun() {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 3.0);
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("fast")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY2(startRun(c, 8), qPrintable(ctl.log()));
        const Monitored m = monitor(c, [] {});
        QVERIFY2(m.end.has_value(), qPrintable(ctl.log()));
        const rths::RthsRun local = localRun(cfg);
        QVERIFY(local.hold.empty());
        QCOMPARE(m.end->hold, std::string());
        QCOMPARE(m.end->ticks, std::uint64_t(local.time.size())); // 3 s at 1024 Hz: 3073
        QCOMPARE(local.time.size(), std::size_t(3073));
        for (int i = 0; i < 9; ++i)
            QVERIFY2(m.end->j[i] == local.criteria.j[std::size_t(i)], qPrintable(QStringLiteral("J%1: %2 vs %3").arg(i + 1).arg(m.end->j[i], 0, 'g', 17).arg(local.criteria.j[std::size_t(i)], 0, 'g', 17)));
        QVERIFY(m.end->peakStroke == local.peakStroke && m.end->peakForce == local.peakForce);
        QVERIFY(m.end->trackingIndicator == local.trackingIndicator);
        // One frame at every 8th tick (0, 8, ..., 3072): ceil(3073 / 8) = 385, none dropped.
        QCOMPARE(m.telemetry.size(), std::size_t(385));
        for (std::size_t i = 0; i < m.telemetry.size(); ++i)
            QCOMPARE(m.telemetry[i].tick, std::uint64_t(8 * i));
        QCOMPARE(m.end->telemetrySent, std::uint64_t(385));
        QCOMPARE(m.end->telemetryDropped, std::uint64_t(0));
        QCOMPARE(m.end->misses, std::uint64_t(0));
        sameTicks(m.telemetry, local);
        // A second run on the same controller is the same run again.
        QVERIFY(c.send(RthsStartMsg{0, 1.0}));
        const Monitored again = monitor(c, [] {});
        QVERIFY(again.end.has_value());
        QCOMPARE(again.end->ticks, std::uint64_t(1025));
        QCOMPARE(again.telemetry.size(), std::size_t(129)); // default: 1024 / 128 = every 8th
        sameTicks(again.telemetry, local);
    }

    void holdFromTheMonitorHoldsTheLoopAtATick() { holdAndCheck(false); }
    void emergencyHoldHoldsTheLoopAtATick() { holdAndCheck(true); }

    void aLostMonitorHoldsTheLoop() {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 30.0);
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("realtime")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY(startRun(c, 8));
        QVERIFY(c.expect<TelemetryMsg>().has_value());
        c.close();
        QVERIFY2(ctl.waitForLog(QStringLiteral("RTHS run ended")), qPrintable(ctl.log()));
        const QString log = ctl.log();
        QVERIFY2(log.contains(QStringLiteral("monitor link lost")) &&
                     log.contains(QStringLiteral("the loop holds before its next tick")),
                 qPrintable(log));
        const QRegularExpression ended(QStringLiteral("RTHS run ended after (\\d+) ticks;.*monitor link lost \\([^)]*\\) before tick (\\d+)"));
        const auto match = ended.match(log);
        QVERIFY2(match.hasMatch(), qPrintable(log));
        QCOMPARE(match.captured(1).toLong(), match.captured(2).toLong());
        QVERIFY(match.captured(1).toLong() < 30 * 1024);
    }

    void aLostMonitorCanBeLetGo() {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 3.0);
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("realtime"),
                               QStringLiteral("--monitor-loss"), QStringLiteral("continue")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY(startRun(c, 8));
        QVERIFY(c.expect<TelemetryMsg>().has_value());
        c.close();
        QVERIFY2(ctl.waitForLog(QStringLiteral("RTHS run ended")), qPrintable(ctl.log()));
        const QString log = ctl.log();
        QVERIFY2(log.contains(QStringLiteral("the loop goes on (--monitor-loss continue)")), qPrintable(log));
        QVERIFY2(log.contains(QStringLiteral("RTHS run ended after 3073 ticks")), qPrintable(log));
        QVERIFY(!log.contains(QStringLiteral("test held")));
    }

    void realtimeRunReportsItsDeadlineMisses() {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 2.0);
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("realtime"),
                               QStringLiteral("--realtime-priority"), QStringLiteral("80")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY(startRun(c, 8));
        const Monitored m = monitor(c, [] {});
        QVERIFY2(m.end.has_value(), qPrintable(ctl.log()));
        QCOMPARE(m.end->hold, std::string()); // holdAfterMisses 0: misses never hold this run
        QCOMPARE(m.end->ticks, std::uint64_t(2049));
        QCOMPARE(m.telemetry.size() + m.end->telemetryDropped, std::size_t(257));
        const rths::RthsRun local = localRun(cfg);
        sameTicks(m.telemetry, local); // the wall clock paces the same ticks
        qInfo("real-time 2 s at 1024 Hz: %llu deadline misses, worst %.1f us late (%s)",
              static_cast<unsigned long long>(m.end->misses), m.end->worstLateness * 1e6,
              ctl.log().contains(QStringLiteral("priority not taken")) ? "normal priority" : "SCHED_FIFO 80");
    }

    void recordHoldsEveryTickOfTheControllersRun() {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 3.0);
        const QString out = dir.path() + QStringLiteral("/records");
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("fast"),
                               QStringLiteral("--record"), out});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY2(startRun(c, 64), qPrintable(ctl.log()));
        const Monitored m = monitor(c, [] {});
        QVERIFY2(m.end.has_value(), qPrintable(ctl.log()));
        QVERIFY2(ctl.waitForLog(QStringLiteral("record: ")), qPrintable(ctl.log()));
        const rths::RthsRun local = localRun(cfg);
        {
            const RecordReader reader((out + QStringLiteral("/record.h5")).toStdString());
            const RecordData& d = reader.data();
            QCOMPARE(d.rows(), int(local.time.size())); // 3073: every tick, not every 64th
            QCOMPARE(d.meta.configName, std::string("sine on case 1"));
            QVERIFY(d.meta.configuration.find("\"benchmarkCase\":1") != std::string::npos);
            QVERIFY(d.alarms.empty());
            for (int k = 0; k < d.rows(); ++k) {
                const auto i = std::size_t(k);
                QCOMPARE(d.steps[i], k);
                QVERIFY(d.time(k) == local.time[i]);
                QVERIFY(d.commanded(k, 0) == local.desired[i]);
                QVERIFY(d.actuatorCommanded(k, 0) == local.command[i]);
                QVERIFY(d.deformation(k, 0) == local.measured[i]);
                QVERIFY(d.force(k, 0) == local.force[i]);
                for (int f = 0; f < 3; ++f) {
                    QVERIFY(d.u(k, f) == local.hybrid(k, f));
                    QVERIFY(d.u(k, 3 + f) == local.reference(k, f));
                }
            }
        }
        // A second run (1 s) on the same controller: record-2.h5, the first run's beginning.
        QVERIFY(c.send(RthsStartMsg{0, 1.0}));
        const Monitored again = monitor(c, [] {});
        QVERIFY(again.end.has_value());
        QVERIFY2(ctl.waitForLog(QStringLiteral("record-2.h5")), qPrintable(ctl.log()));
        {
            const RecordReader reader((out + QStringLiteral("/record-2.h5")).toStdString());
            QCOMPARE(reader.data().rows(), 1025);
            for (int k = 0; k < reader.data().rows(); ++k)
                QVERIFY(reader.data().deformation(k, 0) == local.measured[std::size_t(k)]);
        }
        // Another controller, real-time pace, the same folder: record-3.h5 (nothing of the
        // earlier records overwritten), held by the monitor: its ticks before the hold and
        // the hold as a critical alarm at the last tick.
        QTemporaryDir dir30;
        const QString cfg30 = writeConfig(dir30.path(), 30.0);
        ControllerProcess rt({QStringLiteral("--rths"), cfg30, QStringLiteral("--pace"), QStringLiteral("realtime"),
                              QStringLiteral("--record"), out});
        QVERIFY2(rt.start(), qPrintable(rt.log()));
        RawClient c2;
        QVERIFY(c2.connect(rt.port()));
        QVERIFY(startRun(c2, 8));
        const Monitored held = monitor(c2, [&] { c2.send(HoldMsg{"operator"}); });
        QVERIFY(held.end.has_value());
        QVERIFY2(!held.end->hold.empty(), qPrintable(rt.log()));
        QVERIFY2(rt.waitForLog(QStringLiteral("record-3.h5")), qPrintable(rt.log()));
        const RecordReader third((out + QStringLiteral("/record-3.h5")).toStdString());
        const RecordData& d = third.data();
        QCOMPARE(d.rows(), int(held.end->ticks));
        QVERIFY(d.rows() < 30 * 1024);
        QCOMPARE(d.alarms.size(), std::size_t(1));
        QCOMPARE(d.alarms.front().severity, AlarmSeverity::Critical);
        QCOMPARE(d.alarms.front().kind, AlarmKind::OperatorHold);
        QCOMPARE(d.alarms.front().message, held.end->hold);
        QCOMPARE(d.alarms.front().step, d.rows() - 1);
        const rths::RthsRun local30 = localRun(cfg30);
        for (int k = 0; k < d.rows(); ++k)
            QVERIFY(d.deformation(k, 0) == local30.measured[std::size_t(k)]);
        QCOMPARE(RecordReader((out + QStringLiteral("/record.h5")).toStdString()).data().rows(), 3073);
    }

    void aHeldRunResumesWhereItHeld() {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 10.0);
        const QString out = dir.path() + QStringLiteral("/records");
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("fast"),
                               QStringLiteral("--record"), out});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY(c.hello(7));
        QVERIFY(c.send(ResumeMsg{}));
        const auto none = c.expect<ErrorMsg>();
        QVERIFY(none.has_value());
        QCOMPARE(none->code, ErrorCode::ProtocolViolation);
        QVERIFY2(none->reason.find("no held RTHS run") != std::string::npos, none->reason.c_str());
        // Every tick a frame: the fast pace waits for this monitor once half the ring is full,
        // so the hold sent after the first frame comes within the run.
        QVERIFY(c.send(RthsStartMsg{1, 0.0}));
        const Monitored first = monitor(c, [&] { c.send(HoldMsg{"operator"}); });
        QVERIFY2(first.end.has_value(), qPrintable(ctl.log()));
        const long held = long(first.end->ticks);
        QVERIFY2(first.end->hold.rfind("console hold (operator) before tick " + std::to_string(held), 0) == 0,
                 first.end->hold.c_str());
        QVERIFY(held > 0 && held < 10241);
        QVERIFY2(ctl.waitForLog(QStringLiteral("held: the ticks after a resume follow")), qPrintable(ctl.log()));
        QVERIFY(c.send(ResumeMsg{}));
        Monitored second;
        for (int i = 0; i < 1000000 && !second.end; ++i) { // the ack, telemetry, the end
            const auto msg = c.receive();
            QVERIFY2(msg.has_value(), qPrintable(ctl.log()));
            if (const auto* a = std::get_if<AckMsg>(&*msg))
                QCOMPARE(a->acked, MessageType::Resume);
            else if (const auto* t = std::get_if<TelemetryMsg>(&*msg))
                second.telemetry.push_back(*t);
            else if (const auto* e = std::get_if<RthsEndMsg>(&*msg))
                second.end = *e;
            else
                QFAIL("unexpected message after resume");
        }
        QVERIFY2(second.end.has_value(), qPrintable(ctl.log()));
        QCOMPARE(second.end->hold, std::string());
        QCOMPARE(second.end->ticks, std::uint64_t(10241));
        QVERIFY2(ctl.waitForLog(QStringLiteral("RTHS run resumed before tick %1").arg(held)), qPrintable(ctl.log()));
        // Every tick once, in order, across the hold.
        std::vector<TelemetryMsg> all = first.telemetry;
        all.insert(all.end(), second.telemetry.begin(), second.telemetry.end());
        QCOMPARE(all.size(), std::size_t(10241));
        for (std::size_t i = 0; i < all.size(); ++i)
            QCOMPARE(all[i].tick, std::uint64_t(i));
        const rths::RthsRun local = localRun(cfg);
        sameTicks(all, local);
        for (int i = 0; i < 9; ++i)
            QVERIFY2(second.end->j[i] == local.criteria.j[std::size_t(i)], qPrintable(QStringLiteral("J%1").arg(i + 1)));
        QVERIFY(second.end->peakStroke == local.peakStroke && second.end->trackingIndicator == local.trackingIndicator);
        QVERIFY2(ctl.waitForLog(QStringLiteral("record.h5 (10241 ticks)")), qPrintable(ctl.log()));
        const RecordReader reader((out + QStringLiteral("/record.h5")).toStdString());
        const RecordData& d = reader.data();
        QCOMPARE(d.rows(), 10241);
        for (int k = 0; k < d.rows(); ++k) {
            QCOMPARE(d.steps[std::size_t(k)], k);
            QVERIFY(d.deformation(k, 0) == local.measured[std::size_t(k)]);
        }
        QCOMPARE(d.alarms.size(), std::size_t(1));
        QCOMPARE(d.alarms.front().kind, AlarmKind::OperatorHold);
        QCOMPARE(d.alarms.front().step, int(held - 1));
        QCOMPARE(d.notes.size(), std::size_t(1));
        QCOMPARE(d.notes.front().step, int(held));
        QVERIFY2(d.notes.front().text.rfind("resumed before tick " + std::to_string(held), 0) == 0,
                 d.notes.front().text.c_str());
    }

    void aLimitHoldDoesNotResumeIntoTheBreach() {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 3.0, QStringLiteral("\"stroke\": 1e-4"));
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("fast")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY(startRun(c, 8));
        const Monitored m = monitor(c, [] {});
        QVERIFY2(m.end.has_value(), qPrintable(ctl.log()));
        QVERIFY2(m.end->hold.find("stroke limit") != std::string::npos, m.end->hold.c_str());
        QVERIFY(c.send(ResumeMsg{}));
        const auto refused = c.expect<ErrorMsg>();
        QVERIFY2(refused.has_value(), qPrintable(ctl.log()));
        QCOMPARE(refused->code, ErrorCode::Holding);
        QVERIFY2(refused->reason.rfind("resume refused: ", 0) == 0 &&
                     refused->reason.find("stroke limit") != std::string::npos,
                 refused->reason.c_str());
        // Still held: refused again; a new run starts from rest.
        QVERIFY(c.send(ResumeMsg{}));
        QCOMPARE(c.expect<ErrorMsg>()->code, ErrorCode::Holding);
        QVERIFY(c.send(RthsStartMsg{8, 0.0}));
        QVERIFY(c.expect<AckMsg>().has_value());
        const Monitored again = monitor(c, [] {});
        QVERIFY(again.end.has_value());
        QCOMPARE(again.end->ticks, m.end->ticks);
        QCOMPARE(again.end->hold, m.end->hold);
    }

    void recordWithoutRthsIsRefused() {
        ControllerProcess ctl({QStringLiteral("--config"), QStringLiteral("paper-condition-3"),
                               QStringLiteral("--record"), QStringLiteral("/tmp")});
        QVERIFY(!ctl.start());
        QVERIFY2(ctl.log().contains(QStringLiteral("--record DIR applies to --rths")), qPrintable(ctl.log()));
    }

private:
    void holdAndCheck(bool emergency) {
        QTemporaryDir dir;
        const QString cfg = writeConfig(dir.path(), 30.0);
        ControllerProcess ctl({QStringLiteral("--rths"), cfg, QStringLiteral("--pace"), QStringLiteral("realtime")});
        QVERIFY2(ctl.start(), qPrintable(ctl.log()));
        RawClient c;
        QVERIFY(c.connect(ctl.port()));
        QVERIFY(startRun(c, 8));
        const Monitored m = monitor(c, [&] {
            if (emergency)
                c.send(EmergencyHoldMsg{"operator"});
            else
                c.send(HoldMsg{"operator"});
        });
        QVERIFY2(m.end.has_value(), qPrintable(ctl.log()));
        const std::string what = emergency ? "emergency hold (operator)" : "console hold (operator)";
        QVERIFY2(m.end->hold.rfind(what + " before tick " + std::to_string(m.end->ticks) + " (t = ", 0) == 0,
                 m.end->hold.c_str());
        QVERIFY(m.end->hold.find("test held") != std::string::npos);
        QVERIFY(m.end->ticks > m.telemetry.front().tick && m.end->ticks < 30 * 1024);
        QVERIFY(!m.telemetry.empty());
        for (const TelemetryMsg& t : m.telemetry)
            QVERIFY(t.tick < m.end->ticks);
        QVERIFY2(ctl.waitForLog(QString::fromStdString(what + ": the loop holds before its next tick")), qPrintable(ctl.log()));
        // What ran before the hold is the local run's beginning.
        sameTicks(m.telemetry, localRun(cfg));
    }
};

QTEST_GUILESS_MAIN(TestRthsController)
#include "TestRthsController.moc"
