#include "core/updating/MrDamperUkfIdentifier.h"

#include "core/identification/Calibration.h"
#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryScales.h"
#include "core/updating/RobustUkfJobs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <stdexcept>

namespace hsmu {

namespace {

std::vector<std::string> layoutNames() {
    std::vector<std::string> names(mrDamperUkfParameterNames().begin(),
                                   mrDamperUkfParameterNames().end());
    names.emplace_back("uRef");
    names.emplace_back("fRef");
    return names;
}

/// p replayed over the history from the virgin state (the samples' times t, the first
/// quasi-static): the state and velocity at the end and the squared force errors.
bool replay(const std::vector<double>& u, const std::vector<double>& f,
            const std::vector<double>& t, const MrDamperParameters& p, MrDamperState& state,
            double& velocity, double& sse) {
    if (!MrDamper::admissible(p))
        return false;
    MrDamper law(p);
    sse = 0.0;
    for (std::size_t k = 0; k < u.size(); ++k) {
        law.setTimeIncrement(historyTimeIncrement(t, k));
        if (law.setTrialDeformation(u[k]) != LawStatus::Ok)
            return false;
        law.commit();
        const double e = law.committedForce() - f[k];
        sse += e * e;
    }
    state = law.committedState();
    velocity = law.trialVelocity();
    return std::isfinite(sse);
}

MrDamperParameters fromCalibration(MrDamperParameters p, const CalibrationResult& r) {
    for (int j = 0; j < kMrDamperUkfParameters; ++j)
        if (const auto it = r.parameters.find(mrDamperUkfParameterNames()[std::size_t(j)]);
            it != r.parameters.end())
            MrDamperUkf::field(p, j) = it->second;
    for (const auto& [name, field] : {std::pair{"A", &MrDamperParameters::A},
                                      std::pair{"uRef", &MrDamperParameters::uRef},
                                      std::pair{"fRef", &MrDamperParameters::fRef}})
        if (const auto it = r.parameters.find(name); it != r.parameters.end())
            p.*field = it->second;
    return p;
}

std::vector<double> startOf(const CalibrationSpec& spec, const MrDamperParameters& p) {
    std::vector<double> s;
    for (const auto& b : spec.fitted)
        if (const int j = mrDamperUkfParameterIndex(b.name); j >= 0)
            s.push_back(MrDamperUkf::field(p, j));
    return s;
}

} // namespace

MrDamperAnchorResult mrDamperAnchorJob(const MrDamperAnchorInput& in,
                                       const std::atomic<bool>* cancel) {
    const double t0 = threadCpuSeconds();
    MrDamperAnchorResult out;
    const auto finish = [&](std::string reason) {
        out.reason = std::move(reason);
        out.cpuSeconds = threadCpuSeconds() - t0;
        return out;
    };
    try {
        const HistoryScales scales = deriveHistoryScales(in.u, in.f);
        CalibrationRequest request;
        request.law = "mrDamper";
        request.bounds = in.userBounds;
        request.uRef = in.uRef;
        request.fRef = in.fRef;
        request.time = in.t;
        request.cancel = cancel;
        if (!scales.ok && !(request.uRef && request.fRef))
            return finish("no anchor yet: " + scales.reason);
        CalibrationSpec spec = defaultCalibrationSpec(request, scales);
        spec.fixed["A"] = in.initial.A; // the model's (the calibration's default is 1)
        MrDamperParameters base = in.initial;
        base.uRef = spec.fixed.at("uRef");
        base.fRef = spec.fixed.at("fRef");

        double bestSse = std::numeric_limits<double>::infinity();
        const CalibrationResult* bestCal = nullptr;
        const auto consider = [&](const MrDamperParameters& p, const CalibrationResult* c) {
            MrDamperState state;
            double velocity = 0.0, sse = 0.0;
            if (replay(in.u, in.f, in.t, p, state, velocity, sse) && sse < bestSse) {
                out.best = p;
                out.state = state;
                out.velocity = velocity;
                bestSse = sse;
                bestCal = c;
            }
        };
        if (in.anchor)
            consider(*in.anchor, nullptr);
        if (in.estimate)
            consider(*in.estimate, nullptr);
        double sff = 0.0;
        for (double v : in.f)
            sff += v * v;

        CalibrationResult local, global;
        bool searchGlobally = in.global || !in.anchor;
        if (!searchGlobally) { // a warm start from the anchor and the estimate
            CalibrationSpec warm = spec;
            warm.starts.assign(1, startOf(spec, *in.anchor));
            if (in.estimate)
                warm.starts.push_back(startOf(spec, *in.estimate));
            warm.polished = 2;
            warm.global.maxIterations = warm.local.maxIterations =
                std::max(1, in.settings.localIterations);
            local = calibrate(in.u, in.f, warm);
            out.residualEvaluations += local.residualEvaluations;
            if (local.cancelled) {
                out.cancelled = true;
                return finish("cancelled");
            }
            if (local.ok)
                consider(fromCalibration(base, local), &local);
            const double nrmse = sff > 0 ? std::sqrt(bestSse / sff) : 0.0;
            searchGlobally = !local.ok || !std::isfinite(bestSse) ||
                             nrmse > in.settings.poorFitRatio * in.anchorNrmse;
        }
        if (searchGlobally) {
            global = calibrate(in.u, in.f, spec);
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
        for (const auto& b : spec.fitted) {
            const int j = mrDamperUkfParameterIndex(b.name);
            if (j < 0)
                continue;
            out.box[std::size_t(j)] = {b.lower, b.upper};
            out.sd[std::size_t(j)] = initialStandardDeviation(b.name, b.typical, bestCal);
        }
        // a parameter the user did not let the calibration fit: held at its value
        for (int j = 0; j < kMrDamperUkfParameters; ++j)
            if (!std::isfinite(out.box[std::size_t(j)].lower)) {
                const double v = MrDamperUkf::field(out.best, j);
                out.box[std::size_t(j)] = {v, v};
                out.sd[std::size_t(j)] = 0.0;
            }
        if (scales.reversals >= in.settings.verdictReversals &&
            out.nrmse > in.settings.verdictNrmse)
            out.modelInadequate = out.nrmse;
        out.ok = true;
    } catch (const std::exception& e) {
        return finish(std::string("the calibration failed (") + e.what() + ")");
    }
    return finish("");
}

MrDamperUkfIdentifier::MrDamperUkfIdentifier(const MrDamper& model, std::optional<double> uRef,
                                             std::optional<double> fRef,
                                             const ParameterBoundsMap& bounds,
                                             const MrDamperUkfIdentifierSettings& settings)
    : AnchoredUkf(model.parameters(), settings), m_model(model.parameters()),
      m_dt(model.timeIncrement()), m_uRef(uRef), m_fRef(fRef), m_userBounds(bounds),
      m_layout(layoutNames()), m_settings(settings) {
    if (!(m_dt > 0.0) || !std::isfinite(m_dt))
        throw std::invalid_argument("the MR damper UKF needs the samples' time step (the "
                                    "model's time increment)");
    for (const auto& [name, b] : bounds)
        if (mrDamperUkfParameterIndex(name) < 0)
            throw std::invalid_argument("updating.bounds: '" + name +
                                        "' is not identified by the MR damper UKF (expected c0, "
                                        "c1, k0, k1, f0, alpha, beta, gamma, n)");
    if (uRef)
        m_model.uRef = *uRef;
    if (fRef)
        m_model.fRef = *fRef;
    // Until the first anchor: the default box at unit scales, the user's bounds on top.
    CalibrationRequest request;
    request.law = "mrDamper";
    request.bounds = bounds;
    m_bounds.fill({NAN, NAN});
    for (const auto& b : defaultCalibrationSpec(request, HistoryScales{true, "", 1, 1, 1, 1}).fitted)
        if (const int j = mrDamperUkfParameterIndex(b.name); j >= 0)
            m_bounds[std::size_t(j)] = {b.lower, b.upper};
    m_anchor = m_model;
    publish(m_model);
}

void MrDamperUkfIdentifier::publish(const MrDamperParameters& p) {
    m_published = p;
    MrDamperUkf::Values sd{};
    if (m_ukf)
        sd = m_ukf->standardDeviation();
    for (int j = 0; j < kMrDamperUkfParameters; ++j) {
        m_estimate[std::size_t(j)] = MrDamperUkf::field(p, j);
        m_stddev[std::size_t(j)] = sd[std::size_t(j)];
    }
    m_estimate[kMrDamperUkfParameters] = p.uRef;
    m_estimate[kMrDamperUkfParameters + 1] = p.fRef;
}

bool MrDamperUkfIdentifier::setBounds(std::size_t index, const ParameterBounds& b) {
    if (index >= std::size_t(kMrDamperUkfParameters) || !std::isfinite(b.lower) ||
        !std::isfinite(b.upper) || !(b.lower <= b.upper))
        return false;
    m_userBounds[m_layout.name(index)] = b;
    m_bounds[index] = b;
    return true; // effective at the next anchor
}

bool MrDamperUkfIdentifier::finite(const MrDamperParameters& p) const {
    bool ok = true;
    for (int j = 0; j < kMrDamperUkfParameters; ++j)
        ok = ok && std::isfinite(MrDamperUkf::field(p, j));
    return ok;
}

MrDamperUkfIdentifier::FilterStep MrDamperUkfIdentifier::stepFilter(double u, double f) {
    const MrDamperUkfStep s = m_ukf->step(u, f);
    return {s.status.ok, s.status.reason, s.predictedForce, m_ukf->estimate()};
}

void MrDamperUkfIdentifier::restartFilter(const MrDamperState& state, double u) {
    m_ukf->restart(m_anchor, state, u, m_fit.sd);
}

std::string MrDamperUkfIdentifier::startFilter(const MrDamperAnchorResult& r,
                                               const MrDamperState& state, double u) {
    MrDamperUkfSettings us;
    us.forceNoise = std::max(anchorRms(), 1e-3);
    us.stateNoise = 1e-2 * us.forceNoise;
    us.parameterNoise = m_settings.parameterNoise;
    try {
        m_ukf.emplace(r.best, r.box, m_dt, us);
    } catch (const std::exception& e) {
        return e.what();
    }
    for (int j = 0; j < kMrDamperUkfParameters; ++j)
        m_bounds[std::size_t(j)] = r.box[std::size_t(j)];
    m_ukf->restart(r.best, state, u, r.sd);
    return "";
}

MrDamper MrDamperUkfIdentifier::anchorLaw(const MrDamperAnchorResult& r, double uPrevious) const {
    MrDamper law(r.best);
    law.setTimeIncrement(m_dt);
    law.setCommittedState(r.state, uPrevious, r.velocity);
    return law;
}

MrDamperUkfIdentifier::AnchorWork MrDamperUkfIdentifier::anchorWork(bool global, bool diverged) {
    MrDamperAnchorInput in;
    in.u = m_u;
    in.f = m_f;
    in.t = m_t;
    in.uRef = m_uRef;
    in.fRef = m_fRef;
    if (m_anchors > 0) {
        in.anchor = m_anchor;
        in.anchorNrmse = anchorNrmse();
        in.uRef = m_anchor.uRef; // the scales stay those of the first anchor
        in.fRef = m_anchor.fRef;
    }
    if (m_ukf && !diverged)
        in.estimate = m_ukf->estimate();
    in.initial = m_model;
    in.userBounds = m_userBounds;
    in.global = global;
    in.settings = m_settings;
    return [in = std::move(in)](const std::atomic<bool>& cancel) {
        return mrDamperAnchorJob(in, &cancel);
    };
}

MrDamperUkfIdentifier::VerifyWork
MrDamperUkfIdentifier::verifyWork(const MrDamperParameters& p) const {
    return [u = m_u, f = m_f, t = m_t, p] {
        const double t0 = threadCpuSeconds();
        VerifyJobResult r;
        MrDamperState state;
        double velocity = 0.0, sse = 0.0, sff = 0.0;
        for (double v : f)
            sff += v * v;
        r.ok = replay(u, f, t, p, state, velocity, sse);
        r.nrmse = sff > 0 ? std::sqrt(sse / sff) : 0.0;
        r.ok = r.ok && std::isfinite(r.nrmse);
        r.cpuSeconds = threadCpuSeconds() - t0;
        return r;
    };
}

AnchorPlan MrDamperUkfIdentifier::plan(std::size_t n) {
    if (double(n) >= m_settings.globalGrowth * double(m_globalSize))
        return AnchorPlan::GlobalAnchor;
    if (double(n) >= m_settings.anchorGrowth * double(m_anchorSize))
        return AnchorPlan::LocalAnchor;
    return AnchorPlan::VerifyOnly;
}

} // namespace hsmu
