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

/// UKF steps rejected in a row (a sigma point the law cannot integrate) before a refit.
constexpr int kRejectionsBeforeReanchor = 3;

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
            double fromFit = std::nan("");
            if (bestCal)
                for (std::size_t q = 0; q < bestCal->names.size(); ++q)
                    if (bestCal->names[q] == b.name)
                        fromFit = bestCal->standardDeviation[Eigen::Index(q)];
            const double floor = 1e-2 * b.typical, cap = 0.1 * b.typical;
            out.sd[std::size_t(j)] =
                std::clamp(std::isfinite(fromFit) ? fromFit : floor, floor, cap);
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
    : m_model(model.parameters()), m_dt(model.timeIncrement()), m_uRef(uRef), m_fRef(fRef),
      m_userBounds(bounds), m_layout(layoutNames()), m_settings(settings) {
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
    m_anchor = m_published = m_model;
    m_window.assign(std::size_t(std::max(1, m_settings.divergenceWindow)), 0.0);
    m_anchorWindow = m_window;
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

bool MrDamperUkfIdentifier::warmedUp() {
    const std::size_t n = m_u.size();
    if (n < m_nextWarmUpCheck)
        return false;
    m_nextWarmUpCheck = n + std::max<std::size_t>(1, n / 50);
    return int(turningPoints(m_u, 0.02 * (m_uMax - m_uMin)).size()) >= m_settings.warmUpReversals;
}

double MrDamperUkfIdentifier::anchorHistoryNrmse() const {
    return m_sumF2 > 0 ? std::sqrt(m_anchorSse / m_sumF2) : 0.0;
}

double MrDamperUkfIdentifier::replayNrmse(const MrDamperParameters& p) const {
    MrDamperState state;
    double velocity = 0.0, sse = 0.0;
    if (!replay(m_u, m_f, m_t, p, state, velocity, sse))
        return std::nan("");
    return m_sumF2 > 0 ? std::sqrt(sse / m_sumF2) : 0.0;
}

void MrDamperUkfIdentifier::clearWindows() {
    std::fill(m_window.begin(), m_window.end(), 0.0);
    std::fill(m_anchorWindow.begin(), m_anchorWindow.end(), 0.0);
    m_windowSum = m_anchorWindowSum = 0.0;
    m_windowNext = m_windowFill = 0;
}

void MrDamperUkfIdentifier::restartAtAnchor() {
    m_ukf->restart(m_anchor, m_anchorLaw->committedState(), m_u.back(), m_anchorSd);
}

void MrDamperUkfIdentifier::startAnchor(bool global, bool diverged) {
    MrDamperAnchorInput in;
    in.u = m_u;
    in.f = m_f;
    in.t = m_t;
    in.uRef = m_uRef;
    in.fRef = m_fRef;
    if (m_anchors > 0) {
        in.anchor = m_anchor;
        in.anchorNrmse = m_anchorNrmse;
        in.uRef = m_anchor.uRef; // the scales stay those of the first anchor
        in.fRef = m_anchor.fRef;
    }
    if (m_ukf && !diverged)
        in.estimate = m_ukf->estimate();
    in.initial = m_model;
    in.userBounds = m_userBounds;
    in.global = global;
    in.settings = m_settings;
    m_job.start(m_u.size(), JobMeta{diverged}, [in = std::move(in)](const std::atomic<bool>& cancel) {
        return mrDamperAnchorJob(in, &cancel);
    });
}

IdentificationStatus MrDamperUkfIdentifier::applyAnchor() {
    Job::Taken taken = m_job.take();
    const bool diverged = taken.meta.diverged;
    const MrDamperAnchorResult& r = taken.outcome;
    const std::size_t startSize = taken.startSize;
    IdentificationStatus st;
    m_lastSeconds = r.cpuSeconds;
    if (!r.ok) {
        st.ok = !diverged;
        st.message = "MR damper UKF: no anchor: " + r.reason;
        return st;
    }
    // Catch up over the samples measured since the job started.
    MrDamper law(r.best);
    law.setTimeIncrement(m_dt);
    law.setCommittedState(r.state, m_u[startSize - 1], r.velocity);
    double sse = r.squaredErrors;
    for (std::size_t k = startSize; k < m_u.size(); ++k) {
        if (law.setTrialDeformation(m_u[k]) != LawStatus::Ok) {
            st.ok = !diverged;
            st.message = "MR damper UKF: no anchor: its law fails on the samples since the "
                         "calibration";
            return st;
        }
        law.commit();
        const double e = law.committedForce() - m_f[k];
        sse += e * e;
    }
    MrDamperUkfSettings us;
    m_anchorRms = r.nrmse * r.rmsForce / r.best.fRef;
    us.forceNoise = std::max(m_anchorRms, 1e-3);
    us.stateNoise = 1e-2 * us.forceNoise;
    us.parameterNoise = m_settings.parameterNoise;
    try {
        m_ukf.emplace(r.best, r.box, m_dt, us);
    } catch (const std::exception& e) {
        st.ok = false;
        st.message = std::string("MR damper UKF: no anchor: ") + e.what();
        return st;
    }
    for (int j = 0; j < kMrDamperUkfParameters; ++j)
        m_bounds[std::size_t(j)] = r.box[std::size_t(j)];
    m_anchorLaw.emplace(std::move(law));
    m_anchorSse = sse;
    m_anchor = r.best;
    m_anchorSd = r.sd;
    m_anchorNrmse = r.nrmse;
    m_anchorSize = startSize;
    if (r.global) {
        m_globalSize = startSize;
        ++m_globalAnchors;
    }
    restartAtAnchor();
    clearWindows();
    m_rejectedInRow = 0;
    ++m_anchors;
    publish(r.best);
    m_nextCheck = m_u.size() + scheduledJobDelay(m_u.size());
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  "MR damper UKF %s %d (%s) at a fit over %zu samples: NRMSE %.4f",
                  diverged ? "restarted, anchor" : "anchor", m_anchors,
                  r.global ? "calibration" : "local refit", startSize, r.nrmse);
    st.message = buf;
    st.updated = true;
    st.refit = true;
    if (r.modelInadequate)
        st.modelInadequate = r.modelInadequate;
    return st;
}

