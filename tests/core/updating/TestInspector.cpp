// Inspector (core/updating/Inspector.h): the windowed normalized RMS error against its closed
// form, the threshold's request and alarm, fracture detection, pinned parameters and the
// tracking indices J1-J3 on signals with a known delay and error.
#include "core/rths/TrackingMetrics.h"
#include "core/updating/Inspector.h"

#include <QtTest>

#include <cmath>

using namespace hsmu;

namespace {
InspectorInput input(int step, double dt, double fm, double fa, double dm = 0.0, double dc = 0.0)
{
    InspectorInput in;
    in.step = step;
    in.time = step * dt;
    in.measuredForce = fm;
    in.auxiliaryForce = fa;
    in.measuredDeformation = dm;
    in.commandedDeformation = dc;
    return in;
}

int count(const std::vector<Alarm>& alarms, AlarmKind k)
{
    int n = 0;
    for (const auto& a : alarms)
        n += a.kind == k;
    return n;
}
} // namespace

class TestInspector : public QObject {
    Q_OBJECT
private slots:
    void fitErrorIsTheWindowedNormalizedRms()
    {
        const double dt = 0.01;
        InspectorSettings s;
        s.window = 0.5; // 50 steps
        s.threshold = 10.0;
        Inspector insp(s, dt);
        std::vector<Alarm> alarms;
        std::vector<double> fm, fa;
        for (int i = 1; i <= 300; ++i) {
            fm.push_back(std::sin(0.1 * i));
            fa.push_back(1.1 * std::sin(0.1 * i) + 0.01 * std::cos(0.37 * i));
            insp.observe(input(i, dt, fm.back(), fa.back()), alarms);
        }
        double r2 = 0, f2 = 0;
        for (std::size_t i = fm.size() - 50; i < fm.size(); ++i) {
            r2 += (fa[i] - fm[i]) * (fa[i] - fm[i]);
            f2 += fm[i] * fm[i];
        }
        QVERIFY(std::abs(insp.fitError() - std::sqrt(r2 / f2)) < 1e-12);
    }

    void thresholdRequestsUpdatingAndWarnsOncePerExcursion()
    {
        const double dt = 0.01;
        InspectorSettings s;
        s.window = 0.2;
        s.threshold = 0.05;
        Inspector insp(s, dt);
        std::vector<Alarm> alarms;
        int step = 0;
        auto run = [&](int n, double gain) {
            for (int i = 0; i < n; ++i, ++step)
                insp.observe(input(step + 1, dt, std::sin(0.2 * step), gain * std::sin(0.2 * step)),
                             alarms);
        };
        run(100, 1.01); // 1 % error: below
        QVERIFY(!insp.updateRequested());
        QCOMPARE(count(alarms, AlarmKind::FitError), 0);
        run(100, 1.2); // 20 %: above, one alarm
        QVERIFY(insp.updateRequested());
        QCOMPARE(count(alarms, AlarmKind::FitError), 1);
        run(100, 1.0);
        QVERIFY(!insp.updateRequested());
        run(100, 0.7);
        QCOMPARE(count(alarms, AlarmKind::FitError), 2);
    }

    void fractureIsCriticalAtTheStepOfTheLoss()
    {
        const double dt = 0.01;
        Inspector insp({}, dt);
        std::vector<Alarm> alarms;
        for (int i = 1; i <= 400; ++i) {
            const double f = 10.0 * std::sin(0.05 * i);
            const double measured = i >= 250 ? 0.4 * f : f; // 60 % strength lost at step 250
            insp.observe(input(i, dt, measured, f), alarms);
        }
        QVERIFY(insp.fractureDetected());
        QCOMPARE(count(alarms, AlarmKind::Fracture), 1);
        // Loss 0.6 |f|: flagged at the first step from 250 on where 0.6 |f| > 0.25 * peak (10).
        int expected = 250;
        while (0.6 * std::abs(10.0 * std::sin(0.05 * expected)) <= 2.5)
            ++expected;
        QVERIFY(std::abs(insp.fractureTime() - expected * 0.01) < 1e-9);
        QVERIFY(insp.fractureTime() - 2.5 <= 0.5); // the acceptance bound: within 0.5 s
        for (const auto& a : alarms)
            if (a.kind == AlarmKind::Fracture)
                QVERIFY(a.severity == AlarmSeverity::Critical);
    }

    void noFractureOnNoise()
    {
        Inspector insp({}, 0.01);
        std::vector<Alarm> alarms;
        for (int i = 1; i <= 2000; ++i) {
            const double f = 10.0 * std::sin(0.05 * i);
            insp.observe(input(i, 0.01, f + 0.2 * std::sin(7.1 * i), f), alarms);
        }
        QVERIFY(!insp.fractureDetected());
    }

    void parameterPinnedAtABoundWarnsAfterPinnedTime()
    {
        InspectorSettings s;
        s.pinnedTime = 1.0;
        Inspector insp(s, 0.01);
        std::vector<Alarm> alarms;
        const ParameterLayout layout({"alpha", "k0"});
        const std::vector<ParameterBounds> bounds{{0.001, 0.05}, {0.7, 1.4}};
        int firstAlarmStep = -1;
        for (int i = 1; i <= 300; ++i) {
            const std::vector<double> v{i > 50 ? 0.05 : 0.03, 1.0};
            InspectorInput in = input(i, 0.01, 1.0, 1.0);
            in.parameters = &layout;
            in.parameterValues = v;
            in.parameterBounds = bounds;
            insp.observe(in, alarms);
            if (firstAlarmStep < 0 && count(alarms, AlarmKind::ParameterPinned) > 0)
                firstAlarmStep = i;
        }
        QCOMPARE(count(alarms, AlarmKind::ParameterPinned), 1);
        QCOMPARE(firstAlarmStep, 151); // pinned from step 51 (t = 0.51 s) for 1.0 s
    }

