#include "core/identification/PinchingSearch.h"

#include "core/hysteresis/BoucWenPinching.h"
#include "core/hysteresis/LawFactory.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <string>

namespace hsmu {

namespace {

using Box = CalibrationSpec::Parameter;
using Values = std::map<std::string, double>;

bool isPinchingParameter(const std::string& name) {
    return name == "zetaS" || name == "p" || name == "q" || name == "psi" ||
           name == "deltaPsi" || name == "lambda";
}

bool isRate(const std::string& name) {
    return name == "p" || name == "deltaPsi" || name == "deltaNu" || name == "deltaEta";
}

/// Starts scattered over the pinching law's box around the Bouc-Wen optimum `base`: each
/// pinching parameter uniform over its box (the energy rates skewed toward 0 as u^3, most
/// specimens degrade slowly), each Bouc-Wen shape parameter the optimum's value times
/// exp(+-0.25), the Bouc-Wen degradation rates skewed as the pinching rates. Pinching moves
/// the loop's shape enough that the plain law's optimum is not inside the pinched law's
/// basin (measured on the shared RC columns and bearing: docs/validation.md), so the search
/// has to leave it. Deterministic (a fixed seed): the same history gives the same fit.
std::vector<std::vector<double>> scatteredPinchingStarts(
    const std::vector<Box>& fitted, const std::map<std::string, double>& base, int count) {
    std::mt19937 rng(20261124u);
    const auto uniform = [&rng] { return double(rng()) / 4294967296.0; };
    const auto logUniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, uniform()); };
    std::vector<std::vector<double>> starts;
    for (int k = 0; k < count; ++k) {
        std::map<std::string, double> v;
        for (const Box& b : fitted) {
            const auto at = base.find(b.name);
            const double u = uniform();
            if (isRate(b.name)) // drawn over at most 200 typical (20 / E): p's box is wider
                v[b.name] = b.lower + std::min(b.upper - b.lower, 200.0 * b.typical) * u * u * u;
            else if (b.name == "n")
                v[b.name] = logUniform(0.7, 6.0);
            else if (isPinchingParameter(b.name) || at == base.end())
                v[b.name] = b.lower + (b.upper - b.lower) * u;
            else
                v[b.name] = at->second * std::exp(0.5 * (u - 0.5));
        }
        // The width of the pinched zone zeta2 = psi (lambda + zeta1) matters more than psi
        // and lambda apart: zeta2 log-uniform over [0.05, 1] (in z, whose ultimate value is
        // about 1 with the derived scales), lambda log-uniform over its box.
        if (v.count("lambda") && v.count("psi")) {
            const Box& lb = *std::find_if(fitted.begin(), fitted.end(),
                                          [](const Box& x) { return x.name == "lambda"; });
            v["lambda"] = logUniform(std::max(lb.lower, 1e-3), lb.upper);
            v["psi"] = logUniform(0.05, 1.0) / (v["lambda"] + 0.5 * v["zetaS"]);
        }
        std::vector<double> s;
        for (const Box& b : fitted)
            s.push_back(v[b.name]);
        starts.push_back(std::move(s));
    }
    return starts;
}

