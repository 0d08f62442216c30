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
    : AnchoredUkf(initial, settings), m_initial(initial), m_uRef(uRef), m_fRef(fRef),
      m_userBounds(bounds), m_settings(settings), m_layout(layoutNames()) {
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
    m_bounds.fill({NAN, NAN});
    for (const auto& [name, b] : bounds)
        m_bounds[m_layout.indexOf(name, "updating.bounds")] = b;
    publish(m_initial);
}

void RobustUkfIdentifier::publish(const BoucWenParameters& p) {
    m_published = p;
    const bool filtering = m_ukf && m_ukf->filter().initialized();
    for (std::size_t j = 0; j < std::size(kRobustUkfParameters); ++j) {
        m_estimate[j] = robustUkfField(m_published, kRobustUkfParameters[j]);
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

bool RobustUkfIdentifier::finite(const BoucWenParameters& p) const {
    bool ok = true;
    for (double v : {p.k0, p.alpha, p.beta, p.gamma, p.n, p.deltaNu, p.deltaEta})
        ok = ok && std::isfinite(v);
    return ok;
}

RobustUkfIdentifier::FilterStep RobustUkfIdentifier::stepFilter(double u, double f) {
    const BoucWenUkfStep s = m_ukf->step(u, f);
    return {s.status.ok, s.status.reason, s.predictedForce, s.estimate};
}

void RobustUkfIdentifier::restartFilter(const BoucWenState& state, double u) {
    m_ukf->restart(m_anchor, state, u, m_fit.sd);
}

std::string RobustUkfIdentifier::startFilter(const AnchorJobResult& r, const BoucWenState& state,
                                             double u) {
    BoucWenUkfSettings us;
    us.ukf.a = 1.0;
    us.ukf.b = 2.0;
    us.ukf.kappa = 0.0;
    us.forceNoise = std::max(anchorRms(), 1e-3);
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
    return "";
}

BoucWen RobustUkfIdentifier::anchorLaw(const AnchorJobResult& r, double uPrevious) const {
    BoucWen law(r.best);
    law.setCommittedState(r.state, uPrevious);
    return law;
}

AnchorJobInput RobustUkfIdentifier::anchorInput(bool global) const {
    AnchorJobInput in;
    in.uRef = m_uRef;
    in.fRef = m_fRef;
    in.initial = m_initial;
    in.userBounds = m_userBounds;
    in.global = global;
    in.rescaleFactor = m_settings.rescaleFactor;
    in.verdictReversals = m_settings.verdictReversals;
    in.verdictNrmse = m_settings.verdictNrmse;
    return in;
}

RobustUkfIdentifier::AnchorWork RobustUkfIdentifier::anchorWork(bool global, bool diverged) {
    AnchorJobInput in = anchorInput(global);
    in.u = m_u;
    in.f = m_f;
    if (m_anchors > 0)
        in.anchor = m_anchor;
    if (m_ukf && !diverged)
        in.estimate = m_ukf->estimate();
    return [in = std::move(in)](const std::atomic<bool>& cancel) { return anchorJob(in, &cancel); };
}

RobustUkfIdentifier::VerifyWork RobustUkfIdentifier::verifyWork(const BoucWenParameters& p) const {
    return [u = m_u, f = m_f, p] { return verifyJob(u, f, p); };
}

AnchorPlan RobustUkfIdentifier::plan(std::size_t n) {
    if (!m_ownAnchor) // seeded: the first anchor on this history after the warm-up's reversals
        return warmedUp() ? AnchorPlan::GlobalAnchor : AnchorPlan::VerifyOnly;
    const bool doubled = double(n) >= m_settings.anchorGrowth * double(m_anchorSize);
    const bool wider = m_maxAmplitude >= m_settings.amplitudeGrowth * m_anchorAmplitude;
    if (doubled || wider) // multi-start when the history doubled
        return doubled ? AnchorPlan::GlobalAnchor : AnchorPlan::LocalAnchor;
    return AnchorPlan::Guard;
}

bool RobustUkfIdentifier::seed(const std::vector<double>& deformation,
                               const std::vector<double>& force, std::string& message) {
    if (!m_u.empty() || jobs() > 0 || m_ukf) {
        message = "the robust UKF is seeded before the test's first step";
        return false;
    }
    if (deformation.size() != force.size() || deformation.size() < 3) {
        message = "the seed record needs at least three samples of deformation and force";
        return false;
    }
    AnchorJobInput in = anchorInput(true);
    in.u = deformation;
    in.f = force;
    const AnchorJobResult r = anchorJob(in);
    m_workerCpu += r.cpuSeconds;
    m_anchorCpu += r.cpuSeconds;
    if (!r.ok) {
        message = "the seed record cannot be calibrated: " + r.reason;
        return false;
    }
    // a new specimen: virgin at zero deformation
    if (std::string error; !takeSeed(r, BoucWenState{}, 0.0, error)) {
        message = "the seed cannot start the UKF: " + error;
        return false;
    }
    double amplitude = 0.0;
    for (double v : deformation)
        amplitude = std::max(amplitude, std::abs(v));
    m_anchorAmplitude = amplitude;
    m_uRef = m_uRef.value_or(r.best.uRef);
    m_fRef = m_fRef.value_or(r.best.fRef);
    m_seeded = true;
    publish(r.best);
    message = "UKF seeded at a fit of a previous record over " +
              std::to_string(deformation.size()) + " samples: NRMSE " + fixed(r.nrmse, 3);
    if (r.modelInadequate)
        message += "; the model family cannot represent that specimen (best NRMSE " +
                   fixed(*r.modelInadequate, 2) + ")";
    return true;
}

} // namespace hsmu