    // Parameters by position: each value is checked against the bound at its own position
    // (not its neighbour's), NaN bounds are skipped, and alarms raised together come in name
    // order whatever the layout's order.
    void pinnedChecksEachPositionAgainstItsOwnBound()
    {
        InspectorSettings s;
        s.pinnedTime = 0.5;
        Inspector insp(s, 0.01);
        std::vector<Alarm> alarms;
        const ParameterLayout layout({"n", "k0", "beta", "alpha"});
        const double nan = std::nan("");
        // n on its upper bound, k0 inside its own bounds (on n's lower one), beta unbounded at
        // a value equal to alpha's upper bound, alpha on its lower bound.
        const std::vector<ParameterBounds> bounds{{1.0, 3.0}, {0.7, 1.4}, {nan, nan}, {0.001, 0.05}};
        const std::vector<double> v{3.0, 1.0, 0.05, 0.001};
        for (int i = 1; i <= 100; ++i) {
            InspectorInput in = input(i, 0.01, 1.0, 1.0);
            in.parameters = &layout;
            in.parameterValues = v;
            in.parameterBounds = bounds;
            insp.observe(in, alarms);
        }
        std::vector<std::string> pinned;
        for (const Alarm& a : alarms)
            if (a.kind == AlarmKind::ParameterPinned)
                pinned.push_back(a.message.substr(0, a.message.find(' ')));
        QCOMPARE(pinned, (std::vector<std::string>{"alpha", "n"}));
    }

    void trackingIndicesOfADelayedScaledSignal()
    {
        const double dt = 0.01;
        InspectorSettings s;
        s.trackingWindow = 4.0;
        s.trackingJ2Limit = 0.05;
        std::vector<Alarm> alarms;
        const int delaySteps = 3;
        auto cmd = [](int i) { return std::sin(2 * M_PI * 0.5 * i * 0.01); };
        // Evaluated at t = 0 (too little data) and once more when the window is full.
        s.trackingInterval = 4.0 - 1e-9;
        Inspector at(s, dt);
        for (int i = 0; i <= 400; ++i) {
            const double c = cmd(i);
            const double m = i >= delaySteps ? cmd(i - delaySteps) : 0.0;
            at.observe(input(i, dt, 1.0, 1.0, m, c), alarms);
        }
        // J1: the correlation's peak refined by a parabola (a sine's peak is not a parabola):
        // within 2 % of a step of the delay.
        QVERIFY2(std::abs(at.tracking().j1 - delaySteps * dt) < 0.02 * dt,
                 qPrintable(QString::number(at.tracking().j1)));
        // J2 of a pure delay tau on a sine: sqrt(2 - 2 cos(w tau)) (RMS ratio), w = pi.
        const double expectedJ2 = std::sqrt(2 - 2 * std::cos(M_PI * delaySteps * dt));
        QVERIFY2(std::abs(at.tracking().j2 - expectedJ2) < 0.01 * expectedJ2,
                 qPrintable(QString::number(at.tracking().j2)));
        // J3 ~ 2 sin(w tau / 2).
        QVERIFY(std::abs(at.tracking().j3 - 2 * std::sin(M_PI * delaySteps * dt / 2)) < 2e-3);
        QVERIFY(count(alarms, AlarmKind::TrackingError) == 1); // J2 = 9.4 % > 5 %
    }

    void trackingDelayIsTheNormalizedCorrelationsOnAShortWindow()
    {
        // J1 is the console's live RTHS estimator (TrackingWindow.h, M1'): on a 1 s window of a
        // 2 Hz sine 5 steps (4.88 ms) late at 1024 Hz it reads the delay within 0.05 ms. M1's
        // plain sum over the same window (lags to a quarter of it: the sum for lag l has n - l
        // terms) leans towards the short lags (3.94 ms here): why the inspector left it.
        const double dt = 1.0 / 1024;
        InspectorSettings s;
        s.trackingWindow = 1.0;
        s.trackingInterval = 1.0 - 1e-9; // at t = 0 and once the window is full
        Inspector at(s, dt);
        std::vector<Alarm> alarms;
        std::vector<double> cmd, meas;
        auto c = [dt](int i) { return 1e-3 * std::sin(2 * M_PI * 2.0 * i * dt + 0.3); };
        for (int i = 0; i <= 1024; ++i) {
            at.observe(input(i, dt, 1.0, 1.0, c(i - 5), c(i)), alarms);
            if (i >= 1) { // the window: the last 1024 steps
                cmd.push_back(c(i));
                meas.push_back(c(i - 5));
            }
        }
        QVERIFY2(std::abs(at.tracking().j1 - 5 * dt) < 0.05e-3, qPrintable(QString::number(at.tracking().j1 * 1e3)));
        const double plain = rths::delayByCorrelation(cmd, meas, dt, 256);
        QVERIFY2(std::abs(plain - 5e3 * dt) > 0.5, qPrintable(QString::number(plain))); // 3.94 ms
    }
};

QTEST_APPLESS_MAIN(TestInspector)
#include "TestInspector.moc"
