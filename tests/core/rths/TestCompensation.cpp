// Compensators and the servo-controller's filters (docs/rths.md, eqs. C1-C5) against closed forms
// and a synthetic loop with a known delay and gain.
#include "core/rths/Compensation.h"
#include "core/rths/DiscreteFilters.h"
#include "core/rths/TrackingMetrics.h"

#include <QtTest>

#include <cmath>
#include <complex>
#include <deque>
#include <memory>

using namespace hsmu::rths;

namespace {
const double kH = 1.0 / 4096.0;
}

class TestCompensation : public QObject {
    Q_OBJECT

private slots:
    void piStepResponse()
    {
        // Tustin integral of a unit step: ki h (n - 1/2) after n ticks, plus kp.
        Pid pid(PidGains{2.0, 95.0, 0.0, 0.0}, kH);
        double u = 0.0;
        for (int n = 1; n <= 100; ++n)
            u = pid.step(1.0);
        QVERIFY(std::abs(u - (2.0 + 95.0 * kH * 99.5)) < 1e-12);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Pid(PidGains{1.0, 0.0, 0.1, 0.0}, kH));
    }

    void leadMatchesItsTustinResponse()
    {
        // Gt = K (s + z) / (s + p) by Tustin: a sine's steady gain and phase equal
        // Gt(j (2 / h) tan(w h / 2)); DC gain 1 for the benchmark's values.
        const LeadSettings l;
        FirstOrderSection gt = FirstOrderSection::lead(l.gain, l.zero, l.pole, kH);
        QVERIFY(std::abs(gt.dcGain() - 1.0) < 1e-4);
        const double w = 2 * M_PI * 5.0;
        std::complex<double> acc = 0.0;
        const int settle = 4096, n = 4096; // 1 s each: 5 whole periods
        for (int k = 0; k < settle + n; ++k) {
            const double y = gt.step(std::sin(w * k * kH));
            if (k >= settle)
                acc += y * std::exp(std::complex<double>(0.0, -w * k * kH));
        }
        const std::complex<double> measured = acc * 2.0 / double(n) * std::complex<double>(0.0, 1.0);
        const std::complex<double> s(0.0, 2.0 / kH * std::tan(0.5 * w * kH));
        const std::complex<double> expected = l.gain * (s + l.zero) / (s + l.pole);
        QVERIFY(std::abs(measured - expected) / std::abs(expected) < 1e-6);
    }

    void polynomialExtrapolationIsExactForACubic()
    {
        CompensationSettings s;
        s.type = CompensationSettings::Type::Polynomial;
        s.order = 3;
        s.delay = 4.6e-3;
        Compensator c(s, kH);
        c.reset(0.0);
        const auto cubic = [](double t) { return 0.001 + 0.02 * t - 0.3 * t * t + 0.5 * t * t * t; };
        double out = 0.0;
        for (int k = 0; k < 10; ++k)
            out = c.command(TargetState{cubic(k * kH), 0.0, 0.0});
        QVERIFY(std::abs(out - cubic(9 * kH + 4.6e-3)) < 1e-12);
    }

    void feedforwardFitInvertsAPureDelay()
    {
        // T = e^{-j w tau}: its inverse e^{j w tau} ~ 1 + tau s + tau^2 s^2 / 2 at low frequency.
        const double tau = 4.6e-3;
        CompensationSettings s;
        fitFeedforward([&](double w) { return std::exp(std::complex<double>(0.0, -w * tau)); },
                       0.2, 6.0, s);
        // (the cubic term of e^{j w tau} leaks into c1 by about 0.5 % at 6 Hz).
        QVERIFY(std::abs(s.c0 - 1.0) < 1e-3);
        QVERIFY(std::abs(s.c1 - tau) < 0.01 * tau);
        QVERIFY(std::abs(s.c2 - 0.5 * tau * tau) < 0.05 * 0.5 * tau * tau);
        for (double f = 0.2; f <= 6.0; f += 0.1) {
            const double w = 2 * M_PI * f;
            const std::complex<double> inv(s.c0 - s.c2 * w * w, s.c1 * w);
            QVERIFY(std::abs(inv * std::exp(std::complex<double>(0.0, -w * tau)) - 1.0) < 1e-3);
        }
    }

    void atsLearnsADelayedScaledLoop()
    {
        // A loop that delays the command by 20 ticks (4.9 ms) and scales it by 0.9; targets are a
        // two-tone motion. Starting from c = (1, 0, 0) the ATS's tracking error over the last
        // 4 s must be below 15 % of the uncompensated one, and a0, a1 near 1 / 0.9, tau / 0.9.
        const int delay = 20;
        const double gain = 0.9;
        const auto run = [&](CompensationSettings::Type type, std::unique_ptr<Compensator>& c) {
            CompensationSettings s;
            s.type = type;
            s.window = 2.0;
            c = std::make_unique<Compensator>(s, kH);
            c->reset(0.0);
            std::deque<double> line(delay, 0.0);
            std::vector<double> y, xm;
            const int n = int(20.0 / kH);
            for (int k = 0; k < n; ++k) {
                const double t = k * kH, w1 = 2 * M_PI * 1.3, w2 = 2 * M_PI * 3.7;
                const TargetState tgt{0.002 * std::sin(w1 * t) + 0.001 * std::sin(w2 * t),
                                      0.002 * w1 * std::cos(w1 * t) + 0.001 * w2 * std::cos(w2 * t),
                                      -0.002 * w1 * w1 * std::sin(w1 * t) - 0.001 * w2 * w2 * std::sin(w2 * t)};
                const double measured = gain * line.front();
                line.pop_front();
                c->observe(measured);
                line.push_back(c->command(tgt));
                if (t > 16.0) {
                    y.push_back(tgt.x);
                    xm.push_back(measured);
                }
            }
            return normalizedRmsError(y, xm);
        };
        std::unique_ptr<Compensator> plain, ats;
        const double e0 = run(CompensationSettings::Type::None, plain);
        const double e1 = run(CompensationSettings::Type::Ats, ats);
        QVERIFY2(e1 < 0.15 * e0, qPrintable(QString("ATS %1 %% against %2 %%").arg(e1).arg(e0)));
        QVERIFY(std::abs(ats->c0() - 1.0 / gain) < 0.03);
        QVERIFY(std::abs(ats->c1() - delay * kH / gain) < 0.15 * delay * kH / gain);
    }

    void typeNamesRoundTrip()
    {
        for (auto t : {CompensationSettings::Type::None, CompensationSettings::Type::Polynomial,
                       CompensationSettings::Type::Feedforward, CompensationSettings::Type::Ats}) {
            CompensationSettings::Type back{};
            QVERIFY(parseCompensationType(compensationTypeName(t), back));
            QCOMPARE(int(back), int(t));
        }
        CompensationSettings::Type x{};
        QVERIFY(!parseCompensationType("smith", x));
    }
};

QTEST_APPLESS_MAIN(TestCompensation)
#include "TestCompensation.moc"
