#include "core/rths/TrackingMetrics.h"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace hsmu::rths {

namespace {
void requireSameLength(const std::vector<double>& a, const std::vector<double>& b)
{
    if (a.size() != b.size() || a.empty())
        throw std::invalid_argument("tracking metrics need two non-empty histories of one length");
}
} // namespace

std::size_t fftFriendlyLength(std::size_t size)
{
    for (std::size_t n = size; n > 1; --n) {
        std::size_t m = n;
        for (std::size_t p : {2, 3, 5, 7})
            while (m % p == 0)
                m /= p;
        if (m == 1)
            return n;
    }
    return size;
}

double delayByCorrelation(const std::vector<double>& y, const std::vector<double>& xm, double h,
                          int maxLag)
{
    requireSameLength(y, xm);
    const int n = int(y.size());
    maxLag = std::min(maxLag, n - 1);
    std::vector<double> r(std::size_t(maxLag) + 1, 0.0);
    for (int l = 0; l <= maxLag; ++l) {
        double s = 0.0;
        for (int k = l; k < n; ++k)
            s += xm[std::size_t(k)] * y[std::size_t(k - l)];
        r[std::size_t(l)] = s;
    }
    const int best = int(std::max_element(r.begin(), r.end()) - r.begin());
    double lag = best;
    if (best > 0 && best < maxLag) {
        const double a = r[std::size_t(best - 1)], b = r[std::size_t(best)], c = r[std::size_t(best + 1)];
        const double den = a - 2.0 * b + c;
        if (den < 0.0)
            lag += 0.5 * (a - c) / den;
    }
    return lag * h * 1000.0;
}

double normalizedRmsError(const std::vector<double>& ref, const std::vector<double>& act)
{
    requireSameLength(ref, act);
    double e = 0.0, r = 0.0;
    for (std::size_t k = 0; k < ref.size(); ++k) {
        e += (act[k] - ref[k]) * (act[k] - ref[k]);
        r += ref[k] * ref[k];
    }
    return r > 0.0 ? 100.0 * std::sqrt(e / r) : 0.0;
}

double peakError(const std::vector<double>& ref, const std::vector<double>& act)
{
    requireSameLength(ref, act);
    double e = 0.0, r = 0.0;
    for (std::size_t k = 0; k < ref.size(); ++k) {
        e = std::max(e, std::abs(act[k] - ref[k]));
        r = std::max(r, std::abs(ref[k]));
    }
    return r > 0.0 ? 100.0 * e / r : 0.0;
}

FrequencyEvaluation frequencyEvaluationIndex(const std::vector<double>& y,
                                             const std::vector<double>& xm, double h)
{
    requireSameLength(y, xm);
    // The first n samples, n the largest length <= size with no prime factor above 7: Eigen's
    // FFT costs O(size p) for a prime factor p (a prime 40,961-tick run took 16 s of CPU).
    const std::size_t n = fftFriendlyLength(y.size());
    const std::vector<double> yn(y.begin(), y.begin() + std::ptrdiff_t(n));
    const std::vector<double> xn(xm.begin(), xm.begin() + std::ptrdiff_t(n));
    Eigen::FFT<double> fft;
    std::vector<std::complex<double>> fy, fx;
    fft.fwd(fy, yn);
    fft.fwd(fx, xn);
    const std::size_t half = n / 2;
    // The band: bins holding 99 % of the command's energy, from the largest down.
    std::vector<std::size_t> order;
    double total = 0.0;
    for (std::size_t i = 1; i <= half; ++i) {
        order.push_back(i);
        total += std::norm(fy[i]);
    }
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return std::norm(fy[a]) > std::norm(fy[b]); });
    std::complex<double> cross = 0.0;
    double power = 0.0, weightedF = 0.0, kept = 0.0;
    const double df = 1.0 / (double(n) * h);
    for (std::size_t i : order) {
        if (kept >= 0.99 * total)
            break;
        const double p = std::norm(fy[i]);
        kept += p;
        cross += fx[i] * std::conj(fy[i]);
        power += p;
        weightedF += p * double(i) * df;
    }
    FrequencyEvaluation out;
    if (power <= 0.0)
        return out;
    const std::complex<double> hxy = cross / power;
    out.amplitude = std::abs(hxy);
    out.frequency = weightedF / power;
    out.delay = -std::arg(hxy) / (2.0 * M_PI * out.frequency) * 1000.0;
    return out;
}

double trackingIndicator(const std::vector<double>& y, const std::vector<double>& xm)
{
    requireSameLength(y, xm);
    double a = 0.0;
    for (std::size_t k = 1; k < y.size(); ++k)
        a += 0.25 * ((y[k] + y[k - 1]) * (xm[k] - xm[k - 1]) - (xm[k] + xm[k - 1]) * (y[k] - y[k - 1]));
    return a;
}

TrackingReport trackingReport(const std::vector<double>& y, const std::vector<double>& xm, double h)
{
    TrackingReport r;
    if (y.size() < 2 || xm.size() != y.size())
        return r;
    r.j1 = delayByCorrelation(y, xm, h);
    r.j2 = normalizedRmsError(y, xm);
    r.j3 = peakError(y, xm);
    r.frequency = frequencyEvaluationIndex(y, xm, h);
    r.indicator = trackingIndicator(y, xm);
    return r;
}

} // namespace hsmu::rths
