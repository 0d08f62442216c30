#include "core/rths/TrackingWindow.h"

#include "core/rths/RthsLoop.h"
#include "core/rths/TrackingMetrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace hsmu::rths {

std::string checkTrackingWindow(const TrackingWindowSettings& s, double h)
{
    if (!(h > 0.0) || !std::isfinite(h))
        return "the loop period must be positive";
    if (!(s.window > 0.0) || !std::isfinite(s.window) || s.window / h < 8.0)
        return "tracking window: at least 8 loop periods";
    if (!(s.interval > 0.0) || !std::isfinite(s.interval))
        return "tracking interval: a positive number of seconds";
    if (!(s.maxDelay > 0.0) || !std::isfinite(s.maxDelay) || s.maxDelay > 0.5 * s.window)
        return "tracking maxDelay: positive and at most half the window";
    if (!(s.minimumRms >= 0.0) || !std::isfinite(s.minimumRms))
        return "tracking minimumRms: finite and >= 0 m";
    if (!(s.peakFraction >= 0.0) || !(s.peakFraction < 1.0))
        return "tracking peakFraction: 0 up to (not including) 1";
    return {};
}

TrackingWindowSettings gatedWindowSettings(TrackingWindowSettings s, const SensorSettings& sensor)
{
    const double noise = std::hypot(sensor.noise ? sensor.displacementNoise : 0.0, sensor.quantum / std::sqrt(12.0));
    s.minimumRms = kNoiseMultiple * noise;
    s.peakFraction = kPeakFraction;
    return s;
}

double amplitudeRatio(const std::vector<double>& y, const std::vector<double>& xm, int lag,
                      std::size_t from)
{
    if (y.size() != xm.size() || lag < 0)
        throw std::invalid_argument("amplitudeRatio: two histories of one length and a lag >= 0");
    double num = 0.0, den = 0.0;
    for (std::size_t k = std::max(std::size_t(lag), from); k < y.size(); ++k) {
        const double ys = y[k - std::size_t(lag)];
        num += xm[k] * ys;
        den += ys * ys;
    }
    return den > 0.0 ? num / den : std::numeric_limits<double>::quiet_NaN();
}

double windowDelay(const std::vector<double>& y, const std::vector<double>& xm, double h, int maxLag)
{
    if (y.size() != xm.size() || maxLag < 1 || std::size_t(maxLag) + 2 > y.size())
        throw std::invalid_argument("windowDelay: two histories of one length, longer than maxLag + 1");
    const std::size_t n = y.size(), L = std::size_t(maxLag);
    std::vector<double> r(L + 1, 0.0);
    for (std::size_t l = 0; l <= L; ++l) {
        double num = 0.0, den = 0.0;
        for (std::size_t k = L; k < n; ++k) {
            num += xm[k] * y[k - l];
            den += y[k - l] * y[k - l];
        }
        r[l] = den > 0.0 ? num / std::sqrt(den) : 0.0;
    }
    const std::size_t best = std::size_t(std::max_element(r.begin(), r.end()) - r.begin());
    double lag = double(best);
    if (best > 0 && best < L) {
        const double a = r[best - 1], b = r[best], c = r[best + 1];
        const double curvature = a - 2.0 * b + c;
        if (curvature < 0.0)
            lag += 0.5 * (a - c) / curvature;
    }
    return lag * h * 1000.0;
}

TrackingWindow::TrackingWindow(double h, const TrackingWindowSettings& settings)
    : m_h(h), m_s(settings)
{
    if (const std::string e = checkTrackingWindow(settings, h); !e.empty())
        throw std::invalid_argument(e);
    m_n = std::size_t(std::llround(settings.window / h));
    m_every = std::max(1L, long(std::llround(settings.interval / h)));
    m_maxLag = std::max(1, int(std::llround(settings.maxDelay / h)));
    m_y.assign(m_n, 0.0);
    m_xm.assign(m_n, 0.0);
    m_yBuf.resize(m_n);
    m_xmBuf.resize(m_n);
}

void TrackingWindow::reset()
{
    m_head = m_filled = 0;
    m_next = 0;
    m_count = 0;
    m_peakRms = 0.0;
    m_last = {};
}

bool TrackingWindow::add(long k, double desired, double measured)
{
    m_y[m_head] = desired;
    m_xm[m_head] = measured;
    m_head = (m_head + 1) % m_n;
    if (m_filled < m_n)
        ++m_filled;
    if (m_filled < m_n || k < m_next)
        return false;
    m_next = k + m_every;
    estimate(k);
    return true;
}

void TrackingWindow::estimate(long k)
{
    // Oldest first: the ring from m_head on.
    for (std::size_t i = 0; i < m_n; ++i) {
        const std::size_t j = (m_head + i) % m_n;
        m_yBuf[i] = m_y[j];
        m_xmBuf[i] = m_xm[j];
    }
    TrackingEstimate e;
    e.tick = k;
    e.time = double(k) * m_h;
    double sum = 0.0;
    for (const double y : m_yBuf)
        sum += y * y;
    e.commandRms = std::sqrt(sum / double(m_n));
    m_peakRms = std::max(m_peakRms, e.commandRms);
    e.gate = std::max(m_s.minimumRms, m_s.peakFraction * m_peakRms);
    ++m_count;
    if (e.commandRms < e.gate) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        e.valid = false;
        e.delay = e.j2 = e.amplitude = e.amplitudeError = nan;
        m_last = e;
        return;
    }
    e.j2 = normalizedRmsError(m_yBuf, m_xmBuf);
    e.delay = windowDelay(m_yBuf, m_xmBuf, m_h, m_maxLag);
    const int lag = int(std::lround(e.delay * 1e-3 / m_h));
    e.amplitude = amplitudeRatio(m_yBuf, m_xmBuf, lag, std::size_t(m_maxLag));
    e.amplitudeError = (e.amplitude - 1.0) * 100.0;
    m_last = e;
}

} // namespace hsmu::rths
