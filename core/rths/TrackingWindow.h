#pragma once
// TrackingWindow: the loop's delay and amplitude error estimated online, over a moving window
// of the last W seconds of desired y and measured xm (docs/rths.md, "Live tracking"), one
// estimate every `interval` seconds; the console's synchronization view and its J1 / J2 alarms
// (TrackingAlarms) read it. J2 is TrackingMetrics' own (M2, one definition):
//
//   delay      J1 over the window, normalized (M1'): the lag l = 0 .. L = maxDelay / h
//              maximizing r(l) = sum_{k=L}^{n-1} xm[k] y[k-l] / sqrt(sum_{k=L}^{n-1} y[k-l]^2),
//              refined by a parabola through the peak [ms]. Every lag is summed over the same
//              ticks and divided by the shifted y's energy: over a window of a few periods M1's
//              plain sum leans towards the lags whose shifted y carries more energy (tens of
//              ticks at 2 Hz in 1 s); r(l) peaks exactly at d when xm[k] = g y[k-d]
//              (Cauchy-Schwarz)
//   J2         normalized RMS tracking error over the window (M2) [%]
//   amplitude  A = sum xm[k] y[k-d] / sum y[k-d]^2, k = max(d, L) .. n-1, d = round(delay / h):
//              the least-squares gain of xm on y shifted by the delay [-]                 (M7)
//   amplitude error  (A - 1) 100 [%]
//   signal gate      no estimate (valid false; delay, J2, amplitude NaN) while the window's
//                    command is too quiet for one: rms(y) < max(minimumRms, peakFraction x
//                    the largest window rms(y) of the run so far) (docs/rths.md, "Live
//                    tracking": sensor noise as large as the motion makes the delay wander
//                    to the search bound and the amplitude to +-100 %); a valid estimate is
//                    computed as without the gate, bit for bit
//
// h: the loop period [s]. Cost per estimate: O(n maxDelay / h) with n = W / h samples.
// Thread rules: one thread (the loop's, as a TickObserver's helper).

#include <cstddef>
#include <string>
#include <vector>

namespace hsmu::rths {

struct TrackingWindowSettings {
    double window = 1.0;    ///< W [s]
    double interval = 0.1;  ///< between estimates [s]
    double maxDelay = 0.05; ///< the longest delay searched [s]
    /// The window's command RMS below which no estimate is made [m] (0: no absolute floor);
    /// the console's view: kNoiseMultiple x the displacement sensor's noise RMS.
    double minimumRms = 0.0;
    /// ... or below this fraction of the largest window RMS of the run so far [-] (0: none).
    double peakFraction = 0.0;
};

struct SensorSettings;

/// The console's signal gate for the loop's displacement sensor (docs/rths.md, "Live
/// tracking"): minimumRms = kNoiseMultiple x the sensor's noise RMS, sqrt(sigma^2 + q^2 / 12)
/// (sigma its Gaussian noise when on, q its A/D quantum), and peakFraction = kPeakFraction.
constexpr double kNoiseMultiple = 10.0;
constexpr double kPeakFraction = 0.1;
TrackingWindowSettings gatedWindowSettings(TrackingWindowSettings s, const SensorSettings& sensor);

/// "" when usable, else what is wrong (naming the field).
std::string checkTrackingWindow(const TrackingWindowSettings& s, double h);

struct TrackingEstimate {
    long tick = 0;                ///< the window's last tick
    double time = 0.0;            ///< its time k h [s]
    double delay = 0.0;           ///< J1 over the window [ms]
    double j2 = 0.0;              ///< [%]
    double amplitude = 1.0;       ///< A [-]
    double amplitudeError = 0.0;  ///< (A - 1) 100 [%]
    bool valid = true;            ///< false: the command was too quiet (the fields above NaN)
    double commandRms = 0.0;      ///< rms(y) over the window [m]
    double gate = 0.0;            ///< the RMS it had to reach [m]
};

class TrackingWindow {
public:
    /// Throws std::invalid_argument when checkTrackingWindow fails.
    TrackingWindow(double h, const TrackingWindowSettings& settings = {});
    /// Tick k's desired and measured displacement [m]; true when an estimate was made now (a
    /// full window, and `interval` since the last one).
    bool add(long k, double desired, double measured);
    const TrackingEstimate& last() const { return m_last; }
    bool hasEstimate() const { return m_count > 0; }
    void reset();

private:
    void estimate(long k);
    double m_h;
    TrackingWindowSettings m_s;
    std::size_t m_n;       // samples in the window
    long m_every;          // ticks between estimates
    int m_maxLag;          // ticks
    std::vector<double> m_y, m_xm; // rings of m_n
    std::size_t m_head = 0, m_filled = 0;
    long m_next = 0;       // the tick of the next estimate
    std::vector<double> m_yBuf, m_xmBuf; // contiguous copies (kept)
    TrackingEstimate m_last;
    long m_count = 0;
    double m_peakRms = 0.0; // the largest window rms(y) so far [m]
};

/// M1' over whole histories [ms] (maxLag >= 1 ticks, shorter than the histories).
double windowDelay(const std::vector<double>& y, const std::vector<double>& xm, double h, int maxLag);

/// M7: the least-squares gain of xm on y shifted by `lag` ticks, summed over
/// k = max(lag, from) .. n-1 [-] (NaN when y carries no energy there).
double amplitudeRatio(const std::vector<double>& y, const std::vector<double>& xm, int lag,
                      std::size_t from = 0);

} // namespace hsmu::rths
