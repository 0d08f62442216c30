#include "core/updating/NelderMeadIdentifier.h"

#include "core/hysteresis/HysteresisLaw.h"
#include "core/identification/CalibrationDefaults.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace hsmu {

namespace {

double range(const std::vector<double>& u) {
    const auto [lo, hi] = std::minmax_element(u.begin(), u.end());
    return *hi - *lo;
}

bool isBoucWenFamily(const std::string& law) {
    return law == "boucWen" || law == "boucWenPinching";
}

bool movedBy(double a, double b, double factor) {
    return a > factor * b || b > factor * a;
}

/// The same physical Bouc-Wen (or pinching) model in the scales (uRef, fRef), by name: the
/// transformation of RobustUkfJobs.h's rescaled() (s = uRef_old / uRef, c = fRef_old / fRef:
/// k0 c / s, beta and gamma s^-n, deltaA, deltaNu, deltaEta and p / (c s), psi s, deltaPsi / c).
void rescale(ParameterValues& v, double uRef, double fRef) {
    const double s = v.at("uRef") / uRef, c = v.at("fRef") / fRef;
    const auto scale = [&v](const char* name, double factor) {
        if (auto it = v.find(name); it != v.end())
            it->second *= factor;
    };
    scale("k0", c / s);
    const double sn = std::pow(s, -v.at("n"));
    scale("beta", sn);
    scale("gamma", sn);
    for (const char* rate : {"deltaA", "deltaNu", "deltaEta", "p"})
        scale(rate, 1.0 / (c * s));
    scale("psi", s);
    scale("deltaPsi", 1.0 / c);
    v["uRef"] = uRef;
    v["fRef"] = fRef;
}

double rmsOf(const std::vector<double>& f, std::size_t window) {
    const std::size_t first = window > 0 && window < f.size() ? f.size() - window : 0;
    double s = 0.0;
    for (std::size_t k = first; k < f.size(); ++k)
        s += f[k] * f[k];
    return f.size() > first ? std::sqrt(s / double(f.size() - first)) : 0.0;
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

} // namespace

NelderMeadIdentifier::NelderMeadIdentifier(const HysteresisLaw& model,
                                           const NelderMeadIdentifierSettings& s)
    : m_law(model.lawName()), m_s(s), m_sinceTrigger(s.cooldownSteps)
{
    if (model.isRateDependent()) {
        m_dt = model.timeIncrement();
        if (!(m_dt > 0.0) || !std::isfinite(m_dt))
            throw std::invalid_argument("nelderMead: the " + m_law + " model is rate-dependent "
                                        "and needs the time step of the samples");
    }
    const std::vector<std::string> lawNames = model.parameterNames();
    for (std::size_t i = 0; i < lawNames.size(); ++i)
        m_all[lawNames[i]] = model.parameterValue(static_cast<int>(i));
    m_deriveScales = isBoucWenFamily(m_law) && !(m_s.uRef && m_s.fRef);
    if (isBoucWenFamily(m_law)) {
        if (m_s.uRef)
            m_all["uRef"] = *m_s.uRef;
        if (m_s.fRef)
            m_all["fRef"] = *m_s.fRef;
    }
    std::vector<std::string> withoutBounds;
    for (const auto& name : m_s.parameters) {
        if (!m_all.count(name))
            throw std::invalid_argument("nelderMead: '" + name + "' is not a parameter of the " +
                                        m_law + " law");
        if (m_deriveScales && (name == "uRef" || name == "fRef"))
            throw std::invalid_argument("nelderMead: '" + name +
                                        "' is a scale, not fitted: give it in the model, or "
                                        "leave both scales to the data");
        auto b = m_s.bounds.find(name);
        if (b == m_s.bounds.end()) {
            withoutBounds.push_back(name);
            m_bounds.push_back({kNaN, kNaN}); // the default box, once the data give it
            continue;
        }
        if (!std::isfinite(b->second.lower) || !std::isfinite(b->second.upper) ||
            b->second.lower > b->second.upper)
            throw std::invalid_argument("nelderMead: parameter '" + name +
                                        "' needs finite bounds [lower, upper] in "
                                        "updating.bounds");
        m_all[name] = b->second.clamp(m_all[name]);
        m_bounds.push_back(b->second);
    }
    if (!withoutBounds.empty()) {
        // The calibration's default box must have them (the law's defaults, any scales).
        CalibrationRequest request;
        request.law = m_law;
        request.fitted = withoutBounds;
        try {
            (void)defaultCalibrationSpec(request, HistoryScales{true, "", 1, 1, 1, 1});
        } catch (const std::invalid_argument&) {
            std::string names;
            for (const auto& n : withoutBounds)
                names += (names.empty() ? "'" : ", '") + n + "'";
            throw std::invalid_argument("nelderMead: parameter " + names +
                                        " needs finite bounds [lower, upper] in updating.bounds "
                                        "(the " + m_law + " law has no default range for it)");
        }
    }
    std::vector<std::string> names = m_s.parameters;
    if (m_deriveScales) {
        names.emplace_back("uRef");
        names.emplace_back("fRef");
        m_bounds.push_back({kNaN, kNaN});
        m_bounds.push_back({kNaN, kNaN});
    }
    m_layout = ParameterLayout(std::move(names));
    m_stddev.assign(m_layout.size(), 0.0);
    publish();
}

void NelderMeadIdentifier::publish()
{
    m_estimate.resize(m_layout.size());
    for (std::size_t k = 0; k < m_layout.size(); ++k)
        m_estimate[k] = m_all.at(m_layout.name(k));
}

double NelderMeadIdentifier::predictedForce() const
{
    return std::numeric_limits<double>::quiet_NaN();
}

bool NelderMeadIdentifier::setBounds(std::size_t index, const ParameterBounds& b)
{
    if (index >= m_s.parameters.size() || !(b.lower <= b.upper) || !std::isfinite(b.lower) ||
        !std::isfinite(b.upper))
        return false;
    const std::string& name = m_layout.name(index);
    m_s.bounds[name] = b;
    m_bounds[index] = b;
    m_all[name] = b.clamp(m_all[name]);
    publish();
    return true;
}

IdentificationStatus NelderMeadIdentifier::observe(double deformation, double force,
                                                   bool updateRequested)
{
    if (m_dt > 0.0)
        m_t.push_back(double(m_u.size()) * m_dt);
    m_u.push_back(deformation);
    m_f.push_back(force);
    ++m_sinceTrigger;
    if (!updateRequested || m_sinceTrigger < m_s.cooldownSteps)
        return {};
    // The cost bound: refit only once the history has grown by refitGrowth since the last
    // refit (the calibrated refits always; the paper's simplex past kSimplexSpacedSamples).
    const bool spaced = m_s.calibrated || m_u.size() > kSimplexSpacedSamples;
    if (spaced && m_lastRefitSize > 0 &&
        double(m_u.size()) < (1.0 + m_s.refitGrowth) * double(m_lastRefitSize))
        return {};
    m_sinceTrigger = 0;
    m_lastRefitSize = m_u.size();
    ++m_triggers;
    const IdentificationStatus st = refit(false);
    publish();
    return st;
}

IdentificationStatus NelderMeadIdentifier::finalFit()
{
    if (m_u.size() < 3)
        return {};
    const IdentificationStatus st = refit(true);
    publish();
    return st;
}

IdentificationStatus NelderMeadIdentifier::refit(bool final)
{
    std::string note;
    const ParameterValues before = m_all;
    if (m_deriveScales && !updateScales(final, note)) {
        IdentificationStatus st;
        char buf[120];
        std::snprintf(buf, sizeof buf, "Nelder-Mead trigger %d: no fit yet, ", m_triggers);
        st.message = buf + note;
        return st;
    }
    IdentificationStatus st = m_s.calibrated ? calibratedRefit(final) : simplexRefit(final);
    if (!note.empty()) {
        st.message += note;
        if (m_all != before) { // re-expressed at least: the auxiliary model takes the scales
            st.updated = true;
            st.refit = true;
        }
    }
    return st;
}

bool NelderMeadIdentifier::updateScales(bool /*final*/, std::string& note)
{
    const HistoryScales sc = deriveHistoryScales(m_u, m_f);
    if (!sc.ok) {
        if (m_scaled)
            return true; // keep the scales already taken
        note = "the history has no scales yet (" + sc.reason + ")";
        return false;
    }
    const double uRef = m_s.uRef.value_or(sc.uRef), fRef = m_s.fRef.value_or(sc.fRef);
    if (m_scaled && !movedBy(uRef, m_scaleBasis[0], kRescaleFactor) &&
        !movedBy(fRef, m_scaleBasis[1], kRescaleFactor))
        return true;
    rescale(m_all, uRef, fRef);
    m_scaleBasis = {uRef, fRef};
    m_scaled = true;
    char buf[160];
    std::snprintf(buf, sizeof buf, " (scales from the data: uRef %.6g, fRef %.6g)", uRef, fRef);
    note = buf;
    return true;
}

bool NelderMeadIdentifier::budgeted(bool final) const
{
    return !final && m_s.windowSteps <= 0 && m_s.refitSamples > 0 &&
           m_u.size() > m_s.refitSamples;
}

bool NelderMeadIdentifier::fittedBox(const HistoryScales& scales,
                                     std::vector<ParameterBounds>& box) const
{
    CalibrationRequest request;
    request.law = m_law;
    request.pinchingSearch = PinchingSearch::Anchor; // the online box (PinchingSearch.h)
    for (const auto& name : m_s.parameters)
        if (!m_s.bounds.count(name))
            request.fitted.push_back(name);
    if (m_law == "mrDamper") { // the box in the model's own scales, velocities from the times
        request.uRef = m_all.at("uRef");
        request.fRef = m_all.at("fRef");
        request.time = m_t;
    }
    CalibrationSpec spec;
    if (!request.fitted.empty()) {
        try {
            spec = defaultCalibrationSpec(request, scales);
        } catch (const std::invalid_argument&) {
            return false;
        }
    }
    box.clear();
    for (const auto& name : m_s.parameters) {
        if (auto b = m_s.bounds.find(name); b != m_s.bounds.end()) {
            box.push_back(b->second);
            continue;
        }
        const auto it = std::find_if(spec.fitted.begin(), spec.fitted.end(),
                                     [&](const CalibrationSpec::Parameter& p) {
                                         return p.name == name;
                                     });
        if (it == spec.fitted.end())
            return false;
        box.push_back({it->lower, it->upper});
    }
    return true;
}

IdentificationStatus NelderMeadIdentifier::simplexRefit(bool final)
{
    IdentificationStatus st;
    const std::string label =
        final ? std::string("Nelder-Mead final fit") : "Nelder-Mead trigger " + std::to_string(m_triggers);
    std::vector<ParameterBounds> box;
    const HistoryScales scales = deriveHistoryScales(m_u, m_f);
    if (!fittedBox(scales, box) || (!scales.ok && box.size() != m_s.parameters.size())) {
        st.ok = false;
        st.message = label + " failed: no bounds for the fitted parameters";
        return st;
    }
    HistoryFitSpec spec;
    spec.law = m_law;
    spec.initial = m_all;
    bool clamped = false;
    for (std::size_t j = 0; j < m_s.parameters.size(); ++j) {
        const std::string& name = m_s.parameters[j];
        spec.fitted.push_back({name, box[j].lower, box[j].upper});
        const double v = box[j].clamp(m_all.at(name));
        clamped = clamped || v != m_all.at(name);
        spec.initial[name] = v;
        m_bounds[j] = box[j];
    }
    const std::size_t window = final ? 0 : static_cast<std::size_t>(std::max(0, m_s.windowSteps));
    spec.window = window;
    spec.optimizer.maxEvaluations = m_s.maxEvaluations;
    spec.time = m_t;
    const HistoryFitResult r = HistoryFit(spec).fit(m_u, m_f);
    m_lastSeconds = r.computeSeconds;
    m_lastEvaluations = r.evaluations;
    char buf[240];
    if (!r.ok) {
        st.ok = false;
        st.message = label + " failed: " + r.reason;
        return st;
    }
    const double rmsBefore =
        clamped ? HistoryFit::rmsError(m_law, m_all, m_u, m_f, window, m_t) : r.rmsBefore;
    if (!(r.rmsAfter < rmsBefore)) {
        std::snprintf(buf, sizeof buf,
                      "%s kept the parameters (RMS %.4g not improved, %d evaluations, %.1f ms)",
                      label.c_str(), rmsBefore, r.evaluations, 1e3 * r.computeSeconds);
        st.message = buf;
        return st;
    }
    for (const auto& name : m_s.parameters)
        m_all[name] = r.parameters.at(name);
    std::snprintf(buf, sizeof buf, "%s: RMS force error %.4g -> %.4g (%d evaluations, %.1f ms)",
                  label.c_str(), rmsBefore, r.rmsAfter, r.evaluations, 1e3 * r.computeSeconds);
    st.updated = true;
    st.refit = true;
    st.message = buf;
    return st;
}

CalibrationRequest NelderMeadIdentifier::refitRequest(bool final) const
{
    CalibrationRequest request;
    request.law = m_law;
    request.bounds = m_s.bounds;
    request.fitted = m_s.parameters;
    request.window = final ? 0 : static_cast<std::size_t>(std::max(0, m_s.windowSteps));
    request.time = m_t;
    request.pinchingSearch = PinchingSearch::Anchor; // the online search (PinchingSearch.h)
    if (isBoucWenFamily(m_law) || m_law == "mrDamper") {
        // the estimate's normalization: the fit's values are in its units
        request.uRef = m_all.at("uRef");
        request.fRef = m_all.at("fRef");
    }
    if (budgeted(final))
        request.polishSamples = m_s.refitSamples;
    return request;
}

bool NelderMeadIdentifier::wholeDefaultSet() const
{
    if (!isBoucWenFamily(m_law))
        return false;
    for (const auto& [name, v] : m_all) {
        if (std::find(m_s.parameters.begin(), m_s.parameters.end(), name) !=
            m_s.parameters.end())
            continue;
        const bool fixedByDefault = name == "uRef" || name == "fRef" ||
                                    (name == "A0" && v == 1.0) || (name == "deltaA" && v == 0.0);
        if (!fixedByDefault)
            return false;
    }
    return true;
}

bool NelderMeadIdentifier::refitSpec(bool final, CalibrationSpec& spec,
                                     std::vector<std::vector<double>>& globalStarts) const
{
    const bool boucWenFamily = isBoucWenFamily(m_law);
    const CalibrationRequest request = refitRequest(final);
    HistoryScales scales = deriveHistoryScales(m_u, m_f);
    if (!scales.ok && !boucWenFamily)
        return false; // no stiffness or force scale yet for the default box and starts
    try {
        spec = defaultCalibrationSpec(request, scales);
    } catch (const std::invalid_argument&) {
        return false; // a law without defaults, or a fitted parameter without a default range
    }
    spec.fixed.clear();
    for (const auto& [name, v] : m_all)
        if (std::find(m_s.parameters.begin(), m_s.parameters.end(), name) ==
            m_s.parameters.end())
            spec.fixed[name] = v;
    globalStarts = std::move(spec.starts);
    spec.starts.clear();
    const int iterations = std::max(5, m_s.maxEvaluations / int(m_s.parameters.size() + 1));
    spec.global.maxIterations = iterations;
    spec.local.maxIterations = iterations;
    return true;
}

IdentificationStatus NelderMeadIdentifier::calibratedRefit(bool final)
{
    CalibrationSpec spec;
    std::vector<std::vector<double>> globalStarts;
    if (!refitSpec(final, spec, globalStarts))
        return simplexRefit(final);
    const std::string label =
        final ? std::string("Nelder-Mead final fit") : "Nelder-Mead trigger " + std::to_string(m_triggers);
    const auto t0 = std::chrono::steady_clock::now();
    const std::size_t window = spec.window;
    const double rmsF = rmsOf(m_f, window);
    // Every candidate is judged by a replay over the whole history (scored over the window),
    // whatever part of it the fit ran on.
    const auto rmsOfValues = [&](const ParameterValues& v) {
        return HistoryFit::rmsError(m_law, v, m_u, m_f, window, m_t);
    };
    IdentificationStatus st;
    const double rmsBefore = rmsOfValues(m_all);
    std::vector<double> current;
    for (const auto& name : m_s.parameters)
        current.push_back(m_all.at(name));

    // Local: warm start from the current estimate.
    spec.starts = {current};
    spec.polished = 1;
    const CalibrationResult local = calibrate(m_u, m_f, spec);
    int evaluations = local.residualEvaluations;
    ParameterValues best;
    double bestRms = std::numeric_limits<double>::infinity();
    std::string reason = local.reason;
    if (local.ok) {
        best = local.parameters;
        bestRms = rmsOfValues(best);
    }
    const double localNrmse = rmsF > 0 ? bestRms / rmsF : bestRms;
    // A poor local fit calls for the global search again only once the history has grown
    // by kPoorGrowth since the last one (a specimen the law follows poorly everywhere would
    // otherwise run it at every trigger); the final fit runs it only on growth.
    const bool poor = !(localNrmse <= std::max(kPoorNrmse, 1.25 * m_globalNrmse)) &&
                      !final && double(m_u.size()) >= kPoorGrowth * double(m_globalSize);
    const bool grown = double(m_u.size()) >= kGlobalGrowth * double(m_globalSize);
    const bool cycled = turningPoints(m_u, 0.02 * range(m_u)).size() >= 2;
    const bool global = cycled && (m_globalSize == 0 || grown || poor);
    std::string globalNote;
    if (!local.ok)
        globalNote = "; the warm start failed: " + local.reason;
    const auto takeGlobal = [&](const CalibrationResult& g) {
        evaluations += g.residualEvaluations;
        if (!g.ok) {
            reason = g.reason;
            globalNote = "; the global search failed: " + g.reason;
            return;
        }
        ++m_globalFits;
        m_globalSize = m_u.size();
        const double gRms = rmsOfValues(g.parameters);
        m_globalNrmse = rmsF > 0 ? gRms / rmsF : gRms;
        if (gRms < bestRms) {
            best = g.parameters;
            bestRms = gRms;
        }
    };
    if (global && wholeDefaultSet()) {
        // the default calibration as offline (for boucWenPinching: the plain law's optimum,
        // then starts scattered around it) in the user's box; in the estimate's scales, or
        // with derived scales the calibration's own (it may move uRef by the k0 it finds)
        CalibrationRequest request = refitRequest(final);
        if (m_deriveScales) {
            request.uRef = m_s.uRef;
            request.fRef = m_s.fRef;
        }
        takeGlobal(calibrateHistory(m_u, m_f, request));
    } else if (global) {
        spec.starts = std::move(globalStarts);
        spec.starts.push_back(current);
        if (local.ok)
            spec.starts.emplace_back(local.estimate.data(),
                                     local.estimate.data() + local.estimate.size());
        spec.polished = 2;
        takeGlobal(calibrate(m_u, m_f, spec));
    }
    for (std::size_t j = 0; j < m_s.parameters.size() && j < spec.fitted.size(); ++j)
        if (!m_s.bounds.count(m_s.parameters[j]))
            m_bounds[j] = {spec.fitted[j].lower, spec.fitted[j].upper};
    m_lastSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    m_lastEvaluations = evaluations;
    const char* kind = global ? "calibration, multi-start" : "calibration, warm start";
    char buf[320];
    if (!std::isfinite(bestRms)) {
        st.ok = false;
        st.message = label + " failed (" + kind + "): " + reason;
        return st;
    }
    if (!(bestRms < rmsBefore)) {
        std::snprintf(buf, sizeof buf,
                      "%s kept the parameters (%s: RMS %.4g not improved, %d evaluations, "
                      "%.1f ms)",
                      label.c_str(), kind, rmsBefore, evaluations, 1e3 * m_lastSeconds);
        st.message = buf + globalNote;
        return st;
    }
    for (const auto& name : m_s.parameters)
        m_all[name] = best.at(name);
    if (m_deriveScales) {
        m_all["uRef"] = best.at("uRef");
        m_all["fRef"] = best.at("fRef");
    }
    std::snprintf(buf, sizeof buf,
                  "%s (%s): RMS force error %.4g -> %.4g (%d evaluations, %.1f ms)",
                  label.c_str(), kind, rmsBefore, bestRms, evaluations, 1e3 * m_lastSeconds);
    st.updated = true;
    st.refit = true;
    st.message = buf + globalNote;
    return st;
}

} // namespace hsmu
