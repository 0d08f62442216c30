#include "core/updating/RobustUkfIdentifier.h"

#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryScales.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hsmu {

namespace {

constexpr BoucWenUkfIndex kParams[] = {BoucWenUkfIndex::K0,    BoucWenUkfIndex::Alpha,
                                       BoucWenUkfIndex::Beta,  BoucWenUkfIndex::Gamma,
                                       BoucWenUkfIndex::N,     BoucWenUkfIndex::DeltaNu,
                                       BoucWenUkfIndex::DeltaEta};

double& field(BoucWenParameters& p, BoucWenUkfIndex i) {
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

/// The values of p for the spec's fitted parameters, in its order (a calibration start).
std::vector<double> startOf(const CalibrationSpec& spec, BoucWenParameters p) {
    std::vector<double> s;
    for (const auto& q : spec.fitted)
        for (BoucWenUkfIndex i : kParams)
            if (q.name == boucWenUkfIndexName(i))
                s.push_back(field(p, i));
    return s;
}

bool isUkfParameter(const std::string& name) {
    for (BoucWenUkfIndex i : kParams)
        if (name == boucWenUkfIndexName(i))
            return true;
    return false;
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
    : m_initial(initial), m_uRef(uRef), m_fRef(fRef), m_userBounds(bounds), m_settings(settings) {
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
    m_bounds = bounds;
    m_window.assign(std::size_t(std::max(settings.divergenceWindow, 1)), 0.0);
    m_anchorWindow = m_window;
    publish();
}

std::vector<std::string> RobustUkfIdentifier::parameterNames() const {
    std::vector<std::string> names;
    for (BoucWenUkfIndex i : kParams)
        names.emplace_back(boucWenUkfIndexName(i));
    names.emplace_back("uRef");
    names.emplace_back("fRef");
    return names;
}

void RobustUkfIdentifier::publish() {
    BoucWenParameters p = m_published;
    p.uRef = m_anchor.uRef;
    p.fRef = m_anchor.fRef;
    Eigen::VectorXd sd = Eigen::VectorXd::Zero(kBoucWenUkfSize);
    if (m_ukf && m_ukf->filter().initialized())
        sd = m_ukf->filter().standardDeviations();
    for (BoucWenUkfIndex i : kParams) {
        m_estimate[boucWenUkfIndexName(i)] = field(p, i);
        m_stddev[boucWenUkfIndexName(i)] = sd[static_cast<int>(i)];
    }
    m_estimate["uRef"] = p.uRef;
    m_estimate["fRef"] = p.fRef;
    m_stddev["uRef"] = m_stddev["fRef"] = 0.0;
}

ParameterValues RobustUkfIdentifier::estimate() const { return m_estimate; }
ParameterValues RobustUkfIdentifier::standardDeviation() const { return m_stddev; }

bool RobustUkfIdentifier::setBounds(const std::string& name, const ParameterBounds& b) {
    if (!isUkfParameter(name) || !(b.lower <= b.upper))
        return false;
    if (m_ukf) {
        for (BoucWenUkfIndex i : kParams)
            if (name == boucWenUkfIndexName(i) && !m_ukf->setBounds(i, b.lower, b.upper))
                return false;
    }
    m_userBounds[name] = b;
    m_bounds[name] = b;
    return true;
}

bool RobustUkfIdentifier::replayState(const BoucWenParameters& p, BoucWenState& state,
                                      double& nrmse) const {
    if (!BoucWen::admissible(p))
        return false;
    BoucWen law(p);
    double sum = 0.0, sumF = 0.0;
    for (std::size_t k = 0; k < m_u.size(); ++k) {
        if (law.setTrialDeformation(m_u[k]) != LawStatus::Ok)
            return false;
        law.commit();
        const double e = law.committedForce() - m_f[k];
        sum += e * e;
        sumF += m_f[k] * m_f[k];
    }
    state = law.committedState();
    nrmse = sumF > 0 ? std::sqrt(sum / sumF) : 0.0;
    return std::isfinite(nrmse);
}

BoucWenParameters RobustUkfIdentifier::fromCalibration(const CalibrationResult& r) const {
    BoucWenParameters p = m_initial;
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

IdentificationStatus RobustUkfIdentifier::anchor(bool diverged, bool global) {
    IdentificationStatus st;
    const HistoryScales scales = deriveHistoryScales(m_u, m_f);
    CalibrationRequest request;
    request.bounds = m_userBounds;
    request.uRef = m_uRef ? m_uRef : (m_anchors > 0 ? std::optional(m_anchor.uRef) : std::nullopt);
    request.fRef = m_fRef ? m_fRef : (m_anchors > 0 ? std::optional(m_anchor.fRef) : std::nullopt);
    if (!scales.ok && !(request.uRef && request.fRef)) {
        st.message = "no anchor yet: " + scales.reason;
        return st;
    }
    CalibrationSpec spec = defaultCalibrationSpec(request, scales);
    if (m_ukf && !global) // a local refit: from the anchor (and the estimate below) only
        spec.starts.assign(1, startOf(spec, m_anchor));
    if (m_ukf) { // the current estimate is one more start
        std::vector<double> s = startOf(spec, m_ukf->estimate());
        if (s.size() == spec.fitted.size())
            spec.starts.push_back(std::move(s));
    }
    const CalibrationResult cal = calibrate(m_u, m_f, spec);
    BoucWenParameters best = m_anchor;
    BoucWenState state;
    double bestNrmse = std::numeric_limits<double>::infinity(), nrmse = 0.0;
    if (m_ukf && !diverged) {
        BoucWenParameters now = m_ukf->estimate();
        if (replayState(now, state, nrmse))
            best = now, bestNrmse = nrmse;
    }
    if (cal.ok) {
        const BoucWenParameters p = fromCalibration(cal);
        BoucWenState s;
        if (replayState(p, s, nrmse) && nrmse < bestNrmse)
            best = p, bestNrmse = nrmse;
    }
    if (!std::isfinite(bestNrmse) || !replayState(best, state, nrmse)) {
        st.ok = !diverged;
        st.message = "no anchor: the calibration failed (" + cal.reason + ")";
        return st;
    }
    // The UKF restarts at the anchor, in the anchor's box.
    BoucWenUkf::BoundsArray box = BoucWenUkf::tableIIIBounds();
    std::array<double, kBoucWenUkfSize> sd{};
    sd[0] = 1e-3;
    sd[1] = 1e-3;
    for (std::size_t q = 0; q < spec.fitted.size(); ++q)
        for (BoucWenUkfIndex i : kParams)
            if (spec.fitted[q].name == boucWenUkfIndexName(i)) {
                const auto at = std::size_t(i);
                box[at] = {spec.fitted[q].lower, spec.fitted[q].upper};
                const double fromFit = cal.ok && q < std::size_t(cal.standardDeviation.size())
                                           ? cal.standardDeviation[Eigen::Index(q)]
                                           : std::nan("");
                const double floor = 1e-2 * spec.fitted[q].typical;
                const double cap = 0.1 * spec.fitted[q].typical;
                sd[at] = std::clamp(std::isfinite(fromFit) ? fromFit : floor, floor, cap);
            }
    BoucWenUkfSettings us;
    us.ukf.a = 1.0;
    us.ukf.b = 2.0;
    us.ukf.kappa = 0.0;
    const double rmsF = [&] {
        double s = 0;
        for (double f : m_f)
            s += f * f;
        return std::sqrt(s / double(m_f.size()));
    }();
    m_anchorRms = bestNrmse * rmsF / best.fRef;
    us.forceNoise = std::max(m_anchorRms, 1e-3);
    us.zNoise = us.eNoise = 1e-2 * us.forceNoise;
    us.parameterNoise = m_settings.parameterNoise;
    if (!m_ukf)
        m_ukf.emplace(best, us, box);
    else
        m_ukf->setSettings(us);
    for (BoucWenUkfIndex i : kParams) // a user's bound edit stays in force
        m_ukf->setBounds(i, box[std::size_t(i)].lower, box[std::size_t(i)].upper);
    m_ukf->restart(best, state, m_u.back(), sd);
    for (BoucWenUkfIndex i : kParams)
        m_bounds[boucWenUkfIndexName(i)] = {box[std::size_t(i)].lower, box[std::size_t(i)].upper};
    m_anchorLaw.emplace(best);
    m_anchorLaw->setCommittedState(state, m_u.back());
    std::fill(m_anchorWindow.begin(), m_anchorWindow.end(), 0.0);
    m_anchorWindowSum = 0.0;
    m_anchor = best;
    m_published = best;
    m_anchorSd = sd;
    m_anchorNrmse = bestNrmse;
    m_anchorSize = m_u.size();
    m_anchorAmplitude = m_maxAmplitude;
    m_nextCheck = m_u.size() + std::max<std::size_t>(50, m_u.size() / 20);
    std::fill(m_window.begin(), m_window.end(), 0.0);
    m_windowSum = 0.0;
    m_windowNext = 0;
    ++m_anchors;
    st.updated = true;
    st.refit = true;
    st.message = std::string(diverged ? "UKF restarted" : "UKF anchored") + " at a fit over " +
                 std::to_string(m_u.size()) + " samples: NRMSE " + fixed(bestNrmse, 3);
    if (scales.reversals >= m_settings.verdictReversals && bestNrmse > m_settings.verdictNrmse) {
        st.modelInadequate = bestNrmse;
        st.message += "; the model family cannot represent this specimen (best NRMSE " +
                      fixed(bestNrmse, 2) + ")";
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
    m_u.push_back(deformation);
    m_f.push_back(force);
    m_maxAmplitude = std::max(m_maxAmplitude, std::abs(deformation));
    if (!m_ukf) {
        m_predicted = std::numeric_limits<double>::quiet_NaN();
        const auto [lo, hi] = std::minmax_element(m_u.begin(), m_u.end());
        if (int(turningPoints(m_u, 0.02 * (*hi - *lo)).size()) < m_settings.warmUpReversals)
            return st; // warm-up: nothing to identify yet
        st = anchor(false, true);
        publish();
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
        const double a = (m_anchorLaw->committedForce() - force) / m_anchor.fRef;
        a2 = a * a;
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
        IdentificationStatus again = anchor(true, false);
        m_recovering = m_settings.divergenceWindow;
        publish();
        again.ok = false;
        again.reportable = false;
        again.message = "UKF diverging (prediction error " + fixed(windowRms, 3) +
                        " of fRef over the last " + std::to_string(m_window.size()) +
                        " steps, the anchor's " + fixed(anchorRms, 3) + "): " + again.message;
        return again;
    }
    const bool doubled = double(m_u.size()) >= m_settings.anchorGrowth * double(m_anchorSize);
    bool grown = doubled || m_maxAmplitude >= m_settings.amplitudeGrowth * m_anchorAmplitude;
    std::string drift;
    bool verified = false;
    if (!grown && m_u.size() >= m_nextCheck) {
        // The guard: the whole history decides, not the one-step prediction (the filter can
        // follow the force through z with parameters that replay the history poorly).
        m_nextCheck = m_u.size() + std::max<std::size_t>(50, m_u.size() / 20);
        BoucWenState zs, za;
        double nu = 0.0, na = 0.0;
        const bool okU = replayState(s.estimate, zs, nu);
        const bool okA = replayState(m_anchor, za, na);
        if (okA && na > m_settings.staleRatio * m_anchorNrmse &&
            double(m_u.size()) >= 1.25 * double(m_anchorSize)) {
            grown = true; // the anchor no longer fits what was measured since: refit
        } else if (okA && (!okU || nu > m_settings.driftRatio * na)) {
            m_ukf->restart(m_anchor, za, m_u.back(), m_anchorSd);
            m_published = m_anchor;
            ++m_pullBacks;
            std::ostringstream m;
            m.precision(3);
            m << "UKF estimate replays the history with NRMSE " << nu << " against the anchor's "
              << na << ": back to the anchor";
            drift = m.str();
            verified = true;
        } else if (okU) {
            m_published = s.estimate; // verified on the whole history
            verified = true;
        }
    }
    if (grown) {
        st = anchor(false, doubled); // multi-start when the history doubled, else local
        publish();
        st.reportable = m_recovering == 0;
        return st;
    }
    publish();
    st.ok = s.status.ok;
    st.updated = verified; // only estimates checked against the whole history are published
    if (!s.status.ok)
        st.message = s.status.reason;
    else if (!drift.empty())
        st.message = drift;
    if (m_recovering > 0) {
        --m_recovering;
        st.reportable = false;
    }
    return st;
}

} // namespace hsmu
