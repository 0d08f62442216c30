#include "core/identification/HistoryScales.h"

#include <algorithm>
#include <cmath>

namespace hsmu {

namespace {

/// Least-squares slope of F against u over samples [first, last] (with an intercept);
/// NaN if u does not vary.
double slope(const std::vector<double>& u, const std::vector<double>& f, std::size_t first,
             std::size_t last) {
    const double n = double(last - first + 1);
    double su = 0, sf = 0;
    for (std::size_t k = first; k <= last; ++k) {
        su += u[k];
        sf += f[k];
    }
    const double mu = su / n, mf = sf / n;
    double suu = 0, suf = 0;
    for (std::size_t k = first; k <= last; ++k) {
        suu += (u[k] - mu) * (u[k] - mu);
        suf += (u[k] - mu) * (f[k] - mf);
    }
    return suu > 0 ? suf / suu : std::nan("");
}

/// The last sample index after `start` before |u - u[start]| exceeds `reach`.
std::size_t branchEnd(const std::vector<double>& u, std::size_t start, double reach) {
    std::size_t k = start;
    while (k + 1 < u.size() && std::abs(u[k + 1] - u[start]) <= reach)
        ++k;
    return k + 1 < u.size() ? k + 1 : k;
}

} // namespace

std::vector<std::size_t> turningPoints(const std::vector<double>& u, double deadBand) {
    std::vector<std::size_t> out;
    if (u.size() < 3)
        return out;
    int dir = 0; // +1 rising, -1 falling, 0 not known yet
    std::size_t extreme = 0;
    for (std::size_t k = 1; k < u.size(); ++k) {
        if (dir == 0) {
            if (u[k] - u[0] > deadBand)
                dir = 1;
            else if (u[0] - u[k] > deadBand)
                dir = -1;
            extreme = k;
            continue;
        }
        if ((dir > 0 && u[k] >= u[extreme]) || (dir < 0 && u[k] <= u[extreme])) {
            extreme = k;
        } else if (std::abs(u[k] - u[extreme]) > deadBand) {
            out.push_back(extreme);
            dir = -dir;
            extreme = k;
        }
    }
    return out;
}

HistoryScales deriveHistoryScales(const std::vector<double>& u, const std::vector<double>& f) {
    HistoryScales s;
    if (u.size() < 3 || u.size() != f.size()) {
        s.reason = "at least three samples of deformation and force are needed";
        return s;
    }
    const auto [uMin, uMax] = std::minmax_element(u.begin(), u.end());
    s.deformationRange = *uMax - *uMin;
    s.fRef = 0.0;
    for (double v : f)
        s.fRef = std::max(s.fRef, std::abs(v));
    if (!(s.deformationRange > 0) || !(s.fRef > 0) || !std::isfinite(s.fRef)) {
        s.reason = "the history has no deformation or no force to scale by";
        return s;
    }
    const double reach = 0.1 * s.deformationRange;
    const std::vector<std::size_t> tps = turningPoints(u, 0.02 * s.deformationRange);
    s.reversals = int(tps.size());
    std::vector<double> slopes;
    for (std::size_t tp : tps) {
        const double k = slope(u, f, tp, branchEnd(u, tp, reach));
        if (std::isfinite(k) && k > 0)
            slopes.push_back(k);
    }
    if (slopes.empty()) { // the first loading branch from the start
        const double k = slope(u, f, 0, branchEnd(u, 0, reach));
        if (std::isfinite(k) && k > 0)
            slopes.push_back(k);
    }
    if (slopes.empty()) {
        s.reason = "no branch of the history has a positive stiffness";
        return s;
    }
    std::nth_element(slopes.begin(), slopes.begin() + std::ptrdiff_t(slopes.size() / 2),
                     slopes.end());
    s.stiffness = slopes[slopes.size() / 2];
    s.uRef = s.fRef / s.stiffness;
    double work = 0.0;
    for (std::size_t k = 1; k < u.size(); ++k)
        work += 0.5 * std::abs(f[k] + f[k - 1]) * std::abs(u[k] - u[k - 1]);
    s.energy = work / (s.fRef * s.uRef);
    s.ok = true;
    return s;
}

HistoryScales withURef(HistoryScales scales, double uRef) {
    if (uRef > 0.0 && std::isfinite(uRef)) {
        scales.energy *= scales.uRef / uRef;
        scales.uRef = uRef;
        scales.stiffness = scales.fRef / uRef;
    }
    return scales;
}

} // namespace hsmu
