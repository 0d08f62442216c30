#include "core/updating/PinchingUkfIdentifier.h"

#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryScales.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace hsmu {

namespace {

/// The global phase of an anchor's calibration runs on this many samples (the offline
/// calibration: 800): an anchor's polish still sees the whole history.
constexpr std::size_t kAnchorReducedSamples = 300;
/// ... from this many scattered pinching starts (offline: 40) and the plain law's optimum;
/// the previous anchor and the UKF's estimate compete with its result.
constexpr int kAnchorPinchingStarts = 12;
/// UKF steps rejected in a row (a sigma point the law cannot integrate) before a new anchor.
constexpr int kRejectionsBeforeReanchor = 3;

int indexOf(const std::string& name) {
    const auto& names = pinchingUkfParameterNames();
    for (int j = 0; j < kPinchingUkfParameters; ++j)
        if (name == names[std::size_t(j)])
            return j;
    return -1;
}

std::vector<std::string> layoutNames() {
    std::vector<std::string> names(pinchingUkfParameterNames().begin(),
                                   pinchingUkfParameterNames().end());
    names.emplace_back("uRef");
    names.emplace_back("fRef");
    return names;
}

double rmsOf(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v)
        s += x * x;
    return v.empty() ? 0.0 : std::sqrt(s / double(v.size()));
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
        if (indexOf(name) < 0)
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
        if (const int j = indexOf(b.name); j >= 0)
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

int PinchingUkfIdentifier::reversals() const {
    return int(turningPoints(m_u, 0.02 * (m_uMax - m_uMin)).size());
}

bool PinchingUkfIdentifier::replay(const BoucWenPinchingParameters& p, BoucWenState& end,
                                   double& nrmse) const {
    if (!BoucWenPinching::admissible(p))
        return false;
    BoucWenPinching law(p);
    double s = 0.0;
    for (std::size_t k = 0; k < m_u.size(); ++k) {
        if (law.setTrialDeformation(m_u[k]) != LawStatus::Ok)
            return false;
        law.commit();
        const double e = law.committedForce() - m_f[k];
        s += e * e;
    }
    const double rmsF = rmsOf(m_f);
    nrmse = rmsF > 0 ? std::sqrt(s / double(m_u.size())) / rmsF : 0.0;
    end = law.committedState();
    return std::isfinite(nrmse);
}

BoucWenPinchingParameters PinchingUkfIdentifier::fromCalibration(const CalibrationResult& r) const {
    BoucWenPinchingParameters p = m_anchor;
    for (int j = 0; j < kPinchingUkfParameters; ++j) {
        const auto it = r.parameters.find(pinchingUkfParameterNames()[std::size_t(j)]);
        if (it != r.parameters.end())
            PinchingUkf::field(p, j) = it->second;
    }
    for (const char* name : {"A0", "deltaA", "uRef", "fRef"}) {
        const auto it = r.parameters.find(name);
        if (it == r.parameters.end())
            continue;
        double& v = std::string(name) == "A0"       ? p.boucWen.A0
                    : std::string(name) == "deltaA" ? p.boucWen.deltaA
                    : std::string(name) == "uRef"   ? p.boucWen.uRef
                                                    : p.boucWen.fRef;
        v = it->second;
    }
    return p;
}

void PinchingUkfIdentifier::restartAtAnchor() {
    BoucWenState state = m_anchorLaw->committedState();
    m_ukf->restart(m_anchor, state, m_u.back(), m_anchorSd);
}

IdentificationStatus PinchingUkfIdentifier::anchor(bool global, bool diverged) {
    const auto t0 = std::chrono::steady_clock::now();
    IdentificationStatus st;
    const HistoryScales scales = deriveHistoryScales(m_u, m_f);
    CalibrationRequest request;
    request.law = "boucWenPinching";
    request.bounds = m_userBounds;
    request.reducedSamples = kAnchorReducedSamples;
    request.pinchingStarts = kAnchorPinchingStarts;
    request.uRef = m_uRef ? m_uRef : (m_anchors > 0 ? std::optional(m_anchor.boucWen.uRef) : std::nullopt);
    request.fRef = m_fRef ? m_fRef : (m_anchors > 0 ? std::optional(m_anchor.boucWen.fRef) : std::nullopt);
    if (!scales.ok && !(request.uRef && request.fRef)) {
        st.message = "no anchor yet: " + scales.reason;
        return st;
    }
    if (!request.uRef) // the scales are fixed at the first anchor
        request.uRef = scales.uRef;
    if (!request.fRef)
        request.fRef = scales.fRef;
    CalibrationSpec spec = defaultCalibrationSpec(request, scales);
    CalibrationResult cal;
    if (global || !m_ukf) {
        cal = calibrateHistory(m_u, m_f, request);
    } else { // local: from the anchor and the current estimate
        spec.starts.clear();
        for (const BoucWenPinchingParameters& p : {m_anchor, m_ukf->estimate()}) {
            std::vector<double> s;
            for (const auto& b : spec.fitted)
                s.push_back(PinchingUkf::field(p, indexOf(b.name)));
            spec.starts.push_back(std::move(s));
        }
        spec.polished = 2;
        cal = calibrate(m_u, m_f, spec);
        if (!cal.ok) { // the law cannot replay the history from either: search globally
            global = true;
            cal = calibrateHistory(m_u, m_f, request);
        }
    }
    if (global)
        m_globalSize = m_u.size();
    BoucWenPinchingParameters best = m_anchor;
    best.boucWen.uRef = *request.uRef;
    best.boucWen.fRef = *request.fRef;
    BoucWenState state;
    double bestNrmse = std::numeric_limits<double>::infinity(), nrmse = 0.0;
    if (m_ukf) {
        if (replay(best, state, nrmse)) // the previous anchor (scales as now)
            bestNrmse = nrmse;
        const BoucWenPinchingParameters now = m_ukf->estimate();
        if (!diverged && replay(now, state, nrmse) && nrmse < bestNrmse)
            best = now, bestNrmse = nrmse;
    }
    if (cal.ok) {
        m_anchor.boucWen.uRef = *request.uRef; // fromCalibration starts from the anchor
        m_anchor.boucWen.fRef = *request.fRef;
        const BoucWenPinchingParameters p = fromCalibration(cal);
        if (replay(p, state, nrmse) && nrmse < bestNrmse)
            best = p, bestNrmse = nrmse;
    }
    if (!std::isfinite(bestNrmse) || !replay(best, state, nrmse)) {
        st.ok = !diverged;
        st.message = "pinching UKF: no anchor, the calibration failed (" + cal.reason + ")";
        return st;
    }
    PinchingUkf::Box box;
    for (const auto& b : spec.fitted) {
        const int j = indexOf(b.name);
        if (j < 0)
            continue;
        box[std::size_t(j)] = {b.lower, b.upper};
        const double fromFit = cal.ok ? [&] {
            for (std::size_t q = 0; q < cal.names.size(); ++q)
                if (cal.names[q] == b.name)
                    return cal.standardDeviation[Eigen::Index(q)];
            return std::nan("");
        }()
                                      : std::nan("");
        const double floor = 1e-2 * b.typical, cap = 0.1 * b.typical;
        m_anchorSd[std::size_t(j)] = std::clamp(std::isfinite(fromFit) ? fromFit : floor, floor, cap);
        m_bounds[std::size_t(j)] = {b.lower, b.upper};
    }
    const double rmsF = rmsOf(m_f);
    m_anchorRms = bestNrmse * rmsF / best.boucWen.fRef;
    PinchingUkfSettings us;
    us.forceNoise = std::max(m_anchorRms, 1e-3);
    us.zNoise = us.eNoise = 1e-2 * us.forceNoise;
    us.parameterNoise = m_settings.parameterNoise;
    m_anchor = best;
    m_anchorNrmse = bestNrmse;
    m_anchorSize = m_u.size();
    m_anchorLaw.emplace(best);
    for (double u : m_u) {
        m_anchorLaw->setTrialDeformation(u);
        m_anchorLaw->commit();
    }
    m_ukf.emplace(best, box, us);
    restartAtAnchor();
    std::fill(m_window.begin(), m_window.end(), 0.0);
    std::fill(m_anchorWindow.begin(), m_anchorWindow.end(), 0.0);
    m_windowSum = m_anchorWindowSum = 0.0;
    m_windowFill = 0;
    ++m_anchors;
    publish(best);
    m_nextCheck = m_u.size() + std::max<std::size_t>(50, m_u.size() / 20);
    m_lastSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "pinching UKF anchor %d (%s) over %zu samples: NRMSE %.4f, zetaS %.3f (%.0f ms)",
                  m_anchors, global ? "calibration" : "local refit", m_u.size(), bestNrmse,
                  best.pinching.zetaS, 1e3 * m_lastSeconds);
    st.message = buf;
    st.updated = true;
    st.refit = true;
    if (reversals() >= m_settings.verdictReversals && bestNrmse > m_settings.verdictNrmse)
        st.modelInadequate = bestNrmse;
    return st;
}

