#pragma once
// Tracking metrics of an RTHS run (docs/rths.md, "Tracking metrics"), on histories sampled at
// the loop period h [s]. y: the desired displacement (the numerical substructure's, at the
// specimen's DOF), xm: the measured one. All errors in percent.
//
//   J1  delay maximizing the cross-correlation sum_k xm[k] y[k-l] over l = 0 .. maxLag samples,
//       refined by a parabola through the peak and its neighbours [ms]                  (M1)
//   J2  sqrt(sum (xm - y)^2 / sum y^2) 100                                               (M2)
//   J3  max |xm - y| / max |y| 100                                                       (M3)
//   J4..J9 the same normalized RMS / peak errors of the hybrid response against the
//       reference structure's (floor 1 measured, floors 2, 3 numerical)                (M4)
//   frequency evaluation index (after Guo et al. 2014): H = sum Xm Y* / sum |Y|^2 over the
//       band holding the command's energy; amplitude |H|, delay -arg(H) / (2 pi f_e) with
//       f_e the energy-weighted mean frequency [ms]                                      (M5)
//   tracking indicator (after Mercan & Ricles 2007): the signed area enclosed by the
//       synchronization plot, TI = 1/4 sum (y[k] + y[k-1]) (xm[k] - xm[k-1])
//       - (xm[k] + xm[k-1]) (y[k] - y[k-1]); positive while xm lags y; pi A^2 sin(phi) per cycle of y = A sin wt, xm lagging by phi [m^2] (M6)

#include <cstddef>
#include <vector>

namespace hsmu::rths {

/// J1 [ms].
double delayByCorrelation(const std::vector<double>& y, const std::vector<double>& xm, double h,
                          int maxLag = 50);
/// J2 / J4 / J6 / J7 [%].
double normalizedRmsError(const std::vector<double>& reference, const std::vector<double>& actual);
/// J3 / J5 / J8 / J9 [%].
double peakError(const std::vector<double>& reference, const std::vector<double>& actual);

struct FrequencyEvaluation {
    double amplitude = 0.0; ///< |H| [-]
    double delay = 0.0;     ///< [ms]
    double frequency = 0.0; ///< energy-weighted mean frequency f_e [Hz]
};
/// M5 over the first fftFriendlyLength(size) samples (at most a few per mille left out).
FrequencyEvaluation frequencyEvaluationIndex(const std::vector<double>& y,
                                             const std::vector<double>& xm, double h);
/// The largest length <= size whose prime factors are 2, 3, 5, 7 (size itself below 2).
std::size_t fftFriendlyLength(std::size_t size);
/// M6 over the whole history [m^2].
double trackingIndicator(const std::vector<double>& y, const std::vector<double>& xm);

/// What a run's summary reports of one actuator's tracking (M1, M2, M3, M5, M6): y desired,
/// xm measured, sampled at h [s]; `hsmu rths`, `hsmu run` and `hsmu compare` alike.
struct TrackingReport {
    double j1 = 0.0, j2 = 0.0, j3 = 0.0; ///< [ms], [%], [%]
    FrequencyEvaluation frequency;
    double indicator = 0.0;              ///< [unit of y squared]
};
TrackingReport trackingReport(const std::vector<double>& y, const std::vector<double>& xm, double h);

/// J1..J9 of a run (index 0 = J1).
struct BenchmarkCriteria {
    double j[9] = {};
};

} // namespace hsmu::rths
