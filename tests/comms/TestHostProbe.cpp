// The host probe (comms/rths/HostProbe.h) on an injected clock: empty ticks released by the
// real loop's pacer, each release's lateness binned, misses counted as the pacer counts them.
// No sleeping, no wall time: the clock is simulated and scripted.
#include "comms/rths/HostProbe.h"

#include <QtTest>

#include <map>

using namespace hsmu;
using namespace std::chrono;

namespace {

// sleepUntil() jumps to the release, late by the scripted amount for the k-th sleep.
class LateClock final : public comms::PaceClock {
public:
    explicit LateClock(std::map<int, nanoseconds> late) : m_late(std::move(late)) {}
    nanoseconds now() override { return m_now; }
    void sleepUntil(nanoseconds t) override
    {
        const auto it = m_late.find(m_sleeps++);
        m_now = std::max(m_now, t + (it == m_late.end() ? nanoseconds(0) : it->second));
    }

private:
    nanoseconds m_now{5'000'000'000};
    int m_sleeps = 0;
    std::map<int, nanoseconds> m_late;
};

} // namespace

class TestHostProbe : public QObject {
    Q_OBJECT
private slots:
    void punctualHostHasNoMiss()
    {
        LateClock clock({});
        const auto r = comms::probeHost(clock, 1.0 / 4096.0, 4096);
        QCOMPARE(r.ticks, 4096L);
        QCOMPARE(r.misses, 0L);
        QCOMPARE(r.histogram[0], 4096L);
        QCOMPARE(r.worstRelease, 0.0);
    }

    // Releases of ticks 10, 20, 30, 40, 50 late by 30, 80, 200, 300 and 600 us at 4096 Hz
    // (period h = 244.141 us): a late release also delays the ticks after it (the schedule is
    // absolute): tick 41 comes 300 - h = 55.9 us late, tick 51 600 - h = 355.9 us and tick 52
    // 600 - 2h = 111.7 us. A tick whose release comes later than h ends past its deadline:
    // ticks 40 (55.9 us past), 50 (355.9 us) and 51 (111.7 us) are the misses.
    void lateReleasesAreBinnedAndCounted()
    {
        LateClock clock({{10, microseconds(30)}, {20, microseconds(80)}, {30, microseconds(200)},
                         {40, microseconds(300)}, {50, microseconds(600)}});
        const auto r = comms::probeHost(clock, 1.0 / 4096.0, 100);
        QCOMPARE(r.ticks, 100L);
        QCOMPARE(r.histogram[1], 1L); // tick 10
        QCOMPARE(r.histogram[2], 2L); // ticks 20, 41
        QCOMPARE(r.histogram[3], 2L); // ticks 30, 52
        QCOMPARE(r.histogram[4], 2L); // ticks 40, 51
        QCOMPARE(r.histogram[5], 1L); // tick 50
        QCOMPARE(r.histogram[0], 92L);
        QCOMPARE(r.misses, 3L);
        QVERIFY(std::abs(r.worstLateness - 355.859e-6) < 1e-12);
        QVERIFY(std::abs(r.worstRelease - 600e-6) < 1e-12);
        const std::string line = comms::describeHostProbe(r, 1.0 / 4096.0);
        QVERIFY2(line.find("100 ticks of 244.1 us: 3 deadline misses (worst 355.9 us") == 0, line.c_str());
        QVERIFY2(line.find("more 1 (worst 600.0 us)") != std::string::npos, line.c_str());
    }
};

QTEST_APPLESS_MAIN(TestHostProbe)
#include "TestHostProbe.moc"
