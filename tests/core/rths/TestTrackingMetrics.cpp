// Tracking metrics (docs/rths.md, eqs. M1-M6) on signals whose answers are known in closed form.
#include "core/rths/TrackingMetrics.h"

#include <QtTest>

#include <cmath>
#include <vector>

using namespace hsmu::rths;

namespace {
const double kH = 1.0 / 4096.0;
// y = A sin(w t), xm = g A sin(w (t - tau)) over whole periods.
void sines(double f, double tau, double gain, int periods, std::vector<double>& y, std::vector<double>& xm)
{
    const int n = int(std::round(periods / f / kH));
    y.resize(std::size_t(n));
    xm.resize(std::size_t(n));
    for (int k = 0; k < n; ++k) {
        const double t = k * kH;
        y[std::size_t(k)] = 0.002 * std::sin(2 * M_PI * f * t);
        xm[std::size_t(k)] = gain * 0.002 * std::sin(2 * M_PI * f * (t - tau));
    }
}
} // namespace

class TestTrackingMetrics : public QObject {
    Q_OBJECT

private slots:
    void delayOfADelayedSine()
    {
        // A delay of 4.6 ms (18.84 ticks): the parabola through the peak finds it within 0.05 ms.
        std::vector<double> y, xm;
        sines(3.0, 4.6e-3, 1.0, 30, y, xm);
        QVERIFY(std::abs(delayByCorrelation(y, xm, kH) - 4.6) < 0.05);
        sines(3.0, 0.0, 1.0, 30, y, xm);
        QVERIFY(std::abs(delayByCorrelation(y, xm, kH)) < 0.01);
    }

    void rmsAndPeakErrorsOfADelayedSine()
    {
        // |sin(wt) - sin(w(t - tau))| has amplitude 2 sin(w tau / 2): J2 = J3 = that, in %.
        std::vector<double> y, xm;
        const double f = 2.0, tau = 5e-3;
        sines(f, tau, 1.0, 20, y, xm);
        const double expected = 100.0 * 2.0 * std::sin(M_PI * f * tau);
        QVERIFY(std::abs(normalizedRmsError(y, xm) - expected) < 1e-3);
        QVERIFY(std::abs(peakError(y, xm) - expected) < 1e-2);
        QCOMPARE(normalizedRmsError(y, y), 0.0);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, normalizedRmsError(y, std::vector<double>(3)));
    }

    void frequencyEvaluationIndexOfAScaledDelayedSine()
    {
        std::vector<double> y, xm;
        sines(4.0, 3e-3, 0.9, 40, y, xm);
        const FrequencyEvaluation fe = frequencyEvaluationIndex(y, xm, kH);
        QVERIFY(std::abs(fe.amplitude - 0.9) < 1e-3);
        QVERIFY(std::abs(fe.delay - 3.0) < 0.01);
        QVERIFY(std::abs(fe.frequency - 4.0) < 1e-6);
    }

    void frequencyEvaluationIndexOfAPrimeLengthUsesItsSmoothPrefix()
    {
        // 40,961 samples (a prime: Eigen's FFT would cost O(n^2)): the index is that of the
        // first 40,960 = 2^13 5, the delay still found.
        QCOMPARE(fftFriendlyLength(40961), std::size_t(40960));
        QCOMPARE(fftFriendlyLength(3073), std::size_t(3072));
        QCOMPARE(fftFriendlyLength(31160), std::size_t(31104)); // 2^7 3^5
        QCOMPARE(fftFriendlyLength(1), std::size_t(1));
        std::vector<double> y, xm;
        sines(4.0, 3e-3, 0.9, 40, y, xm);
        while (y.size() < 40961) {
            y.push_back(y[y.size() - 4096]);
            xm.push_back(xm[xm.size() - 4096]);
        }
        y.resize(40961);
        xm.resize(40961);
        const FrequencyEvaluation all = frequencyEvaluationIndex(y, xm, kH);
        const std::vector<double> y0(y.begin(), y.end() - 1), x0(xm.begin(), xm.end() - 1);
        const FrequencyEvaluation prefix = frequencyEvaluationIndex(y0, x0, kH);
        QCOMPARE(all.delay, prefix.delay);
        QCOMPARE(all.amplitude, prefix.amplitude);
        QVERIFY(std::abs(all.delay - 3.0) < 0.01);
    }

    void trackingIndicatorIsTheLoopArea()
    {
        // Per cycle pi A^2 sin(phi); positive for a lagging response, negative for a leading one.
        std::vector<double> y, xm;
        const double f = 2.0, tau = 10e-3;
        const int periods = 10;
        sines(f, tau, 1.0, periods, y, xm);
        const double phi = 2 * M_PI * f * tau;
        const double expected = periods * M_PI * 0.002 * 0.002 * std::sin(phi);
        QVERIFY2(std::abs(trackingIndicator(y, xm) - expected) < 1e-3 * expected,
                 qPrintable(QString("%1 vs %2").arg(trackingIndicator(y, xm)).arg(expected)));
        sines(f, -tau, 1.0, periods, y, xm);
        QVERIFY(trackingIndicator(y, xm) < 0.0);
    }
};

QTEST_APPLESS_MAIN(TestTrackingMetrics)
#include "TestTrackingMetrics.moc"
