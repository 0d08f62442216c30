#include "core/updating/PinchingUkfJobs.h"

#include "core/identification/Calibration.h"
#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryScales.h"
#include "core/updating/RobustUkfJobs.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>

namespace hsmu {

namespace {

/// The values of p for the spec's fitted parameters, in its order (a calibration start).
std::vector<double> startOf(const CalibrationSpec& spec, const BoucWenPinchingParameters& p) {
    std::vector<double> s;
    for (const auto& b : spec.fitted)
        if (const int j = pinchingUkfParameterIndex(b.name); j >= 0)
            s.push_back(PinchingUkf::field(p, j));
    return s;
}

BoucWenPinchingParameters fromCalibration(BoucWenPinchingParameters p, const CalibrationResult& r) {
    for (int j = 0; j < kPinchingUkfParameters; ++j)
        if (const auto it = r.parameters.find(pinchingUkfParameterNames()[std::size_t(j)]);
            it != r.parameters.end())
            PinchingUkf::field(p, j) = it->second;
    const auto set = [&](const char* name, double& v) {
        if (const auto it = r.parameters.find(name); it != r.parameters.end())
            v = it->second;
    };
    set("A0", p.boucWen.A0);
    set("deltaA", p.boucWen.deltaA);
    set("uRef", p.boucWen.uRef);
    set("fRef", p.boucWen.fRef);
    return p;
}

} // namespace

PinchingAnchorJobResult pinchingAnchorJob(const PinchingAnchorJobInput& in,
                                          const std::atomic<bool>* cancel) {
    const double t0 = threadCpuSeconds();
    PinchingAnchorJobResult out;
    const auto finish = [&](std::string reason) {
        out.reason = std::move(reason);
        out.cpuSeconds = threadCpuSeconds() - t0;
        return out;
    };
    try {
        const HistoryScales scales = deriveHistoryScales(in.u, in.f);
        CalibrationRequest request;
        request.law = "boucWenPinching";
        request.bounds = in.userBounds;
        request.uRef = in.uRef;
        request.fRef = in.fRef;
        request.reducedSamples = in.budget.reducedSamples;
        request.pinchingSearch = PinchingSearch::Anchor;
        request.pinchingStarts = in.budget.pinchingStarts;
        request.polishSamples = in.budget.polishSamples;
        request.localIterations = in.budget.localIterations;
        request.cancel = cancel;
        if (in.anchor)
            out.rescaled = laterAnchorScales(request, scales, in.anchor->boucWen.uRef,
                                             in.anchor->boucWen.fRef, in.rescaleFactor);
        if (!scales.ok && !(request.uRef && request.fRef))
            return finish("no anchor yet: " + scales.reason);
        const CalibrationSpec spec = defaultCalibrationSpec(request, scales);
        const double uRef = spec.fixed.at("uRef"), fRef = spec.fixed.at("fRef");
        std::optional<BoucWenPinchingParameters> anchor, estimate;
        if (in.anchor)
            anchor = rescaled(*in.anchor, uRef, fRef);
        if (in.estimate)
            estimate = rescaled(*in.estimate, uRef, fRef);
        BoucWenPinchingParameters base = anchor ? *anchor : in.initial;
        base.boucWen.uRef = uRef;
        base.boucWen.fRef = fRef;

        // The candidates, judged by their replay over the whole snapshot.
        double bestSse = std::numeric_limits<double>::infinity();
        const CalibrationResult* bestCal = nullptr;
        const auto consider = [&](const BoucWenPinchingParameters& p, const CalibrationResult* c) {
            if (!insideBox(spec, p))
                return false;
            BoucWenState state;
            double sse = 0.0;
            if (replayHistory(in.u, in.f, p, state, sse) && sse < bestSse) {
                out.best = p, out.state = state, bestSse = sse, bestCal = c;
                return true;
            }
            return false;
        };
        if (anchor)
            consider(*anchor, nullptr);
        if (estimate)
            consider(*estimate, nullptr);
        double sff = 0.0;
        for (double v : in.f)
            sff += v * v;

        CalibrationResult local, global;
        bool searchGlobally = in.global || !anchor;
        if (!searchGlobally) { // a warm start from the anchor and the estimate
            CalibrationSpec warm = spec;
            warm.starts.assign(1, startOf(spec, *anchor));
            if (estimate)
                warm.starts.push_back(startOf(spec, *estimate));
            warm.polished = 2;
            local = calibrate(in.u, in.f, warm);
            out.residualEvaluations += local.residualEvaluations;
            if (local.cancelled) {
                out.cancelled = true;
                return finish("cancelled");
            }
            if (local.ok)
                consider(fromCalibration(base, local), &local);
            // Poor: worse than poorFitRatio x the anchor at its fit (or no fit at all).
            const double nrmse = sff > 0 ? std::sqrt(bestSse / sff) : 0.0;
            searchGlobally = !local.ok || !std::isfinite(bestSse) ||
                             nrmse > in.budget.poorFitRatio * in.anchorNrmse;
        }
        if (searchGlobally) {
            global = calibrateHistory(in.u, in.f, request);
            out.residualEvaluations += global.residualEvaluations;
            out.global = true;
            if (global.cancelled) {
                out.cancelled = true;
                return finish("cancelled");
            }
            if (global.ok)
                consider(fromCalibration(base, global), &global);
        }
        if (!std::isfinite(bestSse))
            return finish("the calibration failed (" +
                          (out.global ? global.reason : local.reason) + ")");
        out.squaredErrors = bestSse;
        out.nrmse = sff > 0 ? std::sqrt(bestSse / sff) : 0.0;
        out.rmsForce = std::sqrt(sff / double(in.f.size()));
        // The UKF's box and P0 from the calibration's box and standard deviations.
        for (const auto& b : spec.fitted) {
            const int j = pinchingUkfParameterIndex(b.name);
            if (j < 0)
                continue;
            out.box[std::size_t(j)] = {b.lower, b.upper};
            out.sd[std::size_t(j)] = initialStandardDeviation(b.name, b.typical, bestCal);
        }
        if (scales.reversals >= in.verdictReversals && out.nrmse > in.verdictNrmse)
            out.modelInadequate = out.nrmse;
        out.ok = true;
    } catch (const std::exception& e) {
        return finish(std::string("the calibration failed (") + e.what() + ")");
    }
    return finish("");
}

} // namespace hsmu
