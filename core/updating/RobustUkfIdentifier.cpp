#include "core/updating/RobustUkfIdentifier.h"

#include "core/identification/HistoryScales.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace hsmu {

namespace {

bool isUkfParameter(const std::string& name) {
    for (BoucWenUkfIndex i : kRobustUkfParameters)
        if (name == boucWenUkfIndexName(i))
            return true;
    return false;
}

std::vector<std::string> layoutNames() {
    std::vector<std::string> names;
    for (BoucWenUkfIndex i : kRobustUkfParameters)
        names.emplace_back(boucWenUkfIndexName(i));
    names.emplace_back("uRef");
    names.emplace_back("fRef");
    return names;
}

std::string fixed(double v, int digits) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << v;
    return s.str();
}

} // namespace

RobustUkfIdentifier::RobustUkfIdentifier(const BoucWenParameters& initial,
                                         std::optional<double> uRef, std::optional<double> fRef,
                                         const ParameterBoundsMap& bounds,
                                         const RobustUkfSettings& settings)
    : m_initial(initial), m_uRef(uRef), m_fRef(fRef), m_userBounds(bounds), m_settings(settings),
      m_layout(layoutNames()) {
    for (const auto& [name, b] : bounds) {
        if (!isUkfParameter(name))
            throw std::invalid_argument("updating.bounds: '" + name +
                                        "' is not identified by the UKF (expected k0, alpha, "
                                        "beta, gamma, n, deltaNu, deltaEta)");
        if (!(b.lower <= b.upper) || !std::isfinite(b.lower) || !std::isfinite(b.upper))
            throw std::invalid_argument("updating.bounds: '" + name +
                                        "' needs finite lower <= upper");
    }
    if (uRef)
        m_initial.uRef = *uRef;
    if (fRef)
        m_initial.fRef = *fRef;
    m_anchor = m_initial;
    m_published = m_initial;
    m_bounds.fill({NAN, NAN});
    for (const auto& [name, b] : bounds)
        m_bounds[m_layout.indexOf(name, "updating.bounds")] = b;
    m_window.assign(std::size_t(std::max(settings.divergenceWindow, 1)), 0.0);
    m_anchorWindow = m_window;
    publish();
}

void RobustUkfIdentifier::publish() {
    BoucWenParameters p = m_published;
    const bool filtering = m_ukf && m_ukf->filter().initialized();
    for (std::size_t j = 0; j < std::size(kRobustUkfParameters); ++j) {
        m_estimate[j] = robustUkfField(p, kRobustUkfParameters[j]);
        const auto i = static_cast<Eigen::Index>(kRobustUkfParameters[j]);
        m_stddev[j] =
            filtering ? std::sqrt(std::max(m_ukf->filter().covariance()(i, i), 0.0)) : 0.0;
    }
    m_estimate[7] = m_anchor.uRef;
    m_estimate[8] = m_anchor.fRef;
}

bool RobustUkfIdentifier::setBounds(std::size_t index, const ParameterBounds& b) {
    if (index >= std::size(kRobustUkfParameters) || !(b.lower <= b.upper))
        return false;
    if (m_ukf && !m_ukf->setBounds(kRobustUkfParameters[index], b.lower, b.upper))
        return false;
    m_userBounds[m_layout.name(index)] = b;
    m_bounds[index] = b;
    return true;
}

double RobustUkfIdentifier::anchorHistoryNrmse() const {
    return m_sumF2 > 0 ? std::sqrt(m_anchorSse / m_sumF2) : 0.0;
}

void RobustUkfIdentifier::clearWindows() {
    std::fill(m_window.begin(), m_window.end(), 0.0);
    std::fill(m_anchorWindow.begin(), m_anchorWindow.end(), 0.0);
    m_windowSum = m_anchorWindowSum = 0.0;
    m_windowNext = 0;
}

