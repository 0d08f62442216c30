// ScheduledJob (core/updating/ScheduledJob.h): a job's result is applied at the step fixed when
// it started (N + max(50, N / 20)), whatever the worker's speed; a running job is cancelled by
// cancel() and by the destructor, which then return (a job that only ends when cancelled would
// otherwise hang the test until CTest's timeout); the robust UKF's and the pinching UKF's
// anchor jobs stop on their cancel flag and report it.

#include "core/updating/PinchingUkfJobs.h"
#include "core/updating/RobustUkfIdentifier.h"
#include "core/updating/RobustUkfJobs.h"
#include "core/updating/ScheduledJob.h"
#include "../identification/SyntheticHistory.h"

#include <QtTest>

#include <atomic>
#include <memory>

using namespace hsmu;

namespace {

struct Outcome {
    bool cancelled = false;
    int value = 0;
};

/// Work that ends only when cancelled, and says so through `seen`.
ScheduledJob<int, Outcome>::Work untilCancelled(std::shared_ptr<std::atomic<bool>> seen) {
    return [seen](const std::atomic<bool>& cancel) {
        cancel.wait(false);
        seen->store(true);
        return Outcome{true, 0};
    };
}

} // namespace

class TestScheduledJob : public QObject {
    Q_OBJECT

private slots:
    void appliesAtTheStepFixedAtItsStart() {
        ScheduledJob<int, Outcome> job;
        QVERIFY(!job.running());
        QVERIFY(!job.due(1000000));
        job.start(100, 7, [](const std::atomic<bool>&) { return Outcome{false, 42}; });
        QVERIFY(job.running());
        QCOMPARE(job.applyAt(), std::size_t(150)); // max(50, 100 / 20)
        QVERIFY(!job.due(149));
        QVERIFY(job.due(150));
        const auto t = job.take();
        QCOMPARE(t.meta, 7);
        QCOMPARE(t.outcome.value, 42);
        QCOMPARE(t.startSize, std::size_t(100));
        QVERIFY(!job.running());
        QCOMPARE(scheduledJobDelay(4000), std::size_t(200));
        QCOMPARE(job.started(), 1);
        QCOMPARE(job.cancelled(), 0);
    }

    void cancelStopsARunningJob() {
        ScheduledJob<int, Outcome> job;
        auto seen = std::make_shared<std::atomic<bool>>(false);
        job.start(10, 1, untilCancelled(seen));
        const std::optional<Outcome> out = job.cancel();
        QVERIFY(out.has_value());
        QVERIFY(out->cancelled);
        QVERIFY(seen->load());
        QVERIFY(!job.running());
        QCOMPARE(job.cancelled(), 1);
        QVERIFY(!job.cancel().has_value()); // nothing runs any more
    }

    void destructorCancelsARunningJob() {
        auto seen = std::make_shared<std::atomic<bool>>(false);
        {
            ScheduledJob<int, Outcome> job;
            job.start(10, 1, untilCancelled(seen));
        } // returns only if the work saw the flag
        QVERIFY(seen->load());
    }

    void anchorJobsStopOnTheirFlag() {
        const std::vector<double> u = testing::cyclic(2.0, 4, 100);
        BoucWen law(BoucWenParameters{});
        const std::vector<double> f = testing::forcesOf(law, u);
        std::atomic<bool> cancel{true};
        AnchorJobInput in;
        in.u = u;
        in.f = f;
        const AnchorJobResult r = anchorJob(in, &cancel);
        QVERIFY(!r.ok);
        QVERIFY(r.cancelled);
        PinchingAnchorJobInput pin;
        pin.u = u;
        pin.f = f;
        const PinchingAnchorJobResult p = pinchingAnchorJob(pin, &cancel);
        QVERIFY(!p.ok);
        QVERIFY(p.cancelled);
        QCOMPARE(p.residualEvaluations, 0);
        // ... and run to the end without it
        cancel = false;
        QVERIFY(anchorJob(in, &cancel).ok);
    }

    /// An identifier destroyed while its first anchor (a multi-start calibration) runs.
    void robustUkfDestroyedWhileCalibrating() {
        const std::vector<double> u = testing::cyclic(2.0, 6, 400);
        BoucWen law(BoucWenParameters{});
        const std::vector<double> f = testing::forcesOf(law, u);
        auto id = std::make_unique<RobustUkfIdentifier>(BoucWenParameters{}, std::nullopt,
                                                        std::nullopt, ParameterBoundsMap{});
        std::size_t k = 0;
        while (k < u.size() && id->jobs() == 0)
            id->observe(u[k], f[k], false), ++k;
        QCOMPARE(id->jobs(), 1);
        id.reset(); // cancels the calibration
        QVERIFY(k < u.size());
    }
};

QTEST_APPLESS_MAIN(TestScheduledJob)
#include "TestScheduledJob.moc"