/// The pinching search's screening design (docs/method.md, "The pinching search"): `count`
/// points of a scrambled Halton sequence over the pinching parameters' whole box, around the
/// Bouc-Wen optimum `base` (its shape within +-25 %, n log-uniform over [0.7, 6], its
/// degradation rates as the pinching ones). Coordinates that spread the law's behaviour
/// evenly: zetaS and q uniform over their box; p log-uniform over [0.5, 200] / E (the severity
/// saturating anywhere from the end of the history's work to its first 0.5 %); the width of
/// the pinched zone zeta2 = psi (lambda + zetaS) log-uniform over [0.01, 2] x the optimum's
/// ultimate z `zu`, lambda log-uniform over its box (psi follows); the energy rates deltaPsi,
/// deltaNu, deltaEta over their first 200 typical as u^3 (most specimens degrade slowly).
std::vector<std::vector<double>> pinchingScreenDesign(const std::vector<Box>& fitted,
                                                      const std::map<std::string, double>& base,
                                                      double energy, double zu, int count) {
    const int dims = int(fitted.size());
    const auto grid = scrambledHalton(dims, count, 20261206u);
    const auto logScale = [](double lo, double hi, double u) { return lo * std::pow(hi / lo, u); };
    const double e = std::max(energy, 1.0);
    std::vector<std::vector<double>> points;
    for (const auto& g : grid) {
        std::map<std::string, double> v, unit;
        for (int d = 0; d < dims; ++d) {
            const Box& b = fitted[std::size_t(d)];
            const double u = g[std::size_t(d)];
            unit[b.name] = u;
            const auto at = base.find(b.name);
            const double lower = std::isnan(b.searchLower) ? b.lower : b.searchLower;
            if (b.name == "p")
                v[b.name] = logScale(std::max(lower, 0.5 / e), b.upper, u);
            else if (b.name == "zetaS")
                v[b.name] = lower + (b.upper - lower) * u;
            else if (isRate(b.name))
                v[b.name] = b.lower + std::min(b.upper - b.lower, 200.0 * b.typical) * u * u * u;
            else if (b.name == "n")
                v[b.name] = logScale(0.7, 6.0, u);
            else if (b.name == "lambda")
                v[b.name] = logScale(std::max(b.lower, 1e-3), b.upper, u);
            else if (isPinchingParameter(b.name) || at == base.end())
                v[b.name] = b.lower + (b.upper - b.lower) * u;
            else
                v[b.name] = at->second * std::exp(0.5 * (u - 0.5));
        }
        if (v.count("psi") && v.count("lambda") && v.count("zetaS"))
            v["psi"] = logScale(0.01, 2.0, unit["psi"]) * zu / (v["lambda"] + v["zetaS"]);
        std::vector<double> s;
        for (const Box& b : fitted)
            s.push_back(std::clamp(v[b.name], b.lower, b.upper));
        points.push_back(std::move(s));
    }
    return points;
}

/// The pinching law's parameters of `values` (every name of the law; the others at their
/// defaults) expressed in the scales (uRef, fRef), as a map (rescaled(), BoucWenPinching.h).
Values inScales(const Values& values, double uRef, double fRef) {
    const auto law = makeLaw("boucWenPinching", values);
    const auto& from = dynamic_cast<const BoucWenPinching&>(*law).parameters();
    const BoucWenPinching to(rescaled(from, uRef, fRef));
    Values out;
    const std::vector<std::string> names = to.parameterNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        out[names[i]] = to.parameterValue(int(i));
    return out;
}

std::vector<double> startOf(const std::vector<Box>& fitted, const Values& values,
                            bool pinchingOff) {
    std::vector<double> s;
    for (const Box& b : fitted) {
        const auto it = values.find(b.name);
        s.push_back(std::clamp((pinchingOff && isPinchingParameter(b.name)) || it == values.end()
                                   ? b.lower
                                   : it->second,
                               b.lower, b.upper));
    }
    return s;
}

/// Keeps the pinching on in the global phase (see the header).
void keepPinchingOn(CalibrationSpec& spec, double energy) {
    const double e = std::max(energy, 1.0);
    for (Box& b : spec.fitted) {
        if (b.name == "zetaS")
            b.searchLower = 0.5;
        if (b.name == "p")
            b.searchLower = 5.0 / e;
    }
}

void addCosts(CalibrationResult& to, const CalibrationResult& from) {
    to.residualEvaluations += from.residualEvaluations;
    to.computeSeconds += from.computeSeconds;
    to.startsTried += from.startsTried;
}

constexpr std::size_t kPolishSamples = 4000; ///< the polish's first stage (Global)
constexpr int kFinalIterations = 8;          ///< its second, on the whole history