void RobustUkfIdentifier::startAnchor(bool global, bool diverged,
                                      const std::optional<BoucWenParameters>& estimate) {
    AnchorJobInput in;
    in.u = m_u;
    in.f = m_f;
    in.uRef = m_uRef;
    in.fRef = m_fRef;
    if (m_anchors > 0)
        in.anchor = m_anchor;
    in.estimate = estimate;
    in.initial = m_initial;
    in.userBounds = m_userBounds;
    in.global = global;
    in.rescaleFactor = m_settings.rescaleFactor;
    in.verdictReversals = m_settings.verdictReversals;
    in.verdictNrmse = m_settings.verdictNrmse;
    JobMeta meta;
    meta.anchor = true;
    meta.diverged = diverged;
    meta.startAmplitude = m_maxAmplitude;
    m_job.start(m_u.size(), meta, [in = std::move(in)](const std::atomic<bool>& cancel) {
        return JobOutcome{anchorJob(in, &cancel), {}};
    });
}

void RobustUkfIdentifier::startVerify(const BoucWenParameters& candidate) {
    JobMeta meta;
    meta.anchorNrmseAtStart = anchorHistoryNrmse();
    meta.candidate = candidate;
    m_job.start(m_u.size(), meta, [u = m_u, f = m_f, candidate](const std::atomic<bool>&) {
        return JobOutcome{{}, verifyJob(u, f, candidate)};
    });
}

void RobustUkfIdentifier::restartAtAnchor() {
    m_ukf->restart(m_anchor, m_anchorLaw->committedState(), m_u.back(), m_anchorSd);
    m_published = m_anchor;
}

IdentificationStatus RobustUkfIdentifier::applyJob() {
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
        ++m_pullBacks;
        std::ostringstream m;
        m.precision(3);
        m << "UKF estimate replays the history with NRMSE " << (v.ok ? v.nrmse : NAN)
          << " against the anchor's " << na << ": back to the anchor";
        st.message = m.str();
    } else {
        m_published = job.candidate; // verified on the history up to the job's start
    }
    st.updated = true;
    return st;
}

void RobustUkfIdentifier::startFilter(const AnchorJobResult& r, const BoucWenState& state,
                                      double u) {
    BoucWenUkfSettings us;
    us.ukf.a = 1.0;
    us.ukf.b = 2.0;
    us.ukf.kappa = 0.0;
    m_anchorRms = r.nrmse * r.rmsForce / r.best.fRef;
    us.forceNoise = std::max(m_anchorRms, 1e-3);
    us.zNoise = us.eNoise = 1e-2 * us.forceNoise;
    us.parameterNoise = m_settings.parameterNoise;
    const BoucWenUkf::BoundsArray& box = r.box;
    if (!m_ukf)
        m_ukf.emplace(r.best, us, box);
    else
        m_ukf->setSettings(us);
    for (std::size_t j = 0; j < std::size(kRobustUkfParameters); ++j) {
        const auto i = std::size_t(kRobustUkfParameters[j]);
        m_ukf->setBounds(kRobustUkfParameters[j], box[i].lower, box[i].upper);
        m_bounds[j] = {box[i].lower, box[i].upper};
    }
    m_ukf->restart(r.best, state, u, r.sd);
}

bool RobustUkfIdentifier::seed(const std::vector<double>& deformation,
                               const std::vector<double>& force, std::string& message) {
    if (!m_u.empty() || m_job.running() || m_ukf) {
        message = "the robust UKF is seeded before the test's first step";
        return false;
    }
    if (deformation.size() != force.size() || deformation.size() < 3) {
        message = "the seed record needs at least three samples of deformation and force";
        return false;
    }
    AnchorJobInput in;
    in.u = deformation;
    in.f = force;
    in.uRef = m_uRef;
    in.fRef = m_fRef;
    in.initial = m_initial;
    in.userBounds = m_userBounds;
    in.global = true;
    in.verdictReversals = m_settings.verdictReversals;
    in.verdictNrmse = m_settings.verdictNrmse;
    const AnchorJobResult r = anchorJob(in);
    m_workerCpu += r.cpuSeconds;
    m_anchorCpu += r.cpuSeconds;
    if (!r.ok) {
        message = "the seed record cannot be calibrated: " + r.reason;
        return false;
    }
    startFilter(r, BoucWenState{}, 0.0); // a new specimen: virgin at zero deformation
    m_anchorLaw.emplace(r.best);
    m_anchorSse = 0.0;
    clearWindows();
    m_anchor = r.best;
    m_published = r.best;
    m_anchorSd = r.sd;
    m_anchorNrmse = r.nrmse;
    m_anchorSize = 0;
    double amplitude = 0.0;
    for (double v : deformation)
        amplitude = std::max(amplitude, std::abs(v));
    m_anchorAmplitude = amplitude;
    m_uRef = m_uRef.value_or(r.best.uRef);
    m_fRef = m_fRef.value_or(r.best.fRef);
    m_nextCheck = jobDelay(0);
    m_seeded = true;
    ++m_anchors;
    publish();
    message = "UKF seeded at a fit of a previous record over " +
              std::to_string(deformation.size()) + " samples: NRMSE " + fixed(r.nrmse, 3);
    if (r.modelInadequate)
        message += "; the model family cannot represent that specimen (best NRMSE " +
                   fixed(*r.modelInadequate, 2) + ")";
    return true;
}

