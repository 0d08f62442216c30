// The built-in synthetic record: reproducibility, scaling, and the properties its header
// states (zero final velocity, zero mean, energy between ~0.3 and 12 Hz, envelope shape).
#include "core/groundmotion/SyntheticGroundMotion.h"

#include <QtTest>

#include <bit>
#include <cmath>
#include <complex>
#include <cstdint>
#include <numbers>
#include <stdexcept>

using namespace hsmu;

namespace {

struct VelocityStats {
    double pgv = 0.0;
    double finalVelocity = 0.0;
    double finalDisplacement = 0.0;
};

// Trapezoid-rule velocity and displacement from rest.
VelocityStats integrate(const GroundMotion& m) {
    VelocityStats s;
    double v = 0.0;
    for (std::size_t i = 1; i < m.acceleration.size(); ++i) {
        const double next = v + 0.5 * m.dt * (m.acceleration[i - 1] + m.acceleration[i]);
        s.finalDisplacement += 0.5 * m.dt * (v + next);
        v = next;
        s.pgv = std::max(s.pgv, std::abs(v));
    }
    s.finalVelocity = v;
    return s;
}

// Fraction of the DFT power (one-sided) with frequency in [fLow, fHigh] Hz.
double powerFraction(const GroundMotion& m, double fLow, double fHigh) {
    const std::size_t n = m.acceleration.size();
    double total = 0.0;
    double band = 0.0;
    for (std::size_t k = 0; k <= n / 2; ++k) {
        std::complex<double> sum = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const double phase =
                -2.0 * std::numbers::pi * static_cast<double>((k * i) % n) / static_cast<double>(n);
            sum += m.acceleration[i] * std::polar(1.0, phase);
        }
        const double f = static_cast<double>(k) / (static_cast<double>(n) * m.dt);
        total += std::norm(sum);
        if (f >= fLow && f <= fHigh)
            band += std::norm(sum);
    }
    return band / total;
}

double rms(const GroundMotion& m, double t0, double t1) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < m.acceleration.size(); ++i) {
        const double t = static_cast<double>(i) * m.dt;
        if (t >= t0 && t <= t1) {
            sum += m.acceleration[i] * m.acceleration[i];
            ++count;
        }
    }
    return std::sqrt(sum / count);
}

} // namespace

class TestSyntheticGroundMotion : public QObject {
    Q_OBJECT

private slots:
    void defaultRecordShape() {
        const GroundMotion m = makeSyntheticGroundMotion();
        QCOMPARE(m.acceleration.size(), std::size_t(3001));
        QCOMPARE(m.dt, 0.01);
        QVERIFY(std::abs(m.duration() - 30.0) < 1e-12);
        QCOMPARE(m.name, std::string("synthetic Kanai-Tajimi (seed 1940)"));
        QCOMPARE(m.source, std::string("builtin"));
        QCOMPARE(m.pga(), 0.32 * kStandardGravity); // exactly, by construction
        QVERIFY(std::abs(m.pga() / kStandardGravity - 0.32) < 1e-12);
        for (double a : m.acceleration)
            QVERIFY(std::isfinite(a));
    }

    void sameSeedIsBitIdentical() {
        const GroundMotion a = makeSyntheticGroundMotion(1940);
        const GroundMotion b = makeSyntheticGroundMotion(1940);
        QCOMPARE(a.acceleration.size(), b.acceleration.size());
        for (std::size_t i = 0; i < a.acceleration.size(); ++i)
            QCOMPARE(std::bit_cast<std::uint64_t>(a.acceleration[i]),
                     std::bit_cast<std::uint64_t>(b.acceleration[i]));
    }

    void pinnedSamplesAreBitExact() {
        // Reference bits from the first build (x86-64, GCC 12). The generator uses only IEEE
        // exact operations, so every platform must give these; a failure means the record is
        // no longer portable (libm exp/log/sin, FMA contraction or x87 excess precision).
        const GroundMotion m = makeSyntheticGroundMotion();
        QCOMPARE(m.acceleration[1], -0x1.ceaafab0d45f1p-21);
        QCOMPARE(m.acceleration[100], -0x1.273585b1e6637p-5);
        QCOMPARE(m.acceleration[1500], -0x1.498f76a7cf618p-1);
        QCOMPARE(m.acceleration[3000], -0x1.125b7d86c5e66p-7);
        double energy = 0.0;
        for (double a : m.acceleration)
            energy += a * a;
        QCOMPARE(energy, 0x1.5de8eeabd3f72p+10);
    }

    void differentSeedDiffers() {
        const GroundMotion a = makeSyntheticGroundMotion(1940);
        const GroundMotion b = makeSyntheticGroundMotion(1941);
        QCOMPARE(b.name, std::string("synthetic Kanai-Tajimi (seed 1941)"));
        std::size_t differing = 0;
        for (std::size_t i = 1; i < a.acceleration.size(); ++i)
            differing += a.acceleration[i] != b.acceleration[i] ? 1 : 0;
        QVERIFY(differing > a.acceleration.size() * 99 / 100);
        QCOMPARE(b.pga(), a.pga()); // both scaled to 0.32 g
    }

    void endsAtRestWithZeroMean() {
        for (unsigned seed : {1940u, 1u, 2u, 3u}) {
            const GroundMotion m = makeSyntheticGroundMotion(seed);
            const VelocityStats s = integrate(m);
            QVERIFY2(s.pgv > 0.1 && s.pgv < 1.0, qPrintable(QString::number(s.pgv)));
            QVERIFY2(std::abs(s.finalVelocity) < 0.05 * s.pgv,
                     qPrintable(QString::number(s.finalVelocity)));
            QVERIFY(std::abs(s.finalDisplacement) < 0.02); // m
            double mean = 0.0;
            for (double a : m.acceleration)
                mean += a;
            mean /= static_cast<double>(m.acceleration.size());
            QVERIFY(std::abs(mean) < 1e-3 * m.pga());
        }
    }

    void energyBetweenPointThreeAndTwelveHertz() {
        const GroundMotion m = makeSyntheticGroundMotion();
        const double fraction = powerFraction(m, 0.3, 12.0);
        QVERIFY2(fraction > 0.8, qPrintable(QString::number(fraction)));
    }

    void envelopeShape() {
        const GroundMotion m = makeSyntheticGroundMotion();
        const double strong = rms(m, 2.0, 12.0);
        QVERIFY(rms(m, 0.0, 1.0) < 0.25 * strong);   // quadratic ramp-up
        QVERIFY(rms(m, 27.0, 30.0) < 0.05 * strong); // exp(-0.3 (t - 12)) decay
        QVERIFY(m.pgaTime() > 1.0 && m.pgaTime() < 16.0);
    }

    void otherLengthsAndInvalidArguments() {
        const GroundMotion m = makeSyntheticGroundMotion(7, 10.0, 0.005, 0.5);
        QCOMPARE(m.acceleration.size(), std::size_t(2001));
        QVERIFY(std::abs(m.pga() / kStandardGravity - 0.5) < 1e-12);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeSyntheticGroundMotion(1, 0.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeSyntheticGroundMotion(1, 30.0, 0.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, makeSyntheticGroundMotion(1, 30.0, -0.01));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 makeSyntheticGroundMotion(1, 30.0, 0.01, -0.3));
    }
};

QTEST_APPLESS_MAIN(TestSyntheticGroundMotion)
#include "TestSyntheticGroundMotion.moc"
