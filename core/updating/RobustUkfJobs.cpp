#include "core/updating/RobustUkfJobs.h"

#include "core/identification/Calibration.h"
#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryScales.h"
#include "core/identification/PinchingUkf.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>

namespace hsmu {

double& robustUkfField(BoucWenParameters& p, BoucWenUkfIndex i) {
    switch (i) {
    case BoucWenUkfIndex::K0:
        return p.k0;
    case BoucWenUkfIndex::Alpha:
        return p.alpha;
    case BoucWenUkfIndex::Beta:
        return p.beta;
    case BoucWenUkfIndex::Gamma:
        return p.gamma;
    case BoucWenUkfIndex::N:
        return p.n;
    case BoucWenUkfIndex::DeltaNu:
        return p.deltaNu;
    default:
        return p.deltaEta;
    }
}

namespace {

/// The values of p for the spec's fitted parameters, in its order (a calibration start).
std::vector<double> startOf(const CalibrationSpec& spec, BoucWenParameters p) {
    std::vector<double> s;
    for (const auto& q : spec.fitted)
        for (BoucWenUkfIndex i : kRobustUkfParameters)
            if (q.name == boucWenUkfIndexName(i))
                s.push_back(robustUkfField(p, i));
    return s;
}

BoucWenParameters fromCalibration(const BoucWenParameters& initial, const CalibrationResult& r) {
    BoucWenParameters p = initial;
    const auto value = [&](const char* name, double fallback) {
        auto it = r.parameters.find(name);
        return it != r.parameters.end() ? it->second : fallback;
    };
    p.k0 = value("k0", p.k0);
    p.alpha = value("alpha", p.alpha);
    p.n = value("n", p.n);
    p.beta = value("beta", p.beta);
    p.gamma = value("gamma", p.gamma);
    p.A0 = value("A0", p.A0);
    p.deltaA = value("deltaA", p.deltaA);
    p.deltaNu = value("deltaNu", p.deltaNu);
    p.deltaEta = value("deltaEta", p.deltaEta);
    p.uRef = value("uRef", p.uRef);
    p.fRef = value("fRef", p.fRef);
    return p;
}

template <class Law, class Parameters>
bool replayLaw(const std::vector<double>& u, const std::vector<double>& f, const Parameters& p,
               BoucWenState& state, double& squaredErrors) {
    if (!Law::admissible(p))
        return false;
    Law law(p);
    double sum = 0.0;
    for (std::size_t k = 0; k < u.size(); ++k) {
        if (law.setTrialDeformation(u[k]) != LawStatus::Ok)
            return false;
        law.commit();
        const double e = law.committedForce() - f[k];
        sum += e * e;
    }
    state = law.committedState();
    squaredErrors = sum;
    return std::isfinite(sum);
}

template <class Parameters>
VerifyJobResult verifyLaw(const std::vector<double>& u, const std::vector<double>& f,
                          const Parameters& p) {
    const double t0 = threadCpuSeconds();
    VerifyJobResult r;
    BoucWenState state;
    double sse = 0.0, sff = 0.0;
    for (double v : f)
        sff += v * v;
    r.ok = replayHistory(u, f, p, state, sse);
    r.nrmse = sff > 0 ? std::sqrt(sse / sff) : 0.0;
    r.ok = r.ok && std::isfinite(r.nrmse);
    r.cpuSeconds = threadCpuSeconds() - t0;
    return r;
}

double sumOfSquares(const std::vector<double>& f) {
    double s = 0.0;
    for (double v : f)
        s += v * v;
    return s;
}

bool movedBy(double a, double b, double factor) {
    return a > factor * b || b > factor * a;
}

/// insideBox() with valueOf(name) the value of the fitted parameter `name` (NaN: not checked).
template <class ValueOf>
bool insideBoxOf(const CalibrationSpec& spec, ValueOf valueOf) {
    for (const auto& b : spec.fitted) {
        const double v = valueOf(b.name);
        if (!std::isnan(v) && !(v >= b.lower && v <= b.upper))
            return false;
    }
    return true;
}

} // namespace

bool insideBox(const CalibrationSpec& spec, const BoucWenParameters& p) {
    return insideBoxOf(spec, [&](const std::string& name) {
        BoucWenParameters q = p;
        for (BoucWenUkfIndex i : kRobustUkfParameters)
            if (name == boucWenUkfIndexName(i))
                return robustUkfField(q, i);
        return std::nan("");
    });
}

bool insideBox(const CalibrationSpec& spec, const BoucWenPinchingParameters& p) {
    return insideBoxOf(spec, [&](const std::string& name) {
        const int j = pinchingUkfParameterIndex(name);
        return j >= 0 ? PinchingUkf::field(p, j) : std::nan("");
    });
}

bool laterAnchorScales(CalibrationRequest& request, const HistoryScales& scales, double uRef,
                       double fRef, double factor) {
    const bool move = scales.ok && (movedBy(scales.uRef, uRef, factor) ||
                                    movedBy(scales.fRef, fRef, factor));
    const bool configured = request.uRef && request.fRef;
    if (!request.uRef)
        request.uRef = move ? scales.uRef : uRef;
    if (!request.fRef)
        request.fRef = move ? scales.fRef : fRef;
    return move && !configured;
}

double initialStandardDeviation(const std::string& name, double typical,
                                const CalibrationResult* cal) {
    double fromFit = std::nan("");
    if (cal)
        for (std::size_t q = 0; q < cal->names.size(); ++q)
            if (cal->names[q] == name && Eigen::Index(q) < cal->standardDeviation.size())
                fromFit = cal->standardDeviation[Eigen::Index(q)];
    const double floor = 1e-2 * typical, cap = 0.1 * typical;
    return std::clamp(std::isfinite(fromFit) ? fromFit : floor, floor, cap);
}

double threadCpuSeconds() {
#if defined(CLOCK_THREAD_CPUTIME_ID)
    timespec t{};
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t) == 0)
        return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