IdentificationStatus MrDamperUkfIdentifier::observe(double deformation, double force, bool) {
    IdentificationStatus st;
    if (!std::isfinite(deformation) || !std::isfinite(force)) {
        st.ok = false;
        st.message = "the measured deformation or force is not finite: step skipped";
        return st;
    }
    m_t.push_back(double(m_u.size()) * m_dt);
    m_u.push_back(deformation);
    m_f.push_back(force);
    m_uMin = m_u.size() == 1 ? deformation : std::min(m_uMin, deformation);
    m_uMax = m_u.size() == 1 ? deformation : std::max(m_uMax, deformation);
    m_sumF2 += force * force;
    const std::size_t n = m_u.size();
    if (!m_ukf) {
        st.reportable = false;
        m_predicted = std::numeric_limits<double>::quiet_NaN();
        if (m_job.running()) {
            if (m_job.due(n)) {
                st = applyAnchor();
                st.reportable = m_ukf.has_value();
            }
            return st;
        }
        if (warmedUp())
            startAnchor(true, false);
        return st;
    }
    const MrDamperUkfStep s = m_ukf->step(deformation, force);
    m_predicted = s.predictedForce;
    // divergence watch: the filter's a-priori error against the anchor model's own
    const double fRef = m_anchor.fRef;
    const bool anchorFailed = m_anchorLaw->setTrialDeformation(deformation) != LawStatus::Ok;
    double a = 0.0;
    if (!anchorFailed) {
        m_anchorLaw->commit();
        const double err = m_anchorLaw->committedForce() - force;
        m_anchorSse += err * err;
        a = err / fRef;
    }
    m_rejectedInRow = s.status.ok ? 0 : m_rejectedInRow + 1;
    const double e = (s.predictedForce - force) / fRef;
    const std::size_t w = m_window.size();
    const double e2 = std::isfinite(e) ? e * e : 1e300;
    m_windowSum += e2 - m_window[m_windowNext];
    m_anchorWindowSum += a * a - m_anchorWindow[m_windowNext];
    m_window[m_windowNext] = e2;
    m_anchorWindow[m_windowNext] = a * a;
    m_windowNext = (m_windowNext + 1) % w;
    m_windowFill = std::min(m_windowFill + 1, w);
    const MrDamperParameters now = m_ukf->estimate();
    bool finite = std::isfinite(s.predictedForce);
    for (int j = 0; j < kMrDamperUkfParameters; ++j)
        finite = finite && std::isfinite(MrDamperUkf::field(now, j));
    const double rms = std::sqrt(std::max(m_windowSum, 0.0) / double(w));
    const double reference = std::max({std::sqrt(std::max(m_anchorWindowSum, 0.0) / double(w)),
                                       m_anchorRms, m_settings.divergenceFloor});
    const bool lawFailed = anchorFailed || m_rejectedInRow >= kRejectionsBeforeReanchor;
    if (!finite || lawFailed ||
        (m_windowFill == w && rms > m_settings.divergenceRatio * reference)) {
        char buf[240];
        if (lawFailed) {
            std::snprintf(buf, sizeof buf, "%s: restarted from the anchor",
                          anchorFailed ? "the MR damper UKF's anchor model failed on the new "
                                         "deformation"
                                       : "MR damper UKF steps rejected in a row");
            m_rejectedInRow = 0;
        } else {
            ++m_divergences;
            std::snprintf(buf, sizeof buf,
                          "MR damper UKF diverging (a-priori force error %.3g of fRef over the "
                          "last %zu steps, the anchor's %.3g): restarted from the anchor",
                          rms, w, reference);
        }
        st.ok = false;
        st.message = buf;
        if (!anchorFailed)
            restartAtAnchor();
        publish(m_anchor);
        clearWindows();
        m_recovering = int(w);
        if (!m_job.running()) {
            startAnchor(anchorFailed, true);
            st.message += ", a refit started";
        }
        st.reportable = false;
        st.updated = true;
        return st;
    }
    if (!s.status.ok) {
        st.ok = false;
        st.message = "MR damper UKF step rejected: " + s.status.reason;
    }
    if (m_recovering > 0)
        --m_recovering;
    const bool reportable = m_recovering == 0;
    if (m_job.due(n)) {
        IdentificationStatus j = applyAnchor();
        if (!j.message.empty() || !j.ok)
            st = j;
        st.updated = st.updated || j.updated;
        st.refit = j.refit;
    } else if (!m_job.running()) {
        if (double(n) >= m_settings.globalGrowth * double(m_globalSize)) {
            startAnchor(true, false);
        } else if (double(n) >= m_settings.anchorGrowth * double(m_anchorSize)) {
            startAnchor(false, false);
        } else if (n >= m_nextCheck) {
            // The guard: the whole history decides, not the one-step prediction.
            m_nextCheck = n + scheduledJobDelay(n);
            const double nrmse = replayNrmse(now);
            const double anchorNow = anchorHistoryNrmse();
            if (std::isfinite(nrmse) && nrmse <= m_settings.driftRatio * anchorNow) {
                publish(now);
            } else {
                restartAtAnchor();
                publish(m_anchor);
                char buf[200];
                std::snprintf(buf, sizeof buf,
                              "MR damper UKF estimate replays the history with NRMSE %.3g "
                              "against the anchor's %.3g: back to the anchor",
                              nrmse, anchorNow);
                st.message = buf;
            }
            st.updated = true;
        }
    }
    st.reportable = reportable;
    return st;
}

} // namespace hsmu
