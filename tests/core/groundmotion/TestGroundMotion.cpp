// GroundMotion (interpolation, peak, scaling, resampling) and AccelerationUnit.
#include "core/groundmotion/AccelerationUnit.h"
#include "core/groundmotion/GroundMotion.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <stdexcept>

using namespace hsmu;

namespace {

GroundMotion sampled(double dt, std::size_t n, double (*f)(double)) {
    GroundMotion g;
    g.name = "test";
    g.source = "test";
    g.dt = dt;
    for (std::size_t i = 0; i < n; ++i)
        g.acceleration.push_back(f(static_cast<double>(i) * dt));
    return g;
}

double ramp(double t) {
    return 0.5 + 3.0 * t;
}
double sine(double t) {
    return std::sin(2.0 * std::numbers::pi * t);
}

} // namespace

class TestGroundMotion : public QObject {
    Q_OBJECT

private slots:
    void durationAndInterpolation() {
        const GroundMotion g = sampled(0.02, 51, ramp); // 0 .. 1.0 s
        QVERIFY(std::abs(g.duration() - 1.0) < 1e-12);
        QVERIFY(std::abs(g.at(0.0) - 0.5) < 1e-12);
        QVERIFY(std::abs(g.at(0.013) - ramp(0.013)) < 1e-12);
        QVERIFY(std::abs(g.at(1.0) - ramp(1.0)) < 1e-12);
        QCOMPARE(g.at(-0.001), 0.0);
        QCOMPARE(g.at(1.001), 0.0);
        QCOMPARE(GroundMotion{}.duration(), 0.0);
        QCOMPARE(GroundMotion{}.at(0.0), 0.0);
    }

    void peakIsAbsoluteAndFirst() {
        GroundMotion g;
        g.dt = 0.01;
        g.acceleration = {0.1, -0.3, 0.2, 0.3, -0.05};
        QCOMPARE(g.pga(), 0.3);
        QVERIFY(std::abs(g.pgaTime() - 0.01) < 1e-15);
        QCOMPARE(GroundMotion{}.pga(), 0.0);
    }

    void scaledMultipliesEverySample() {
        const GroundMotion g = sampled(0.02, 51, sine);
        const GroundMotion s = g.scaled(-2.5);
        QCOMPARE(s.acceleration.size(), g.acceleration.size());
        QCOMPARE(s.dt, g.dt);
        for (std::size_t i = 0; i < g.acceleration.size(); ++i)
            QCOMPARE(s.acceleration[i], -2.5 * g.acceleration[i]);
        QVERIFY(std::abs(s.pga() - 2.5 * g.pga()) < 1e-15);
    }

    void resampledRampIsExact() {
        const GroundMotion g = sampled(0.02, 51, ramp);
        const GroundMotion r = g.resampled(0.005);
        QCOMPARE(r.acceleration.size(), std::size_t(201)); // floor(1.0 / 0.005 + 1e-9) + 1
        QCOMPARE(r.dt, 0.005);
        QVERIFY(std::abs(r.duration() - g.duration()) < 1e-12);
        for (std::size_t k = 0; k < r.acceleration.size(); ++k)
            QVERIFY(std::abs(r.acceleration[k] - ramp(static_cast<double>(k) * 0.005)) < 1e-12);

        // A step that does not divide the duration: floor(1.0 / 0.03) + 1 = 34 samples.
        const GroundMotion coarse = g.resampled(0.03);
        QCOMPARE(coarse.acceleration.size(), std::size_t(34));
        QVERIFY(std::abs(coarse.acceleration.back() - ramp(33 * 0.03)) < 1e-12);
    }

    void resampledSineMatchesInterpolation() {
        const GroundMotion g = sampled(0.02, 201, sine); // 4 s, 1 Hz
        const GroundMotion r = g.resampled(0.005);
        QCOMPARE(r.acceleration.size(), std::size_t(801));
        QVERIFY(std::abs(r.duration() - 4.0) < 1e-12);
        // Linear interpolation error bound: (2 pi f)^2 dt^2 / 8 = 0.00197.
        const double bound = std::pow(2.0 * std::numbers::pi * 0.02, 2) / 8.0;
        for (std::size_t k = 0; k < r.acceleration.size(); ++k) {
            const double t = static_cast<double>(k) * 0.005;
            QVERIFY(std::abs(r.acceleration[k] - g.at(t)) < 1e-12);
            QVERIFY(std::abs(r.acceleration[k] - sine(t)) <= bound + 1e-12);
            if (k % 4 == 0) // coincides with an original sample
                QVERIFY(std::abs(r.acceleration[k] - g.acceleration[k / 4]) < 1e-12);
        }
    }

    void resampledRejectsBadStep() {
        const GroundMotion g = sampled(0.02, 51, ramp);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, g.resampled(0.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, g.resampled(-0.01));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, g.resampled(std::nan("")));
    }

    void unitParsing() {
        QCOMPARE(parseAccelerationUnit("g"), AccelerationUnit::G);
        QCOMPARE(parseAccelerationUnit(" G "), AccelerationUnit::G);
        for (const char* text : {"m/s^2", "m/s2", "M/S^2", "m/s/s"})
            QCOMPARE(parseAccelerationUnit(text), AccelerationUnit::MetersPerSecond2);
        for (const char* text : {"cm/s^2", "cm/s2", "gal", "Gal", "cm/s/s"})
            QCOMPARE(parseAccelerationUnit(text), AccelerationUnit::CentimetersPerSecond2);
        QVERIFY(!parseAccelerationUnit("").has_value());
        QVERIFY(!parseAccelerationUnit("mm/s^2").has_value());
        QVERIFY(!parseAccelerationUnit("gg").has_value());
        for (auto unit : {AccelerationUnit::G, AccelerationUnit::MetersPerSecond2,
                          AccelerationUnit::CentimetersPerSecond2})
            QCOMPARE(parseAccelerationUnit(unitSymbol(unit)), unit);
    }

    void unitFactors() {
        QCOMPARE(toMetersPerSecond2(AccelerationUnit::G), 9.80665);
        QCOMPARE(toMetersPerSecond2(AccelerationUnit::MetersPerSecond2), 1.0);
        QCOMPARE(toMetersPerSecond2(AccelerationUnit::CentimetersPerSecond2), 0.01);
        QCOMPARE(kStandardGravity, 9.80665);
    }
};

QTEST_APPLESS_MAIN(TestGroundMotion)
#include "TestGroundMotion.moc"
