#pragma once
// PinchingSearch: the pinching law's calibration (boucWenPinching; docs/method.md, "The
// pinching search") from the plain Bouc-Wen optimum `base` of the same history, as
// calibrateHistory (CalibrationDefaults.h) runs it. Two searches (CalibrationRequest::
// pinchingSearch):
//  - Global (offline, `hsmu replay --method calibration`): in the history's scales, a
//    screening of request.pinchingScreen points of a scrambled Halton design over the
//    pinching parameters' whole box around the plain optimum (one replay each on a reduced
//    history of 300 samples), then Levenberg-Marquardt from the plain optimum and the
//    request.pinchingKept best points (800 samples, at most 30 iterations), the two best
//    polished (at most 20 iterations, on at most 4,000 samples of the history,
//    then at most 8 more on the whole history when it is longer). When the result's k0 lies
//    outside [0.5, 2] (its ultimate z far from 1, where the widths' box sits) the search is
//    repeated once with uRef moved by that k0, without the screening: Levenberg-Marquardt
//    from the result and the plain optimum, both expressed exactly in the new scales
//    (rescaled(), BoucWenPinching.h), and the polish; the better fit is kept.
//  - Anchor (the online pinching UKF's anchors, the online refits): the plain optimum and
//    request.pinchingStarts starts scattered around it (fixed seed), the two best polished.
// Both keep the pinching on during the global phase (zetaS >= 0.5, p >= 5/max(E, 1)); the
// polish frees the whole box, so a specimen without pinching still ends with zetaS = 0.
// Values in the law's normalized units. Thread rules: none (a pure function of its input).

#include "core/identification/Calibration.h"
#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryScales.h"

#include <vector>

namespace hsmu {

/// The pinching calibration from the plain law's fit `base` (its parameters seed the search;
/// not ok: the pinching law's default starts). Counts and times are the pinching search's only.
CalibrationResult searchPinching(const std::vector<double>& deformation,
                                 const std::vector<double>& force,
                                 const CalibrationRequest& request, const HistoryScales& scales,
                                 const CalibrationResult& base);

/// `count` points of a scrambled Halton sequence in [0, 1)^dims (the first dims primes as
/// bases, each base's digits permuted at random with 0 kept; a fixed seed), in order.
std::vector<std::vector<double>> scrambledHalton(int dims, int count, unsigned seed);

} // namespace hsmu
