#pragma once
// AnchoredUkf's members (a template over the law: included by AnchoredUkf.h only).

#include "core/updating/AnchoredUkf.h"

namespace hsmu {

namespace anchored {
inline std::string format(const char* fmt, auto... args) {
    char buf[320];
    std::snprintf(buf, sizeof buf, fmt, args...);
    return buf;
}
} // namespace anchored

template <class P, class L, class A>
bool AnchoredUkf<P, L, A>::warmedUp() {
    const std::size_t n = m_u.size();
    if (n < m_nextWarmUpCheck)
        return false;
    m_nextWarmUpCheck = n + std::max<std::size_t>(1, n / 50);
    return int(turningPoints(m_u, 0.02 * (m_uMax - m_uMin)).size()) >= m_common.warmUpReversals;
}

template <class P, class L, class A>
void AnchoredUkf<P, L, A>::clearWindows() {
    std::fill(m_window.begin(), m_window.end(), 0.0);
    std::fill(m_anchorWindow.begin(), m_anchorWindow.end(), 0.0);
    m_windowSum = m_anchorWindowSum = 0.0;
    m_windowNext = m_windowFill = 0;
}

template <class P, class L, class A>
void AnchoredUkf<P, L, A>::startAnchor(bool global, bool diverged) {
    JobMeta meta;
    meta.anchor = true;
    meta.diverged = diverged;
    meta.startAmplitude = m_maxAmplitude;
    m_job.start(m_u.size(), meta,
                [work = anchorWork(global, diverged)](const std::atomic<bool>& cancel) {
                    return JobOutcome{work(cancel), {}};
                });
}

template <class P, class L, class A>
void AnchoredUkf<P, L, A>::startVerify(const P& candidate) {
    JobMeta meta;
    meta.anchorNrmseAtStart = anchorHistoryNrmse();
    meta.candidate = candidate;
    m_job.start(m_u.size(), meta, [work = verifyWork(candidate)](const std::atomic<bool>&) {
        return JobOutcome{{}, work()};
    });
}

template <class P, class L, class A>
IdentificationStatus AnchoredUkf<P, L, A>::applyJob() {
    typename Job::Taken taken = m_job.take();
    const JobMeta& job = taken.meta;
    const JobOutcome& out = taken.outcome;
    m_workerCpu += out.anchor.cpuSeconds + out.verify.cpuSeconds;
    m_anchorCpu += out.anchor.cpuSeconds;
    if (job.anchor)
        return applyAnchor(job, taken.startSize, out.anchor);
    if (job.discarded || !filtering())
        return {};
    return applyVerify(job.candidate, job.anchorNrmseAtStart, out.verify);
}

template <class P, class L, class A>
IdentificationStatus AnchoredUkf<P, L, A>::applyVerify(const P& candidate, double na,
                                                       const VerifyJobResult& v) {
    IdentificationStatus st;
    if (!v.ok || v.nrmse > m_common.driftRatio * na) {
        restartFilter(m_anchorLaw->committedState(), m_u.back());
        publish(m_anchor);
        ++m_pullBacks;
        st.message = anchored::format("%s estimate replays the history with NRMSE %.3g against "
                                      "the anchor's %.3g: back to the anchor",
                                      filterName(), v.ok ? v.nrmse : NAN, na);
    } else {
        publish(candidate); // verified on the history up to the job's start
    }
    st.updated = true;
    return st;
}

template <class P, class L, class A>
void AnchoredUkf<P, L, A>::setAnchor(const A& r, L law, double sse, std::size_t startSize) {
    m_anchorLaw.emplace(std::move(law));
    m_anchorSse = sse;
    clearWindows();
    m_anchor = r.best;
    m_fit = r;
    m_anchorNrmse = r.nrmse;
    m_anchorSize = startSize;
    m_rejectedInRow = 0;
    ++m_anchors;
    publish(r.best);
}

template <class P, class L, class A>
IdentificationStatus AnchoredUkf<P, L, A>::applyAnchor(const JobMeta& job, std::size_t startSize,
                                                       const A& r) {
    IdentificationStatus st;
    m_lastSeconds = r.cpuSeconds;
    const std::string noAnchor = std::string(filterName()) + ": no anchor: ";
    if (!r.ok) {
        st.ok = !job.diverged;
        st.message = noAnchor + r.reason;
        return st;
    }
    // Catch up over the samples measured since the job started.
    L law = anchorLaw(r, m_u[startSize - 1]);
    double sse = r.squaredErrors;
    for (std::size_t k = startSize; k < m_u.size(); ++k) {
        if (law.setTrialDeformation(m_u[k]) != LawStatus::Ok) {
            st.ok = !job.diverged;
            st.message = noAnchor + "its law fails on the samples since the calibration";
            return st;
        }
        law.commit();
        const double e = law.committedForce() - m_f[k];
        sse += e * e;
    }
    m_anchorRms = r.nrmse * r.rmsForce / fRef(r.best);
    if (const std::string error = startFilter(r, law.committedState(), m_u.back());
        !error.empty()) {
        st.ok = false;
        st.message = noAnchor + error;
        return st;
    }
    setAnchor(r, std::move(law), sse, startSize);
    m_ownAnchor = true;
    m_anchorAmplitude = job.startAmplitude;
    if (r.global) {
        m_globalSize = startSize;
        ++m_globalAnchors;
    }
    m_nextCheck = m_u.size() + jobDelay(m_u.size());
    st.message = anchored::format("%s %s %d (%s) at a fit over %zu samples: NRMSE %.4f",
                                  filterName(), job.diverged ? "restarted, anchor" : "anchor",
                                  m_anchors, r.global ? "calibration" : "local refit", startSize,
                                  r.nrmse) +
                 anchorNote(r);
    if (r.rescaled)
        st.message += anchored::format(" (scales moved: uRef %.6g, fRef %.6g)", uRef(r.best),
                                       fRef(r.best));
    if (r.modelInadequate) {
        st.modelInadequate = r.modelInadequate;
        st.message += anchored::format("; the model family cannot represent this specimen "
                                       "(best NRMSE %.2f)",
                                       *r.modelInadequate);
    }
    st.updated = true;
    st.refit = true;
    return st;
}

template <class P, class L, class A>
bool AnchoredUkf<P, L, A>::takeSeed(const A& r, const State& state, double u, std::string& error) {
    m_anchorRms = r.nrmse * r.rmsForce / fRef(r.best);
    error = startFilter(r, state, u);
    if (!error.empty())
        return false;
    setAnchor(r, L(r.best), 0.0, 0);
    m_nextCheck = jobDelay(0);
    return true;
}

template <class P, class L, class A>
IdentificationStatus AnchoredUkf<P, L, A>::recover(bool anchorFailed, bool lawFailed, double rms,
                                                   double reference) {
    IdentificationStatus st;
    const std::size_t w = m_window.size();
    if (anchorFailed) {
        // the anchor's model is behind (its state at the previous step): the filter keeps its
        // own, a global refit
        st.message = std::string("the ") + filterName() +
                     "'s anchor model failed on the new deformation";
    } else {
        restartFilter(m_anchorLaw->committedState(), m_u.back());
        if (lawFailed)
            st.message = std::string(filterName()) + " steps rejected in a row: restarted from "
                                                     "the anchor";
        else
            st.message = anchored::format(
                "%s diverging (a-priori force error %.3g of fRef over the last %zu steps, the "
                "anchor's %.3g): restarted from the anchor (NRMSE %.3f)",
                filterName(), rms, w, reference, m_anchorNrmse);
    }
    if (lawFailed)
        m_rejectedInRow = 0;
    else
        ++m_divergences;
    publish(m_anchor);
    clearWindows();
    m_recovering = int(w);
    if (m_job.running() && !m_job.meta().anchor)
        m_job.meta().discarded = true;
    // a seed's anchor is not refitted on a few samples
    if (!m_job.running() && m_ownAnchor) {
        startAnchor(anchorFailed, true);
        st.message += ", a refit started";
    }
    st.ok = false;
    st.reportable = false;
    st.updated = true;
    return st;
}

template <class P, class L, class A>
IdentificationStatus AnchoredUkf<P, L, A>::observe(double deformation, double force, bool) {
    IdentificationStatus st;
    if (!std::isfinite(deformation) || !std::isfinite(force)) {
        st.ok = false;
        st.message = "the measured deformation or force is not finite: step skipped";
        return st;
    }
    if (m_u.empty())
        m_uMin = m_uMax = deformation;
    m_u.push_back(deformation);
    m_f.push_back(force);
    appended();
    m_uMin = std::min(m_uMin, deformation);
    m_uMax = std::max(m_uMax, deformation);
    m_sumF2 += force * force;
    m_maxAmplitude = std::max(m_maxAmplitude, std::abs(deformation));
    const std::size_t n = m_u.size();
    if (!filtering()) {
        st.reportable = false;
        m_predicted = std::numeric_limits<double>::quiet_NaN();
        if (m_job.running()) {
            if (m_job.due(n)) {
                st = applyJob();
                st.reportable = filtering();
            }
            return st;
        }
        if (warmedUp()) // else the warm-up: nothing to identify yet
            startAnchor(true, false);
        return st;
    }
    const FilterStep s = stepFilter(deformation, force);
    m_predicted = s.predictedForce;
    m_rejectedInRow = s.ok ? 0 : m_rejectedInRow + 1;
    // The divergence watch: the filter's a-priori error against the anchor model's own over
    // the same steps (what the model family can do here).
    const double scale = fRef(m_anchor);
    const double e = (s.predictedForce - force) / scale;
    const double e2 = std::isfinite(e) ? e * e : 1e300;
    const bool anchorFailed = m_anchorLaw->setTrialDeformation(deformation) != LawStatus::Ok;
    double a2 = 0.0;
    if (!anchorFailed) {
        m_anchorLaw->commit();
        const double a = m_anchorLaw->committedForce() - force;
        m_anchorSse += a * a;
        a2 = a * a / (scale * scale);
    }
    const std::size_t w = m_window.size();
    m_windowSum += e2 - m_window[m_windowNext];
    m_window[m_windowNext] = e2;
    m_anchorWindowSum += a2 - m_anchorWindow[m_windowNext];
    m_anchorWindow[m_windowNext] = a2;
    m_windowNext = (m_windowNext + 1) % w;
    m_windowFill = std::min(m_windowFill + 1, w);
    const double rms = std::sqrt(std::max(m_windowSum, 0.0) / double(w));
    const double reference = std::max({std::sqrt(std::max(m_anchorWindowSum, 0.0) / double(w)),
                                       m_anchorRms, m_common.divergenceFloor});
    const bool lawFailed = anchorFailed || m_rejectedInRow >= 3;
    if (!finite(s.estimate) || !std::isfinite(s.predictedForce) || lawFailed ||
        ((m_windowFill == w || !m_common.fullWindowOnly) &&
         rms > m_common.divergenceRatio * reference))
        return recover(anchorFailed, lawFailed, rms, reference);
    if (m_job.due(n)) {
        st = applyJob();
    } else if (!m_job.running()) {
        const AnchorPlan next = plan(n);
        if (next == AnchorPlan::GlobalAnchor || next == AnchorPlan::LocalAnchor) {
            startAnchor(next == AnchorPlan::GlobalAnchor, false);
        } else if (next != AnchorPlan::Nothing && n >= m_nextCheck) {
            // The guard: the whole history decides, not the one-step prediction (the filter
            // can follow the force through z with parameters that replay the history poorly).
            m_nextCheck = n + jobDelay(n);
            const bool stale = next == AnchorPlan::Guard &&
                               anchorHistoryNrmse() > m_common.staleRatio * m_anchorNrmse &&
                               double(n) >= 1.25 * double(m_anchorSize);
            if (stale)
                startAnchor(false, false); // the anchor no longer fits: refit
            else if (m_common.verifyOnStep)
                st = applyVerify(s.estimate, anchorHistoryNrmse(), verifyWork(s.estimate)());
            else
                startVerify(s.estimate);
        }
    }
    publish(m_published); // the filter's standard deviations of this step
    if (st.message.empty() && !s.ok) {
        st.ok = false;
        st.message = std::string(filterName()) + " step rejected: " + s.reason;
    }
    if (m_recovering > 0) {
        --m_recovering;
        st.reportable = false;
    }
    return st;
}

} // namespace hsmu
