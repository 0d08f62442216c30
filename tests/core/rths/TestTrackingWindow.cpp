// The live tracking estimates (docs/rths.md, "Live tracking", M1, M2, M7) and their thresholds
// on signals whose answers are known in closed form: y = A sin(2 pi f t), xm = g y(t - d h).
#include "core/rths/TrackingAlarms.h"
#include "core/rths/TrackingWindow.h"

#include <QtTest>

#include <cmath>
#include <stdexcept>
#include <vector>

using namespace hsmu;
using namespace hsmu::rths;

namespace {
const double kH = 1.0 / 4096.0;
const double kF = 2.0; // [Hz]: a 1 s window holds two whole periods

double y(long k) { return 0.002 * std::sin(2 * M_PI * kF * double(k) * kH); }

/// Feed ticks from..to-1 of xm = gain y(k - delayTicks); the estimates made, in order.
std::vector<TrackingEstimate> feed(TrackingWindow& w, long from, long to, double delayTicks, double gain)
{
    std::vector<TrackingEstimate> out;
    for (long k = from; k < to; ++k) {
        const double t = (double(k) - delayTicks) * kH;
        if (w.add(k, y(k), gain * 0.002 * std::sin(2 * M_PI * kF * t)))
            out.push_back(w.last());
    }
    return out;
}

TrackingEstimate at(double delay, double j2)
{
    TrackingEstimate e;
    e.delay = delay;
    e.j2 = j2;
    return e;
}
} // namespace

class TestTrackingWindow : public QObject {
    Q_OBJECT

private slots:
    void delayAndAmplitudeOfADelayedScaledSine()
    {
        // 19 ticks (4.639 ms) late at 0.9 of the amplitude: the window finds the delay within
        // 0.05 ms (the parabola through the correlation's peak) and the gain within 1e-6.
        TrackingWindow w(kH, {1.0, 0.1, 0.05});
        const auto est = feed(w, 0, 3 * 4096, 19.0, 0.9);
        QVERIFY(!est.empty());
        for (const auto& e : est) {
            QVERIFY2(std::abs(e.delay - 19e3 * kH) < 0.05, qPrintable(QString::number(e.delay)));
            QVERIFY2(std::abs(e.amplitude - 0.9) < 1e-6, qPrintable(QString::number(e.amplitude, 'g', 10)));
            QVERIFY(std::abs(e.amplitudeError + 10.0) < 1e-4);
        }
    }

    void fractionalDelayWithinTheParabolasTolerance()
    {
        // 4.6 ms = 18.84 ticks, unit gain: delay within 0.05 ms, gain within 1e-3 (the shift is
        // rounded to 19 ticks: cos(2 pi f 0.16 h) = 1 - 3e-8), J2 = 200 sin(pi f tau) % within 0.02.
        TrackingWindow w(kH, {1.0, 0.25, 0.05});
        const auto est = feed(w, 0, 2 * 4096, 4.6e-3 / kH, 1.0);
        QVERIFY(!est.empty());
        const double j2 = 200.0 * std::sin(M_PI * kF * 4.6e-3);
        for (const auto& e : est) {
            QVERIFY(std::abs(e.delay - 4.6) < 0.05);
            QVERIFY(std::abs(e.amplitude - 1.0) < 1e-3);
            QVERIFY2(std::abs(e.j2 - j2) < 0.02, qPrintable(QString("%1 vs %2").arg(e.j2).arg(j2)));
        }
    }

    void theWindowFollowsAChange()
    {
        // 10 ticks late for 2 s, then 30 ticks late at 1.1: once a whole window has passed the
        // change, the estimates read the new delay and gain.
        TrackingWindow w(kH, {1.0, 0.1, 0.05});
        const auto before = feed(w, 0, 2 * 4096, 10.0, 1.0);
        QVERIFY(std::abs(before.back().delay - 10e3 * kH) < 0.05);
        const auto after = feed(w, 2 * 4096, 4 * 4096, 30.0, 1.1);
        QVERIFY(after.back().tick >= 3 * 4096);
        QVERIFY(std::abs(after.back().delay - 30e3 * kH) < 0.05);
        QVERIFY(std::abs(after.back().amplitude - 1.1) < 1e-6);
    }

    void oneEstimatePerInterval()
    {
        // No estimate before the window is full (4096 ticks), then one every 0.1 s (410 ticks).
        TrackingWindow w(kH, {1.0, 0.1, 0.05});
        const auto est = feed(w, 0, 4095, 0.0, 1.0);
        QVERIFY(est.empty());
        QVERIFY(!w.hasEstimate());
        const auto more = feed(w, 4095, 4095 + 4100, 0.0, 1.0);
        QCOMPARE(more.size(), std::size_t(10)); // at 4095, 4505, ..., 7785; 8195 is past
        QCOMPARE(more.front().tick, 4095L);
        QCOMPARE(more[1].tick, 4095L + 410);
        QCOMPARE(more.front().time, 4095 * kH);
    }

