#pragma once
// HistoryScales: reference scales of a specimen derived from its own measured response, for
// a Bouc-Wen-class law run on normalized variables x = u / uRef, f = F / fRef (BoucWen.h;
// docs/method.md, "Scaling from the data"), when the user gives none:
//
//   fRef = max_k |F_k|                                  (the peak force so far)
//   K    = median over the reversals of the unloading slope dF/du, each fitted by least
//          squares over the samples from a reversal until |u - u_rev| reaches 10 % of the
//          deformation range (a Bouc-Wen branch leaves a reversal with about k0); the slope
//          of the first loading branch when the history has no reversal yet
//   uRef = fRef / K                                     (so that the normalized k0 is about 1)
//   energy = sum_k |F_k + F_k-1| / 2 |u_k - u_k-1| / (fRef uRef)
//                                      (normalized path work, an upper bound of the
//                                       dissipated energy e that the degradation terms see)
//
// Reversals are found with a dead band of 2 % of the deformation range. Units are the
// history's (m or rad; kN or kN m). A history without motion or force has no scales (ok
// false and a reason).
// Thread rules: none (a pure function).

#include <string>
#include <vector>

namespace hsmu {

struct HistoryScales {
    bool ok = false;
    std::string reason;        ///< why there are no scales, when !ok
    double uRef = 1.0;         ///< [deformation units]
    double fRef = 1.0;         ///< [force units]
    double stiffness = 1.0;    ///< K = fRef / uRef [force / deformation]
    double energy = 0.0;       ///< normalized path work [-]
    double deformationRange = 0.0; ///< max u - min u [deformation units]
    int reversals = 0;         ///< turning points found
};

HistoryScales deriveHistoryScales(const std::vector<double>& deformation,
                                  const std::vector<double>& force);

/// The same history's scales with uRef moved (a search that moves uRef by the k0 it found):
/// the stiffness and the normalized path work E = work / (fRef uRef) follow, so the boxes
/// that depend on E (CalibrationDefaults.h) are those of the scales the law runs in.
HistoryScales withURef(HistoryScales scales, double uRef);

/// Indices of the turning points of u (local extrema with a dead band `deadBand` in u), in
/// order; the first and last samples are not included.
std::vector<std::size_t> turningPoints(const std::vector<double>& u, double deadBand);

} // namespace hsmu
