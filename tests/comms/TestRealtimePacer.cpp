// The real-time pace of the RTHS loop (comms/rths/RealtimePacer.h) on an injected clock: absolute
// release times, deadline misses counted with their lateness, the hold after N misses naming
// the tick; then a whole paced run on the benchmark loop that holds on its misses and keeps
// every tick before the hold. No sleeping, no wall time: the clock is simulated.
#include "comms/rths/RealtimePacer.h"
#include "core/rths/RthsRunner.h"

#include <QtTest>

#include <vector>

using namespace hsmu;
using namespace std::chrono;

namespace {

// now() is the simulated time; sleepUntil() jumps there (never back); work() spends time.
class FakeClock final : public comms::PaceClock {
public:
    nanoseconds now() override { return m_now; }
    void sleepUntil(nanoseconds t) override
    {
        m_sleeps += t > m_now ? 1 : 0;
        m_now = std::max(m_now, t);
    }
    void work(nanoseconds d) { m_now += d; }
    int sleeps() const { return m_sleeps; }

private:
    nanoseconds m_now{1'000'000'000};
    int m_sleeps = 0;
};

// A gate wrapper that spends `cost(k)` of simulated time inside each tick.
class CostlyGate final : public rths::TickGate {
public:
    CostlyGate(comms::RealtimePacer& pacer, FakeClock& clock, long slowEvery)
        : m_pacer(pacer), m_clock(clock), m_slowEvery(slowEvery) {}
    bool admit(long k, std::string& why) override { return m_pacer.admit(k, why); }
    void done(long k) override
    {
        m_clock.work(k % m_slowEvery == m_slowEvery - 1 ? microseconds(400) : microseconds(20));
        m_pacer.done(k);
    }
    void resume(long k) override { m_pacer.resume(k); }

private:
    comms::RealtimePacer& m_pacer;
    FakeClock& m_clock;
    long m_slowEvery;
};

// A clock whose every now() reads 1 us later (a busy-wait advances it); sleeps are recorded.
class TickingClock final : public comms::PaceClock {
public:
    nanoseconds now() override { return m_now += microseconds(1); }
    void sleepUntil(nanoseconds t) override
    {
        m_sleptUntil.push_back(t);
        m_now = std::max(m_now, t);
    }
    std::vector<nanoseconds> m_sleptUntil;
    nanoseconds m_now{0};
};

} // namespace

class TestRealtimePacer : public QObject {
    Q_OBJECT

private slots:
    void missesAreCountedAndHoldAfterTheLimit()
    {
        FakeClock clock;
        const double period = 1.0 / 4096.0; // 244.14 us
        comms::RealtimePacer pacer(clock, period, 2);
        std::string why;
        const auto tickCosting = [&](long k, microseconds cost) {
            const bool ok = pacer.admit(k, why);
            clock.work(cost);
            pacer.done(k);
            return ok;
        };
        QVERIFY(tickCosting(0, microseconds(100)));
        QVERIFY(tickCosting(1, microseconds(100)));
        QCOMPARE(pacer.misses(), 0L);
        QVERIFY(tickCosting(2, microseconds(300))); // ends 55.86 us after its deadline
        QCOMPARE(pacer.misses(), 1L);
        QCOMPARE(pacer.firstMissTick(), 2L);
        QVERIFY(std::abs(pacer.worstLateness() - (300e-6 - period)) < 1e-8);
        QVERIFY(tickCosting(3, microseconds(100))); // released late, still ends in time
        QCOMPARE(pacer.misses(), 1L);
        QVERIFY(tickCosting(4, microseconds(500)));
        QCOMPARE(pacer.misses(), 2L);
        QVERIFY(!pacer.admit(5, why));
        QVERIFY2(why.find("2 deadline misses") != std::string::npos, why.c_str());
        QVERIFY2(why.find("tick 4") != std::string::npos, why.c_str());
        QVERIFY2(why.find("before tick 5") != std::string::npos, why.c_str());
    }

    void releasesAreAbsoluteSoNothingDrifts()
    {
        // 1000 ticks of 20 us work: every release is start + k h; the clock ends at the last
        // release plus the work, not at a sum of rounded sleeps.
        FakeClock clock;
        comms::RealtimePacer pacer(clock, 1.0 / 4096.0, 0);
        const nanoseconds start = clock.now();
        std::string why;
        for (long k = 0; k < 1000; ++k) {
            QVERIFY(pacer.admit(k, why));
            clock.work(microseconds(20));
            pacer.done(k);
        }
        const nanoseconds expected = start + 999 * nanoseconds(244141) + microseconds(20);
        QVERIFY(std::abs((clock.now() - expected).count()) <= 1);
        QCOMPARE(pacer.misses(), 0L);
    }