    void badSettingsAreRefused()
    {
        QVERIFY(checkTrackingWindow({1.0, 0.1, 0.05}, kH).empty());
        QVERIFY(!checkTrackingWindow({1.0, 0.1, 0.05}, 0.0).empty());
        QVERIFY(checkTrackingWindow({0.0, 0.1, 0.05}, kH).find("window") != std::string::npos);
        QVERIFY(checkTrackingWindow({1.0, -1.0, 0.05}, kH).find("interval") != std::string::npos);
        QVERIFY(checkTrackingWindow({1.0, 0.1, 0.6}, kH).find("maxDelay") != std::string::npos);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, TrackingWindow(kH, {1.0, 0.1, NAN}));
    }

    void amplitudeRatioOfWholeHistories()
    {
        std::vector<double> a{1, 2, 3, 4}, b{0, 2, 4, 6};
        QCOMPARE(amplitudeRatio(a, b, 1), 2.0); // b[k] = 2 a[k-1]
        QVERIFY(std::isnan(amplitudeRatio({0, 0}, {1, 1}, 0)));
    }

    void alarmsRiseOncePerExcursion()
    {
        // J2 3, 6, 12, 12, 7, 3, 6 % against warning 5, critical 10: a warning at 6, a critical
        // at 12, nothing while it stays or falls back to the warning band (7 < 9: left), a
        // warning again at 6 after 3 (< 4.5: left).
        TrackingAlarms alarms({100.0, 200.0, 5.0, 10.0});
        std::vector<std::vector<Alarm>> raised;
        for (double j2 : {3.0, 6.0, 12.0, 12.0, 7.0, 3.0, 6.0}) {
            std::vector<Alarm> out;
            alarms.judge(at(0.0, j2), out);
            raised.push_back(out);
        }
        const std::vector<int> count{0, 1, 1, 0, 0, 0, 1};
        for (std::size_t i = 0; i < count.size(); ++i)
            QCOMPARE(int(raised[i].size()), count[i]);
        QCOMPARE(raised[1][0].severity, AlarmSeverity::Warning);
        QCOMPARE(raised[1][0].kind, AlarmKind::TrackingError);
        QCOMPARE(raised[1][0].code, std::string("rths-j2-warning"));
        QCOMPARE(raised[1][0].args, (std::vector<std::string>{"6.00", "5.00"}));
        QCOMPARE(raised[2][0].severity, AlarmSeverity::Critical);
        QCOMPARE(raised[2][0].code, std::string("rths-j2-critical"));
        QCOMPARE(raised[6][0].severity, AlarmSeverity::Warning);
        QCOMPARE(alarms.j2Level(), 1);
    }

    void anIndexHoveringAtAThresholdRaisesOneAlarm()
    {
        // J2 around the 10 % critical: 10.5, 9.5, 10.4, 9.1, 10.2 stay critical (left only below
        // 9 %); 8.9 leaves it (to the warning band), 10.3 raises a second critical.
        TrackingAlarms alarms({100.0, 200.0, 5.0, 10.0});
        int critical = 0;
        for (double j2 : {10.5, 9.5, 10.4, 9.1, 10.2, 8.9, 10.3}) {
            std::vector<Alarm> out;
            alarms.judge(at(0.0, j2), out);
            for (const Alarm& a : out)
                critical += a.severity == AlarmSeverity::Critical;
            QVERIFY(out.size() <= 1);
        }
        QCOMPARE(critical, 2);
        // The warning band the same way: 5.2 warns, 4.6 keeps it, 4.4 leaves it, 5.1 warns again.
        TrackingAlarms w({100.0, 200.0, 5.0, 10.0});
        std::vector<Alarm> out;
        for (double j2 : {5.2, 4.6, 5.3, 4.4, 5.1})
            w.judge(at(0.0, j2), out);
        QCOMPARE(out.size(), std::size_t(2));
    }

    void aDelayStraightToCriticalRaisesOneAlarm()
    {
        TrackingAlarms alarms({2.0, 5.0, 50.0, 60.0});
        std::vector<Alarm> out;
        TrackingEstimate e = at(6.2, 1.0);
        e.tick = 8191;
        e.time = 8191 * kH;
        alarms.judge(e, out);
        QCOMPARE(out.size(), std::size_t(1));
        QCOMPARE(out[0].severity, AlarmSeverity::Critical);
        QCOMPARE(out[0].step, 8191);
        QCOMPARE(out[0].time, 8191 * kH);
        QVERIFY(out[0].message.find("6.20 ms") != std::string::npos);
        QCOMPARE(alarms.j1Level(), 2);
    }

    void thresholdsChangeAtTheNextEstimateAndBadOnesAreRefused()
    {
        TrackingAlarms alarms;
        std::vector<Alarm> out;
        alarms.judge(at(1.0, 1.0), out);
        QVERIFY(out.empty());
        alarms.setLimits({0.5, 5.0, 0.5, 10.0});
        alarms.judge(at(1.0, 1.0), out);
        QCOMPARE(out.size(), std::size_t(2)); // J1 then J2, both warnings
        QCOMPARE(out[0].code, std::string("rths-j1-warning"));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, alarms.setLimits({3.0, 2.0, 1.0, 2.0}));
        QCOMPARE(alarms.limits().j1Warning, 0.5); // kept
        QVERIFY(!checkTrackingLimits({1.0, 2.0, -1.0, 2.0}).empty());
        QVERIFY(checkTrackingLimits({1.0, 2.0, 3.0, 2.0}).find("J2") != std::string::npos);
    }
};

QTEST_APPLESS_MAIN(TestTrackingWindow)
#include "TestTrackingWindow.moc"
