// The servo-hydraulic plant against the RTHS benchmark's closed-form transfer function
// (docs/rths.md, eq. P4): the state-space form and the RK4 simulation must both reproduce it.
#include "core/rths/ServoHydraulicPlant.h"

#include <QtTest>

#include <cmath>
#include <complex>

using namespace hsmu::rths;

class TestServoHydraulicPlant : public QObject {
    Q_OBJECT

private slots:
    void frequencyResponseEqualsClosedForm()
    {
        // 0.1 .. 100 Hz: C (jwI - A)^-1 B of the plant's own equations == g a1b0 / A(jw).
        const ServoHydraulicPlant plant;
        double worst = 0.0;
        for (int i = 0; i <= 300; ++i) {
            const double f = 0.1 * std::pow(1000.0, i / 300.0);
            const std::complex<double> closed = plant.parameters().frequencyResponse(2 * M_PI * f);
            const std::complex<double> ss = plant.stateSpaceResponse(2 * M_PI * f);
            worst = std::max(worst, std::abs(ss - closed) / std::abs(closed));
        }
        QVERIFY2(worst < 1e-6, qPrintable(QString("relative difference %1").arg(worst)));
    }

    void nominalPlantHasThePublishedDcGainAndLag()
    {
        // RTHS-BENCHMARK: DC gain 1.0075; lags 25.0 ms at 1 Hz, 22.7 at 5 Hz, 19.0 at 10 Hz.
        const PlantParameters p;
        QVERIFY(std::abs(std::abs(p.frequencyResponse(0.0)) - 1.0075) < 5e-4);
        const double f[] = {1.0, 5.0, 10.0}, lag[] = {25.0e-3, 22.7e-3, 19.0e-3};
        for (int i = 0; i < 3; ++i) {
            const double w = 2 * M_PI * f[i];
            const double d = -std::arg(p.frequencyResponse(w)) / w;
            QVERIFY2(std::abs(d - lag[i]) < 0.15e-3, qPrintable(QString("%1 Hz: %2 ms").arg(f[i]).arg(d * 1e3)));
        }
    }

    void denominatorMatchesThePartsMultipliedOut()
    {
        // A(s) = ((me s^2 + ce s + ke)(s + a3) + a2 s)(s^2 + b1 s + b2) + a1b0 at s = 2 + 3j.
        PlantParameters p;
        p.a3 = 2.0;
        const std::complex<double> s(2.0, 3.0);
        const std::complex<double> direct =
            ((p.me * s * s + p.ce * s + p.ke) * (s + p.a3) + p.a2 * s) * (s * s + p.b1 * s + p.b2) + p.a1b0;
        const auto a = p.denominator();
        std::complex<double> poly = 0.0;
        for (int i = 5; i >= 0; --i)
            poly = poly * s + a[std::size_t(i)];
        QVERIFY(std::abs(poly - direct) / std::abs(direct) < 1e-12);
    }

    void simulatedSineMatchesTheFrequencyResponse()
    {
        // RK4 at 4096 Hz driven by u = sin(wt) (held per tick): after the transient, the
        // response's first Fourier coefficient over whole periods equals G(jw) within 2e-3
        // (the held value is the sine at the tick's middle: no half-tick lag).
        for (double f : {1.0, 10.0, 40.0}) {
            ServoHydraulicPlant plant;
            const double h = 1.0 / 4096.0, w = 2 * M_PI * f;
            const int settle = int(2.0 / h), periods = int(std::ceil(2.0 * f));
            const int n = int(std::round(periods / f / h));
            std::complex<double> acc = 0.0;
            for (int k = 0; k < settle + n; ++k) {
                const double t = k * h;
                if (k >= settle)
                    acc += plant.displacement() * std::exp(std::complex<double>(0.0, -w * t));
                plant.advance(std::sin(w * (t + 0.5 * h)), h);
            }
            const std::complex<double> measured = acc * 2.0 / double(n) * std::complex<double>(0.0, 1.0);
            const std::complex<double> expected = plant.parameters().frequencyResponse(w);
            const double err = std::abs(measured - expected) / std::abs(expected);
            QVERIFY2(err < 2e-3, qPrintable(QString("%1 Hz: relative error %2").arg(f).arg(err)));
        }
    }

    void invalidParametersAreNamed()
    {
        PlantParameters p;
        p.me = 0.0;
        QVERIFY(p.validate().find("me") != std::string::npos);
        p = {};
        p.a3 = -1.0;
        QVERIFY(p.validate().find("a3") != std::string::npos);
        QVERIFY(PlantParameters{}.validate().empty());
    }
};

QTEST_APPLESS_MAIN(TestServoHydraulicPlant)
#include "TestServoHydraulicPlant.moc"