#endif
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

bool replayHistory(const std::vector<double>& u, const std::vector<double>& f,
                   const BoucWenParameters& p, BoucWenState& state, double& squaredErrors) {
    return replayLaw<BoucWen>(u, f, p, state, squaredErrors);
}

bool replayHistory(const std::vector<double>& u, const std::vector<double>& f,
                   const BoucWenPinchingParameters& p, BoucWenState& state,
                   double& squaredErrors) {
    return replayLaw<BoucWenPinching>(u, f, p, state, squaredErrors);
}

VerifyJobResult verifyJob(const std::vector<double>& u, const std::vector<double>& f,
                          const BoucWenParameters& p) {
    return verifyLaw(u, f, p);
}

VerifyJobResult verifyJob(const std::vector<double>& u, const std::vector<double>& f,
                          const BoucWenPinchingParameters& p) {
    return verifyLaw(u, f, p);
}

AnchorJobResult anchorJob(const AnchorJobInput& in, const std::atomic<bool>* cancel) {
    const double t0 = threadCpuSeconds();
    AnchorJobResult out;
    out.global = in.global || !in.anchor;
    try {
        const HistoryScales scales = deriveHistoryScales(in.u, in.f);
        CalibrationRequest request;
        request.bounds = in.userBounds;
        request.uRef = in.uRef;
        request.fRef = in.fRef;
        if (in.anchor)
            out.rescaled = laterAnchorScales(request, scales, in.anchor->uRef, in.anchor->fRef,
                                             in.rescaleFactor);
        if (!scales.ok && !(request.uRef && request.fRef)) {
            out.reason = "no anchor yet: " + scales.reason;
            out.cpuSeconds = threadCpuSeconds() - t0;
            return out;
        }
        CalibrationSpec spec = defaultCalibrationSpec(request, scales);
        const double uRef = spec.fixed.at("uRef"), fRef = spec.fixed.at("fRef");
        std::optional<BoucWenParameters> anchor, estimate;
        if (in.anchor)
            anchor = rescaled(*in.anchor, uRef, fRef);
        if (in.estimate)
            estimate = rescaled(*in.estimate, uRef, fRef);
        if (anchor && !in.global) // a local refit: from the anchor (and the estimate) only
            spec.starts.assign(1, startOf(spec, *anchor));
        if (estimate) { // the current estimate is one more start
            std::vector<double> s = startOf(spec, *estimate);
            if (s.size() == spec.fitted.size())
                spec.starts.push_back(std::move(s));
        }
        spec.cancel = cancel;
        const CalibrationResult cal = calibrate(in.u, in.f, spec);
        if (cal.cancelled) {
            out.cancelled = true;
            out.reason = "cancelled";
            out.cpuSeconds = threadCpuSeconds() - t0;
            return out;
        }
        const double sff = sumOfSquares(in.f);
        double bestSse = std::numeric_limits<double>::infinity(), sse = 0.0;
        BoucWenState state;
        if (estimate && insideBox(spec, *estimate) &&
            replayHistory(in.u, in.f, *estimate, state, sse))
            out.best = *estimate, out.state = state, bestSse = sse;
        if (cal.ok) {
            const BoucWenParameters p = fromCalibration(in.initial, cal);
            if (insideBox(spec, p) && replayHistory(in.u, in.f, p, state, sse) && sse < bestSse)
                out.best = p, out.state = state, bestSse = sse;
        }
        if (!std::isfinite(bestSse)) {
            out.reason = "the calibration failed (" + cal.reason + ")";
            out.cpuSeconds = threadCpuSeconds() - t0;
            return out;
        }
        out.squaredErrors = bestSse;
        out.nrmse = sff > 0 ? std::sqrt(bestSse / sff) : 0.0;
        out.rmsForce = std::sqrt(sff / double(in.f.size()));
        // The UKF's box and P0 from the calibration's box and standard deviations.
        out.box = BoucWenUkf::tableIIIBounds();
        out.sd.fill(0.0);
        out.sd[0] = 1e-3;
        out.sd[1] = 1e-3;
        for (std::size_t q = 0; q < spec.fitted.size(); ++q)
            for (BoucWenUkfIndex i : kRobustUkfParameters)
                if (spec.fitted[q].name == boucWenUkfIndexName(i)) {
                    const auto at = std::size_t(i);
                    out.box[at] = {spec.fitted[q].lower, spec.fitted[q].upper};
                    out.sd[at] = initialStandardDeviation(spec.fitted[q].name,
                                                          spec.fitted[q].typical,
                                                          cal.ok ? &cal : nullptr);
                }
        if (scales.reversals >= in.verdictReversals && out.nrmse > in.verdictNrmse)
            out.modelInadequate = out.nrmse;
        out.ok = true;
    } catch (const std::exception& e) {
        out.ok = false;
        out.reason = std::string("the calibration failed (") + e.what() + ")";
    }
    out.cpuSeconds = threadCpuSeconds() - t0;
    return out;
}

} // namespace hsmu