IdentificationStatus PinchingUkfIdentifier::observe(double deformation, double force, bool) {
    m_u.push_back(deformation);
    m_f.push_back(force);
    m_uMin = m_u.size() == 1 ? deformation : std::min(m_uMin, deformation);
    m_uMax = m_u.size() == 1 ? deformation : std::max(m_uMax, deformation);
    IdentificationStatus st;
    if (!m_ukf) {
        st.reportable = false;
        if (m_u.size() % 10 == 0 && reversals() >= m_settings.warmUpReversals)
            st = anchor(true, false);
        return st;
    }
    const PinchingUkfStep s = m_ukf->step(deformation, force);
    m_predicted = s.predictedForce;
    // divergence watch: the filter's a-priori error against the anchor model's own
    const double fRef = m_anchor.boucWen.fRef;
    const bool anchorFailed = m_anchorLaw->setTrialDeformation(deformation) != LawStatus::Ok;
    m_anchorLaw->commit();
    m_rejectedInRow = s.status.ok ? 0 : m_rejectedInRow + 1;
    if (anchorFailed || m_rejectedInRow >= kRejectionsBeforeReanchor) {
        // the law cannot integrate the anchor (or the filter's points) along the new path:
        // a new anchor from the whole history, which the law can replay
        m_rejectedInRow = 0;
        IdentificationStatus a2 = anchor(true, true);
        a2.ok = false;
        a2.message = std::string(anchorFailed ? "the anchor model failed on the new "
                                                "deformation"
                                              : "pinching UKF steps rejected in a row") +
                     "; " + a2.message;
        return a2;
    }
    const double e = (s.predictedForce - force) / fRef;
    const double a = (m_anchorLaw->committedForce() - force) / fRef;
    const std::size_t w = m_window.size();
    m_windowSum += e * e - m_window[m_windowNext];
    m_anchorWindowSum += a * a - m_anchorWindow[m_windowNext];
    m_window[m_windowNext] = e * e;
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
    if (!finite || (m_windowFill == w && rms > m_settings.divergenceRatio * reference)) {
        ++m_divergences;
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "pinching UKF diverging (a-priori force error %.3g of fRef over the last "
                      "%zu steps, the anchor's %.3g): restarted from the anchor",
                      rms, w, reference);
        st.ok = false;
        st.message = buf;
        restartAtAnchor();
        publish(m_anchor);
        std::fill(m_window.begin(), m_window.end(), 0.0);
        m_windowSum = 0.0;
        m_windowFill = 0;
        m_recovering = int(w);
        st.reportable = false;
        return st;
    }
    if (!s.status.ok) {
        st.ok = false;
        st.message = "pinching UKF step rejected: " + s.status.reason;
    }
    if (m_recovering > 0)
        --m_recovering;
    st.reportable = m_recovering == 0;
    if (double(m_u.size()) >= m_settings.anchorGrowth * double(m_globalSize)) {
        IdentificationStatus a2 = anchor(true, false);
        a2.reportable = st.reportable;
        return a2;
    }
    if (m_u.size() >= m_nextCheck) { // the guard
        m_nextCheck = m_u.size() + std::max<std::size_t>(50, m_u.size() / 20);
        BoucWenState endNow, endAnchor;
        double nrmseNow = 0.0, nrmseAnchor = 0.0;
        const bool nowOk = replay(now, endNow, nrmseNow);
        replay(m_anchor, endAnchor, nrmseAnchor);
        if (nowOk && nrmseNow <= m_settings.driftRatio * nrmseAnchor) {
            publish(now);
            st.updated = true;
        } else {
            restartAtAnchor();
            publish(m_anchor);
            st.updated = true;
        }
        if (nrmseAnchor > m_settings.staleRatio * m_anchorNrmse) {
            IdentificationStatus a2 = anchor(false, false);
            a2.reportable = st.reportable;
            return a2;
        }
    }
    return st;
}

} // namespace hsmu
