#include "core/updating/PinchingUkfIdentifier.h"

#include "core/identification/CalibrationDefaults.h"
#include "core/identification/HistoryScales.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace hsmu {

namespace {

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
    : AnchoredUkf(initial, settings), m_initial(initial), m_uRef(uRef), m_fRef(fRef),
      m_userBounds(bounds), m_layout(layoutNames()), m_settings(settings) {
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
    request.pinchingSearch = PinchingSearch::Anchor; // the anchors' box (PinchingUkfJobs.h)
    request.bounds = bounds;
    m_bounds.fill({NAN, NAN});
    for (const auto& b : defaultCalibrationSpec(request, HistoryScales{true, "", 1, 1, 1, 1}).fitted)
        if (const int j = pinchingUkfParameterIndex(b.name); j >= 0)
            m_bounds[std::size_t(j)] = {b.lower, b.upper};
    m_anchor = m_initial;
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

bool PinchingUkfIdentifier::finite(const BoucWenPinchingParameters& p) const {
    bool ok = true;
    for (int j = 0; j < kPinchingUkfParameters; ++j)
        ok = ok && std::isfinite(PinchingUkf::field(p, j));
    return ok;
}

PinchingUkfIdentifier::FilterStep PinchingUkfIdentifier::stepFilter(double u, double f) {
    const PinchingUkfStep s = m_ukf->step(u, f);
    return {s.status.ok, s.status.reason, s.predictedForce, m_ukf->estimate()};
}

void PinchingUkfIdentifier::restartFilter(const BoucWenState& state, double u) {
    m_ukf->restart(m_anchor, state, u, m_fit.sd);
}

std::string PinchingUkfIdentifier::startFilter(const PinchingAnchorJobResult& r,
                                               const BoucWenState& state, double u) {
    PinchingUkfSettings us;
    us.forceNoise = std::max(anchorRms(), 1e-3);
    us.zNoise = us.eNoise = 1e-2 * us.forceNoise;
    us.parameterNoise = m_settings.parameterNoise;
    try {
        m_ukf.emplace(r.best, r.box, us);
    } catch (const std::exception& e) {
        return e.what();
    }
    for (int j = 0; j < kPinchingUkfParameters; ++j)
        m_bounds[std::size_t(j)] = r.box[std::size_t(j)];
    m_ukf->restart(r.best, state, u, r.sd);
    return "";
}

BoucWenPinching PinchingUkfIdentifier::anchorLaw(const PinchingAnchorJobResult& r,
                                                 double uPrevious) const {
    BoucWenPinching law(r.best);
    law.setCommittedState(r.state, uPrevious);
    return law;
}

PinchingUkfIdentifier::AnchorWork PinchingUkfIdentifier::anchorWork(bool global, bool diverged) {
    PinchingAnchorJobInput in;
    in.u = m_u;
    in.f = m_f;
    in.uRef = m_uRef;
    in.fRef = m_fRef;
    if (m_anchors > 0) {
        in.anchor = m_anchor;
        in.anchorNrmse = anchorNrmse();
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
    return [in = std::move(in)](const std::atomic<bool>& cancel) {
        return pinchingAnchorJob(in, &cancel);
    };
}

PinchingUkfIdentifier::VerifyWork
PinchingUkfIdentifier::verifyWork(const BoucWenPinchingParameters& p) const {
    return [u = m_u, f = m_f, p] { return verifyJob(u, f, p); };
}

AnchorPlan PinchingUkfIdentifier::plan(std::size_t n) {
    if (double(n) >= m_settings.globalGrowth * double(m_globalSize))
        return AnchorPlan::GlobalAnchor; // the history grew a lot since the last global search
    if (double(n) >= m_settings.anchorGrowth * double(m_anchorSize))
        return AnchorPlan::LocalAnchor; // the history doubled: a local refit
    return AnchorPlan::Guard;
}

std::string PinchingUkfIdentifier::anchorNote(const PinchingAnchorJobResult& r) const {
    char buf[40];
    std::snprintf(buf, sizeof buf, ", zetaS %.3f", r.best.pinching.zetaS);
    return buf;
}

} // namespace hsmu