IdentificationStatus RobustUkfIdentifier::applyAnchor(const JobMeta& job, std::size_t startSize,
                                                      const AnchorJobResult& r) {
    IdentificationStatus st;
    if (!r.ok) {
        st.ok = !job.diverged;
        st.message = "no anchor: " + r.reason;
        return st;
    }
    // Catch up over the samples measured since the job started.
    BoucWen law(r.best);
    law.setCommittedState(r.state, m_u[startSize - 1]);
    double sse = r.squaredErrors;
    for (std::size_t k = startSize; k < m_u.size(); ++k) {
        if (law.setTrialDeformation(m_u[k]) != LawStatus::Ok) {
            st.ok = !job.diverged;
            st.message = "no anchor: its law fails on the samples since the calibration";
            return st;
        }
        law.commit();
        const double e = law.committedForce() - m_f[k];
        sse += e * e;
    }
    startFilter(r, law.committedState(), m_u.back());
    m_anchorLaw.emplace(std::move(law));
    m_anchorSse = sse;
    m_ownAnchor = true;
    clearWindows();
    m_anchor = r.best;
    m_published = r.best;
    m_anchorSd = r.sd;
    m_anchorNrmse = r.nrmse;
    m_anchorSize = startSize;
    m_anchorAmplitude = job.startAmplitude;
    m_nextCheck = m_u.size() + jobDelay(m_u.size());
    ++m_anchors;
    st.updated = true;
    st.refit = true;
    st.message = std::string(job.diverged ? "UKF restarted" : "UKF anchored") + " at a fit over " +
                 std::to_string(startSize) + " samples: NRMSE " + fixed(r.nrmse, 3);
    if (r.rescaled)
        st.message += " (scales moved: uRef " + fixed(r.best.uRef, 6) + ", fRef " +
                      fixed(r.best.fRef, 6) + ")";
    if (r.modelInadequate) {
        st.modelInadequate = r.modelInadequate;
        st.message += "; the model family cannot represent this specimen (best NRMSE " +
                      fixed(*r.modelInadequate, 2) + ")";
    }
    return st;
}

