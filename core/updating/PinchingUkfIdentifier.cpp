#include "core/updating/PinchingUkfIdentifier.h"

#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryScales.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace hsmu {

namespace {

/// UKF steps rejected in a row (a sigma point the law cannot integrate) before a refit.
constexpr int kRejectionsBeforeReanchor = 3;

std::vector<std::string> layoutNames() {
    std::vector<std::string> names(pinchingUkfParameterNames().begin(),
                                   pinchingUkfParameterNames().end());
    names.emplace_back("uRef");
    names.emplace_back("fRef");
    return names;
}

} // namespace

PinchingUkfIdentifier::PinchingUkfIdentifier(const BoucWenPinchingParameters& initial,
                                             std::optional<double> uRef,
                                             std::optional<double> fRef,
                                             const ParameterBoundsMap& bounds,
                                             const PinchingUkfIdentifierSettings& settings)
    : m_initial(initial), m_uRef(uRef), m_fRef(fRef), m_userBounds(bounds),
      m_layout(layoutNames()), m_settings(settings) {
    for (const auto& [name, b] : bounds)
        if (pinchingUkfParameterIndex(name) < 0)
            throw std::invalid_argument("updating.bounds: '" + name +
                                        "' is not identified by the pinching UKF (expected k0, "
                                        "alpha, n, beta, gamma, deltaNu, deltaEta, zetaS, p, q, "
                                        "psi, deltaPsi, lambda)");
    if (uRef)
        m_initial.boucWen.uRef = *uRef;
    if (fRef)
        m_initial.boucWen.fRef = *fRef;
    // Until the first anchor: the default box at unit scales, the user's bounds on top.
    CalibrationRequest request;
    request.law = "boucWenPinching";
    request.bounds = bounds;
    m_bounds.fill({NAN, NAN});
    for (const auto& b : defaultCalibrationSpec(request, HistoryScales{true, "", 1, 1, 1, 1}).fitted)
        if (const int j = pinchingUkfParameterIndex(b.name); j >= 0)
            m_bounds[std::size_t(j)] = {b.lower, b.upper};
    m_anchor = m_published = m_initial;
    m_window.assign(std::size_t(std::max(1, m_settings.divergenceWindow)), 0.0);
    m_anchorWindow = m_window;
    publish(m_initial);
}

void PinchingUkfIdentifier::publish(const BoucWenPinchingParameters& p) {
    m_published = p;
    std::array<double, kPinchingUkfParameters> sd{};
    if (m_ukf)
        sd = m_ukf->standardDeviation();
    for (int j = 0; j < kPinchingUkfParameters; ++j) {
        m_estimate[std::size_t(j)] = PinchingUkf::field(p, j);
        m_stddev[std::size_t(j)] = sd[std::size_t(j)];
    }
    m_estimate[kPinchingUkfParameters] = p.boucWen.uRef;
    m_estimate[kPinchingUkfParameters + 1] = p.boucWen.fRef;
}

bool PinchingUkfIdentifier::setBounds(std::size_t index, const ParameterBounds& b) {
    if (index >= std::size_t(kPinchingUkfParameters) || !std::isfinite(b.lower) ||
        !std::isfinite(b.upper) || !(b.lower <= b.upper))
        return false;
    m_userBounds[m_layout.name(index)] = b;
    m_bounds[index] = b;
    return true; // effective at the next anchor
}

bool PinchingUkfIdentifier::warmedUp() {
    const std::size_t n = m_u.size();
    if (n < m_nextWarmUpCheck)
        return false;
    m_nextWarmUpCheck = n + std::max<std::size_t>(1, n / 50);
    return int(turningPoints(m_u, 0.02 * (m_uMax - m_uMin)).size()) >= m_settings.warmUpReversals;
}

double PinchingUkfIdentifier::anchorHistoryNrmse() const {
    return m_sumF2 > 0 ? std::sqrt(m_anchorSse / m_sumF2) : 0.0;
}

void PinchingUkfIdentifier::clearWindows() {
    std::fill(m_window.begin(), m_window.end(), 0.0);
    std::fill(m_anchorWindow.begin(), m_anchorWindow.end(), 0.0);
    m_windowSum = m_anchorWindowSum = 0.0;
    m_windowNext = m_windowFill = 0;
}

void PinchingUkfIdentifier::restartAtAnchor() {
    m_ukf->restart(m_anchor, m_anchorLaw->committedState(), m_u.back(), m_anchorSd);
}

