#pragma once
// CalibrationDefaults: the calibration (Calibration.h) of a law to a history when the user
// gives no scales, bounds or starts (docs/method.md, "Scaling from the data" and "Default
// bounds"). For the Bouc-Wen laws the law runs normalized by the history's own scales
// (HistoryScales.h: fRef the peak force, uRef = fRef / K), so that the normalized k0 is about
// 1 and the ultimate z about 1, and the default normalized box is
//   k0 [0.02, 50]   alpha [0, 0.9]   n [0.5, 10]   beta, gamma [-20, 20] (beta + gamma > 0)
//   deltaNu, deltaEta [0, 20 / max(E, 1)]   (E: the history's normalized path work, so that
//                                            nu and eta stay below 21 over the history)
//   A0 = 1, deltaA = 0 fixed (as the paper; A and k0 are not separately identifiable)
// and, for boucWenPinching, on top: zetaS [0, 0.99], p [0, 200/max(E,1)] (the online
// anchors', PinchingSearch::Anchor: [0, 20/max(E,1)]), q [0, 0.9], psi [0.01, 5],
// deltaPsi [0, 20/max(E,1)], lambda [0.01, 10].
// Starts: k0 = 1 with alpha in {0.02, 0.15}, n in {1, 2, 5} and three loop shapes
// beta / (beta + gamma) in {0.5, 0.9, 1.4} at beta + gamma = 0.8^-n (ultimate z 0.8),
// no degradation. The pinching law's search from the Bouc-Wen optimum: PinchingSearch.h.
// Bilinear: k0 [0.05 K, 20 K], fy [0.02, 2] x the peak force, b [0, 0.9].
// mrDamper (rate-dependent; the history's times are needed): normalized like the Bouc-Wen
// laws, A = 1 fixed (A and alpha are not separately identifiable), and with v the history's
// typical normalized velocity (pi reversals / duration x half the deformation range / uRef)
//   c0 [0, 5 / v]   c1 [0.01 / v, 500 / v]   k0, k1 [0, 5]   f0 [-1, 1]   alpha [0, 2000]
//   n [0.2, 10]   beta, gamma [-2000, 2000] (beta + gamma > 0)
// from 24 starts: c0 in {0.1, 0.4} / v, c1 in {3, 30} c0, n in {0.5, 1, 2}, beta / (beta +
// gamma) in {0.5, 0.9} at an ultimate z of 0.05, alpha giving a hysteretic force of 0.8 (1 -
// c0 v), k0 = k1 = 0.02, f0 = 0; the two best polished.
// A user's bounds replace the defaults name by name; a user's uRef / fRef replace the
// derived scales.
// Offsets (OffsetLaw.h; docs/method.md, "Offsets"): with request.offsets On or Auto, after the
// fit above, the law with a deformation offset u0 and a force offset F0 is fitted from that
// optimum (offsets 0: the same forces; a record starting off zero also from its first sample
// as the rest state, u0 = u_0, F0 = F_0) on the whole history, every other parameter free
// again (so never worse than without), in the physical box u0 [-0.5, 0.5] x the deformation
// range, F0 [-0.5, 0.5] x the peak force.
// On keeps that fit; Auto keeps it only when the data ask for it, by an information
// criterion on the history's branches (a hysteresis fit's residuals are correlated along a
// branch, so the branches, not the samples, are the independent evidence):
//   N_eff ln(RSS_with / RSS_without) + 2 ln N_eff < 0,   N_eff = reversals + 1
// (BIC with two more parameters): with 20 branches the offsets must take 26 % off the
// squared error, with 100 branches 9 %. Off (the default, and the online refits'): no offsets.
// Thread rules: none.

#include "core/identification/Calibration.h"
#include "core/identification/HistoryScales.h"
#include "core/identification/ParameterSet.h"

#include <optional>
#include <string>
#include <vector>

namespace hsmu {

/// Whether the calibration fits a deformation and a force offset (see above).
enum class CalibrationOffsets { Off, On, Auto };

/// "off", "on", "auto"; nullopt for anything else.
std::optional<CalibrationOffsets> calibrationOffsetsFromName(const std::string& name);
const char* calibrationOffsetsName(CalibrationOffsets offsets);

/// The pinching law's search (PinchingSearch.h): Global, offline (the wide box and the
/// space-filling screening), or Anchor, the online anchors' and refits' cheaper search (p's box
/// [0, 20/max(E,1)], scattered starts only).
enum class PinchingSearch { Global, Anchor };

struct CalibrationRequest {
    std::string law = "boucWen";
    CalibrationOffsets offsets = CalibrationOffsets::Off; ///< fit u0 and F0 (see above)
    ParameterBoundsMap bounds;           ///< user bounds, replacing defaults by name
    std::optional<double> uRef, fRef;    ///< user scales (Bouc-Wen laws)
    std::vector<std::string> fitted;     ///< the parameters to fit ("": the law's default set)
    std::size_t window = 0;              ///< score the last `window` samples (0 = all)
    std::size_t reducedSamples = 800;    ///< the global phase's history (Calibration.h)
    PinchingSearch pinchingSearch = PinchingSearch::Global; ///< (boucWenPinching)
    int pinchingStarts = 40;             ///< scattered starts of the pinching search (Anchor)
    int pinchingScreen = 2048;           ///< screened points of the pinching search (Global)
    int pinchingKept = 12;               ///< ... the best of them minimized (Global)
    std::size_t polishSamples = 0;       ///< CalibrationSpec::polishSamples (0: whole history)
    int localIterations = 0;             ///< the local phase's iteration budget (0: default)
    const std::atomic<bool>* cancel = nullptr; ///< CalibrationSpec::cancel
    std::function<void(int done, int total)> progress; ///< CalibrationSpec::progress
    std::vector<double> time; ///< the samples' times [s] (CalibrationSpec::time; mrDamper)
};

/// The default spec for `law` on a history with these scales. Throws std::invalid_argument
/// for a law without defaults or a bound on a parameter that is not fitted.
CalibrationSpec defaultCalibrationSpec(const CalibrationRequest& request,
                                       const HistoryScales& scales);

/// The whole default calibration: scales from the data, the default spec, and for the
/// pinching law a Bouc-Wen fit first that seeds it; then the offsets (request.offsets).
CalibrationResult calibrateHistory(const std::vector<double>& deformation,
                                   const std::vector<double>& force,
                                   const CalibrationRequest& request);

} // namespace hsmu