    void theSpinningClockSleepsToTheMarginThenWaitsForTheRelease()
    {
        TickingClock inner;
        comms::SpinningClock clock(inner, microseconds(60));
        clock.sleepUntil(microseconds(1000));
        QCOMPARE(inner.m_sleptUntil.size(), std::size_t(1));
        QCOMPARE(inner.m_sleptUntil[0], microseconds(940)); // the release less the margin
        QVERIFY(inner.m_now >= microseconds(1000));          // returned only at the release
        QVERIFY(inner.m_now <= microseconds(1001));          // one now() past it at most
        // A release already past: no sleep below the present, no wait.
        const auto before = inner.m_now;
        clock.sleepUntil(microseconds(500));
        QVERIFY(inner.m_now - before <= microseconds(1));
        // Margin 0: no busy-wait, the inner clock's sleep to the release alone.
        TickingClock plain;
        comms::SpinningClock sleeper(plain, nanoseconds(0));
        sleeper.sleepUntil(microseconds(300));
        QCOMPARE(plain.m_sleptUntil.size(), std::size_t(1));
        QCOMPARE(plain.m_sleptUntil[0], microseconds(300));
        QCOMPARE(plain.m_now, microseconds(300));
    }

    void aPacedBenchmarkRunHoldsOnItsMisses()
    {
        // Case 1 on a 1 s synthetic record; every 50th tick costs 400 us: the 10th miss holds
        // the run before tick 500, with every tick before it kept.
        FakeClock clock;
        comms::RealtimePacer pacer(clock, 1.0 / 4096.0, 10);
        CostlyGate gate(pacer, clock, 50);
        GroundMotion ag;
        ag.dt = 0.01;
        for (int i = 0; i <= 100; ++i)
            ag.acceleration.push_back(0.5 * std::sin(2 * M_PI * 2.0 * i * 0.01));
        const rths::RthsSettings s = rths::benchmarkSampleController();
        const rths::RthsRun run = rths::runRths(rths::benchmarkPartition(1, s.plant), ag, s, &gate);
        QCOMPARE(pacer.misses(), 10L);
        QCOMPARE(run.time.size(), std::size_t(500));
        QVERIFY2(run.hold.find("before tick 500") != std::string::npos, run.hold.c_str());
    }

    void aDeadlineMissHoldResumesOnANewSchedule()
    {
        // The same run held by its 10th miss before tick 500, held 2 s, resumed: tick 500 is
        // released at the resume (the time held is no lateness), the policy counts the misses
        // from there (held again by the 10th after the resume, before tick 1000: misses() 20),
        // and every tick equals the unpaced run's bit for bit.
        FakeClock clock;
        comms::RealtimePacer pacer(clock, 1.0 / 4096.0, 10);
        CostlyGate gate(pacer, clock, 50);
        GroundMotion ag;
        ag.dt = 0.01;
        for (int i = 0; i <= 100; ++i)
            ag.acceleration.push_back(0.5 * std::sin(2 * M_PI * 2.0 * i * 0.01));
        const rths::RthsSettings s = rths::benchmarkSampleController();
        const rths::Partition p = rths::benchmarkPartition(1, s.plant);
        rths::RthsRunner runner(p, ag, s, &gate);
        QVERIFY(!runner.run());
        QCOMPARE(runner.next(), 500L);
        QCOMPARE(pacer.misses(), 10L);
        clock.work(seconds(2));
        const nanoseconds resumedAt = clock.now();
        QCOMPARE(runner.resume(), std::string());
        std::string why;
        QVERIFY(!runner.run());
        QCOMPARE(pacer.misses(), 20L);
        QCOMPARE(runner.next(), 1000L);
        QVERIFY2(runner.hold().find("before tick 1000") != std::string::npos, runner.hold().c_str());
        // Ticks 500..999 ran on the schedule restarted at the resume: 500 releases after it,
        // 20 us of work each and 400 us every 50th, the last (999) one of those.
        const nanoseconds expected = resumedAt + 499 * nanoseconds(244141) + microseconds(400);
        QVERIFY2(std::abs((clock.now() - expected).count()) <= 500,
                 qPrintable(QString::number(double((clock.now() - expected).count()))));
        int holds = 2;
        while (runner.resume().empty() && !runner.run())
            ++holds; // each further 10 misses (every 500 ticks) hold it again
        QVERIFY(runner.finished() && !runner.held());
        QCOMPARE(holds, 8); // before ticks 500, 1000, ..., 4000
        const rths::RthsRun paced = runner.result();
        const rths::RthsRun fast = rths::runRths(p, ag, s);
        QCOMPARE(paced.time.size(), fast.time.size());
        QVERIFY(paced.measured == fast.measured && paced.command == fast.command &&
                paced.force == fast.force && paced.hybrid == fast.hybrid);
        QCOMPARE(pacer.misses(), long(fast.time.size()) / 50); // ticks 49, 99, ..., 4049
    }
};

QTEST_APPLESS_MAIN(TestRealtimePacer)
#include "TestRealtimePacer.moc"