void PinchingUkfIdentifier::startAnchor(bool global, bool diverged) {
    PinchingAnchorJobInput in;
    in.u = m_u;
    in.f = m_f;
    in.uRef = m_uRef;
    in.fRef = m_fRef;
    if (m_anchors > 0) {
        in.anchor = m_anchor;
        in.anchorNrmse = m_anchorNrmse;
    }
    if (m_ukf && !diverged)
        in.estimate = m_ukf->estimate();
    in.initial = m_initial;
    in.userBounds = m_userBounds;
    in.global = global;
    in.budget = m_settings.budget;
    in.rescaleFactor = m_settings.rescaleFactor;
    in.verdictReversals = m_settings.verdictReversals;
    in.verdictNrmse = m_settings.verdictNrmse;
    JobMeta meta;
    meta.anchor = true;
    meta.diverged = diverged;
    m_job.start(m_u.size(), meta, [in = std::move(in)](const std::atomic<bool>& cancel) {
        return JobOutcome{pinchingAnchorJob(in, &cancel), {}};
    });
}

void PinchingUkfIdentifier::startVerify(const BoucWenPinchingParameters& candidate) {
    JobMeta meta;
    meta.anchorNrmseAtStart = anchorHistoryNrmse();
    meta.candidate = candidate;
    m_job.start(m_u.size(), meta, [u = m_u, f = m_f, candidate](const std::atomic<bool>&) {
        return JobOutcome{{}, verifyJob(u, f, candidate)};
    });
}

IdentificationStatus PinchingUkfIdentifier::applyJob() {
    Job::Taken taken = m_job.take();
    const JobMeta& job = taken.meta;
    const JobOutcome& out = taken.outcome;
    m_workerCpu += out.anchor.cpuSeconds + out.verify.cpuSeconds;
    m_anchorCpu += out.anchor.cpuSeconds;
    if (job.anchor)
        return applyAnchor(job, taken.startSize, out.anchor);
    IdentificationStatus st;
    if (job.discarded || !m_ukf)
        return st;
    const VerifyJobResult& v = out.verify;
    const double na = job.anchorNrmseAtStart;
    if (!v.ok || v.nrmse > m_settings.driftRatio * na) {
        restartAtAnchor();
        publish(m_anchor);
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "pinching UKF estimate replays the history with NRMSE %.3g against the "
                      "anchor's %.3g: back to the anchor",
                      v.ok ? v.nrmse : NAN, na);
        st.message = buf;
    } else {
        publish(job.candidate); // verified on the history up to the job's start
    }
    st.updated = true;
    return st;
}

IdentificationStatus PinchingUkfIdentifier::applyAnchor(const JobMeta& job, std::size_t startSize,
                                                        const PinchingAnchorJobResult& r) {
    IdentificationStatus st;
    m_lastSeconds = r.cpuSeconds;
    if (!r.ok) {
        st.ok = !job.diverged;
        st.message = "pinching UKF: no anchor: " + r.reason;
        return st;
    }
    // Catch up over the samples measured since the job started.
    BoucWenPinching law(r.best);
    law.setCommittedState(r.state, m_u[startSize - 1]);
    double sse = r.squaredErrors;
    for (std::size_t k = startSize; k < m_u.size(); ++k) {
        if (law.setTrialDeformation(m_u[k]) != LawStatus::Ok) {
            st.ok = !job.diverged;
            st.message = "pinching UKF: no anchor: its law fails on the samples since the "
                         "calibration";
            return st;
        }
        law.commit();
        const double e = law.committedForce() - m_f[k];
        sse += e * e;
    }
    PinchingUkfSettings us;
    m_anchorRms = r.nrmse * r.rmsForce / r.best.boucWen.fRef;
    us.forceNoise = std::max(m_anchorRms, 1e-3);
    us.zNoise = us.eNoise = 1e-2 * us.forceNoise;
    us.parameterNoise = m_settings.parameterNoise;
    try {
        m_ukf.emplace(r.best, r.box, us);
    } catch (const std::exception& e) {
        st.ok = false;
        st.message = std::string("pinching UKF: no anchor: ") + e.what();
        return st;
    }
    for (int j = 0; j < kPinchingUkfParameters; ++j)
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
                  "pinching UKF %s %d (%s) at a fit over %zu samples: NRMSE %.4f, zetaS %.3f",
                  job.diverged ? "restarted, anchor" : "anchor", m_anchors,
                  r.global ? "calibration" : "local refit", startSize, r.nrmse,
                  r.best.pinching.zetaS);
    st.message = buf;
    if (r.rescaled) {
        std::snprintf(buf, sizeof buf, " (scales moved: uRef %.6g, fRef %.6g)",
                      r.best.boucWen.uRef, r.best.boucWen.fRef);
        st.message += buf;
    }
    st.updated = true;
    st.refit = true;
    if (r.modelInadequate)
        st.modelInadequate = r.modelInadequate;
    return st;
}