IdentificationStatus RobustUkfIdentifier::observe(double deformation, double force, bool) {
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
    m_uMin = std::min(m_uMin, deformation);
    m_uMax = std::max(m_uMax, deformation);
    m_sumF2 += force * force;
    m_maxAmplitude = std::max(m_maxAmplitude, std::abs(deformation));
    const std::size_t n = m_u.size();
    if (!m_ukf) {
        m_predicted = std::numeric_limits<double>::quiet_NaN();
        if (m_job.running()) {
            if (!m_job.due(n))
                return st;
            st = applyJob();
            publish();
            st.reportable = m_ukf.has_value();
            return st;
        }
        if (n < m_nextWarmUpCheck)
            return st;
        m_nextWarmUpCheck = n + std::max<std::size_t>(1, n / 50);
        if (int(turningPoints(m_u, 0.02 * (m_uMax - m_uMin)).size()) < m_settings.warmUpReversals)
            return st; // warm-up: nothing to identify yet
        startAnchor(true, false, std::nullopt);
        return st;
    }
    const BoucWenUkfStep s = m_ukf->step(deformation, force);
    m_predicted = s.predictedForce;
    const double e = (s.predictedForce - force) / m_anchor.fRef;
    const double e2 = std::isfinite(e) ? e * e : 1e300;
    // The anchor's own prediction over the same steps: what the model family can do here.
    double a2 = 0.0;
    if (m_anchorLaw && m_anchorLaw->setTrialDeformation(deformation) == LawStatus::Ok) {
        m_anchorLaw->commit();
        const double a = m_anchorLaw->committedForce() - force;
        m_anchorSse += a * a;
        a2 = a * a / (m_anchor.fRef * m_anchor.fRef);
    }
    m_windowSum += e2 - m_window[m_windowNext];
    m_window[m_windowNext] = e2;
    m_anchorWindowSum += a2 - m_anchorWindow[m_windowNext];
    m_anchorWindow[m_windowNext] = a2;
    m_windowNext = (m_windowNext + 1) % m_window.size();
    const double windowRms = std::sqrt(std::max(m_windowSum, 0.0) / double(m_window.size()));
    const double anchorRms =
        std::sqrt(std::max(m_anchorWindowSum, 0.0) / double(m_window.size()));
    bool finite = true;
    for (double v : {s.estimate.k0, s.estimate.alpha, s.estimate.beta, s.estimate.gamma,
                     s.estimate.n, s.estimate.deltaNu, s.estimate.deltaEta})
        finite = finite && std::isfinite(v);
    const bool diverging =
        !finite || windowRms > m_settings.divergenceRatio *
                                   std::max({anchorRms, m_anchorRms, m_settings.divergenceFloor});
    if (diverging) {
        ++m_divergences;
        restartAtAnchor();
        clearWindows();
        m_recovering = m_settings.divergenceWindow;
        if (m_job.running() && !m_job.meta().anchor)
            m_job.meta().discarded = true;
        const bool refit = !m_job.running() && m_ownAnchor; // a seed's anchor is not refitted on a few samples
        if (refit)
            startAnchor(false, true, std::nullopt);
        publish();
        st.ok = false;
        st.reportable = false;
        st.updated = true;
        st.message = "UKF diverging (prediction error " + fixed(windowRms, 3) +
                     " of fRef over the last " + std::to_string(m_window.size()) +
                     " steps, the anchor's " + fixed(anchorRms, 3) +
                     "): UKF restarted at the anchor (NRMSE " + fixed(m_anchorNrmse, 3) + ")" +
                     (refit ? ", a refit started" : "");
        return st;
    }
    if (m_job.due(n)) {
        st = applyJob();
    } else if (!m_job.running()) {
        const bool doubled = double(n) >= m_settings.anchorGrowth * double(m_anchorSize);
        const bool wider = m_maxAmplitude >= m_settings.amplitudeGrowth * m_anchorAmplitude;
        if (!m_ownAnchor) {
            // Seeded: the first anchor on this history after the warm-up's reversals (the
            // seed's anchor is guarded meanwhile, but not refitted on a few samples).
            bool warm = false;
            if (n >= m_nextWarmUpCheck) {
                m_nextWarmUpCheck = n + std::max<std::size_t>(1, n / 50);
                warm = int(turningPoints(m_u, 0.02 * (m_uMax - m_uMin)).size()) >=
                       m_settings.warmUpReversals;
            }
            if (warm) {
                startAnchor(true, false, s.estimate);
            } else if (n >= m_nextCheck) {
                m_nextCheck = n + jobDelay(n);
                startVerify(s.estimate);
            }
        } else if (doubled || wider) {
            startAnchor(doubled, false, s.estimate); // multi-start when the history doubled
        } else if (n >= m_nextCheck) {
            // The guard: the whole history decides, not the one-step prediction (the filter
            // can follow the force through z with parameters that replay the history poorly).
            m_nextCheck = n + jobDelay(n);
            const bool stale = anchorHistoryNrmse() > m_settings.staleRatio * m_anchorNrmse &&
                               double(n) >= 1.25 * double(m_anchorSize);
            if (stale)
                startAnchor(false, false, s.estimate); // the anchor no longer fits: refit
            else
                startVerify(s.estimate);
        }
    }
    publish();
    if (st.message.empty() && !s.status.ok) {
        st.ok = false;
        st.message = s.status.reason;
    }
    if (m_recovering > 0) {
        --m_recovering;
        st.reportable = false;
    }
    return st;
}

} // namespace hsmu