/// One Global search in the scales (uRef, the history's fRef) from the plain optimum `plain`
/// (those scales) and `extra` starts (values in those scales), after the screening when
/// `screen` (steps 1-3 of the header; without it steps 2-3 from those starts only).
CalibrationResult globalSearch(const std::vector<double>& u, const std::vector<double>& f,
                               const CalibrationRequest& request, const HistoryScales& scales,
                               const Values& plain, double uRef,
                               const std::vector<Values>& extra, bool screen) {
    CalibrationRequest moved = request;
    moved.uRef = uRef;
    const HistoryScales used = withURef(scales, uRef); // E in the scales the law runs in
    CalibrationSpec spec = defaultCalibrationSpec(moved, used);
    spec.starts = {startOf(spec.fitted, plain, true)};
    for (const Values& v : extra)
        spec.starts.push_back(startOf(spec.fitted, v, false));
    const double sum = plain.at("beta") + plain.at("gamma");
    const double zu = sum > 0 ? std::pow(plain.at("A0") / sum, 1.0 / plain.at("n")) : 1.0;
    keepPinchingOn(spec, used.energy);
    if (screen)
        spec.screened = pinchingScreenDesign(spec.fitted, plain, used.energy,
                                             std::isfinite(zu) && zu > 0 ? zu : 1.0,
                                             std::max(0, request.pinchingScreen));
    spec.screenKept = request.pinchingKept;
    spec.polished = 2;
    const bool staged = request.polishSamples == 0 && u.size() > kPolishSamples;
    if (staged)
        spec.polishSamples = kPolishSamples;
    CalibrationResult r = calibrate(u, f, spec);
    if (!staged || !r.ok)
        return r;
    // The polish's second stage: the best on the whole history.
    CalibrationSpec whole = spec;
    whole.screened.clear();
    whole.starts = {std::vector<double>(r.estimate.data(), r.estimate.data() + r.estimate.size())};
    for (Box& b : whole.fitted)
        b.searchLower = b.searchUpper = std::numeric_limits<double>::quiet_NaN();
    whole.global.maxIterations = 0; // the start as it is (one replay of the turning points)
    whole.reducedSamples = 2;
    whole.polishSamples = 0;
    whole.polished = 1;
    whole.local.maxIterations = kFinalIterations;
    CalibrationResult out = calibrate(u, f, whole);
    if (!out.ok)
        return r;
    addCosts(out, r);
    return out;
}

} // namespace

std::vector<std::vector<double>> scrambledHalton(int dims, int count, unsigned seed) {
    std::vector<int> primes;
    for (int c = 2; int(primes.size()) < dims; ++c)
        if (std::none_of(primes.begin(), primes.end(), [c](int q) { return c % q == 0; }))
            primes.push_back(c);
    std::mt19937 rng(seed);
    std::vector<std::vector<int>> permutations;
    for (int b : primes) {
        std::vector<int> perm(std::size_t(b), 0);
        std::iota(perm.begin(), perm.end(), 0);
        std::shuffle(perm.begin() + 1, perm.end(), rng);
        permutations.push_back(std::move(perm));
    }
    std::vector<std::vector<double>> points;
    for (int i = 1; i <= count; ++i) {
        std::vector<double> x;
        for (int d = 0; d < dims; ++d) {
            const int b = primes[std::size_t(d)];
            double v = 0.0, scale = 1.0 / b;
            for (int k = i; k > 0; k /= b, scale /= b)
                v += permutations[std::size_t(d)][std::size_t(k % b)] * scale;
            x.push_back(v);
        }
        points.push_back(std::move(x));
    }
    return points;
}

CalibrationResult searchPinching(const std::vector<double>& u, const std::vector<double>& f,
                                 const CalibrationRequest& request, const HistoryScales& scales,
                                 const CalibrationResult& base) {
    if (!base.ok)
        return calibrate(u, f, defaultCalibrationSpec(request, scales));
    if (request.pinchingSearch == PinchingSearch::Global) {
        const double uRef = request.uRef.value_or(base.parameters.at("uRef"));
        const double fRef = base.parameters.at("fRef");
        CalibrationResult first = globalSearch(u, f, request, scales,
                                               inScales(base.parameters, uRef, fRef), uRef, {},
                                               true);
        const double k0 = first.ok ? first.parameters.at("k0") : 1.0;
        if (request.uRef || first.cancelled || !(k0 < 0.5 || k0 > 2.0))
            return first;
        // The repeat minimizes from the first result and the plain optimum, both expressed
        // exactly in the moved scales, without a second screening: the first one covered the
        // pinching box already, and in the moved scales each replay costs several times more
        // (on the MR damper at 0 V 22.6 ms against 3.7 ms per replay of 800 samples; a
        // screened repeat cost 90 s of CPU there for a worse fit: docs/validation.md).
        const double uMoved = first.parameters.at("uRef") / k0;
        CalibrationResult again =
            globalSearch(u, f, request, scales, inScales(base.parameters, uMoved, fRef), uMoved,
                         {inScales(first.parameters, uMoved, fRef)}, false);
        CalibrationResult& kept = again.ok && again.nrmse < first.nrmse ? again : first;
        addCosts(kept, &kept == &again ? first : again);
        return std::move(kept);
    }
    CalibrationSpec spec = defaultCalibrationSpec(request, scales);
    spec.starts = {startOf(spec.fitted, base.parameters, true)};
    for (auto& s : scatteredPinchingStarts(spec.fitted, base.parameters,
                                           std::max(0, request.pinchingStarts)))
        spec.starts.push_back(std::move(s));
    keepPinchingOn(spec, scales.energy);
    spec.polished = 2;
    return calibrate(u, f, spec);
}

} // namespace hsmu