IdentificationStatus PinchingUkfIdentifier::observe(double deformation, double force, bool) {
    IdentificationStatus st;
    if (!std::isfinite(deformation) || !std::isfinite(force)) {
        st.ok = false;
        st.message = "the measured deformation or force is not finite: step skipped";
        return st;
    }
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
                st = applyJob();
                st.reportable = m_ukf.has_value();
            }
            return st;
        }
        if (warmedUp())
            startAnchor(true, false);
        return st;
    }
    const PinchingUkfStep s = m_ukf->step(deformation, force);
    m_predicted = s.predictedForce;
    // divergence watch: the filter's a-priori error against the anchor model's own
    const double fRef = m_anchor.boucWen.fRef;
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
    const BoucWenPinchingParameters now = m_ukf->estimate();
    bool finite = std::isfinite(s.predictedForce);
    for (int j = 0; j < kPinchingUkfParameters; ++j)
        finite = finite && std::isfinite(PinchingUkf::field(now, j));
    const double rms = std::sqrt(std::max(m_windowSum, 0.0) / double(w));
    const double reference = std::max({std::sqrt(std::max(m_anchorWindowSum, 0.0) / double(w)),
                                       m_anchorRms, m_settings.divergenceFloor});
    const bool lawFailed = anchorFailed || m_rejectedInRow >= kRejectionsBeforeReanchor;
    if (!finite || lawFailed || (m_windowFill == w && rms > m_settings.divergenceRatio * reference)) {
        char buf[240];
        if (lawFailed) {
            // the law cannot integrate the anchor (or the filter's points) along the new path:
            // a refit (global if the law cannot replay the history from the anchor)
            std::snprintf(buf, sizeof buf, "%s: restarted from the anchor",
                          anchorFailed ? "the pinching UKF's anchor model failed on the new "
                                         "deformation"
                                       : "pinching UKF steps rejected in a row");
            m_rejectedInRow = 0;
        } else {
            ++m_divergences;
            std::snprintf(buf, sizeof buf,
                          "pinching UKF diverging (a-priori force error %.3g of fRef over the "
                          "last %zu steps, the anchor's %.3g): restarted from the anchor",
                          rms, w, reference);
        }
        st.ok = false;
        st.message = buf;
        restartAtAnchor();
        publish(m_anchor);
        clearWindows();
        m_recovering = int(w);
        if (m_job.running() && !m_job.meta().anchor)
            m_job.meta().discarded = true;
        if (!m_job.running()) {
            startAnchor(false, true);
            st.message += ", a refit started";
        }
        st.reportable = false;
        st.updated = true;
        return st;
    }
    if (!s.status.ok) {
        st.ok = false;
        st.message = "pinching UKF step rejected: " + s.status.reason;
    }
    if (m_recovering > 0)
        --m_recovering;
    const bool reportable = m_recovering == 0;
    if (m_job.due(n)) {
        IdentificationStatus j = applyJob();
        if (!j.message.empty() || !j.ok)
            st = j;
        st.updated = st.updated || j.updated;
        st.refit = j.refit;
    } else if (!m_job.running()) {
        if (double(n) >= m_settings.globalGrowth * double(m_globalSize)) {
            startAnchor(true, false); // the history grew a lot since the last global search
        } else if (double(n) >= m_settings.anchorGrowth * double(m_anchorSize)) {
            startAnchor(false, false); // the history doubled: a local refit
        } else if (n >= m_nextCheck) {
            // The guard: the whole history decides, not the one-step prediction.
            m_nextCheck = n + scheduledJobDelay(n);
            const bool stale = anchorHistoryNrmse() > m_settings.staleRatio * m_anchorNrmse &&
                               double(n) >= 1.25 * double(m_anchorSize);
            if (stale)
                startAnchor(false, false);
            else
                startVerify(now);
        }
    }
    st.reportable = reportable;
    return st;
}

} // namespace hsmu
