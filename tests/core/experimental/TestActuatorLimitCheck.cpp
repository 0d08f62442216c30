// The pre-flight lines of per-actuator limits (core/experimental/ActuatorLimitCheck.h):
//  - a force-controlled channel's constant force within its limit passes, past it is exceeded,
//    with the force and the limit reported as configured;
//  - a schedule's largest |F| inside the run (at a point, or at the run's end between points:
//    eq. F1 by hand) against the limit, with its time;
//  - a displacement channel's limits are checked during the run (no reach before it); a
//    channel without a limit says so.

#include "core/experimental/ActuatorLimitCheck.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace hsmu;

namespace {

ActuatorChannelSpec forceChannel(double force, double limit) {
    ActuatorChannelSpec c;
    c.name = "vertical";
    c.mode = ActuatorMode::Force;
    c.heldForce = force;
    c.limits.maxForce = limit;
    c.limits.maxDeformation = 0.01;
    return c;
}

} // namespace

class TestActuatorLimitCheck : public QObject {
    Q_OBJECT
private slots:
    void constantForce() {
        const auto pass = actuatorLimitLines({forceChannel(-500.0, 1000.0)}, 10.0);
        QCOMPARE(int(pass.size()), 3);
        QCOMPARE(pass[1].quantity, LimitQuantity::Force);
        QCOMPARE(pass[1].verdict, LimitVerdict::Pass);
        QCOMPARE(pass[1].reach, 500.0);
        QCOMPARE(pass[1].limit, 1000.0);
        QCOMPARE(pass[0].verdict, LimitVerdict::DuringRun); // its stroke: the specimen's
        QCOMPARE(pass[0].limit, 0.01);
        QCOMPARE(pass[2].verdict, LimitVerdict::NoLimit);
        const auto exceeded = actuatorLimitLines({forceChannel(-1200.0, 1000.0)}, 10.0);
        QCOMPARE(exceeded[1].verdict, LimitVerdict::Exceeded);
        QCOMPARE(exceeded[1].reach, 1200.0);
        QCOMPARE(exceeded[1].actuator, std::string("vertical"));
    }

    void schedule() {
        ActuatorChannelSpec c = forceChannel(0.0, 1005.0);
        c.forceSchedule = {{0.0, 0.0}, {1.0, -500.0}, {2.0, -500.0}, {3.0, -1500.0}};
        // over 4 s the largest is at the last point, 1500 at 3 s: exceeded
        auto l = actuatorLimitLines({c}, 4.0)[1];
        QCOMPARE(l.verdict, LimitVerdict::Exceeded);
        QCOMPARE(l.reach, 1500.0);
        QCOMPARE(l.reachTime, 3.0);
        // a 2.5 s run ends half way down to -1500: F(2.5) = -1000 by eq. F1, within 1005
        l = actuatorLimitLines({c}, 2.5)[1];
        QCOMPARE(l.verdict, LimitVerdict::Pass);
        QVERIFY(std::abs(l.reach - 1000.0) < 1e-12);
        QCOMPARE(l.reachTime, 2.5);
        // no duration: the schedule's end
        QCOMPARE(actuatorLimitLines({c}, 0.0)[1].reach, 1500.0);
    }

    void displacementChannel() {
        ActuatorChannelSpec c;
        c.name = "lateral";
        c.limits.maxDeformation = 0.2;
        c.limits.maxForce = 1000.0;
        c.limits.maxIncrement = 0.05;
        for (const ActuatorLimitLine& l : actuatorLimitLines({c}, 10.0)) {
            QCOMPARE(l.verdict, LimitVerdict::DuringRun);
            QVERIFY(std::isnan(l.reach));
            QCOMPARE(l.mode, ActuatorMode::Displacement);
        }
        c.limits.maxForce = std::numeric_limits<double>::infinity();
        QCOMPARE(actuatorLimitLines({c}, 10.0)[1].verdict, LimitVerdict::NoLimit);
    }
};

QTEST_APPLESS_MAIN(TestActuatorLimitCheck)
#include "TestActuatorLimitCheck.moc"
