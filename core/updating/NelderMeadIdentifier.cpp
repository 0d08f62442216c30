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
} // namespace

NelderMeadIdentifier::NelderMeadIdentifier(const HysteresisLaw& model,
                                           const NelderMeadIdentifierSettings& s)
    : m_law(model.lawName()), m_s(s), m_layout(s.parameters),
      m_stddev(s.parameters.size(), 0.0), m_sinceTrigger(s.cooldownSteps)
{
    const std::vector<std::string> lawNames = model.parameterNames();
    for (std::size_t i = 0; i < lawNames.size(); ++i)
        m_all[lawNames[i]] = model.parameterValue(static_cast<int>(i));
    for (const auto& name : m_s.parameters) {
        if (!m_all.count(name))
            throw std::invalid_argument("nelderMead: '" + name + "' is not a parameter of the " +
                                        m_law + " law");
        auto b = m_s.bounds.find(name);
        if (b == m_s.bounds.end() || !std::isfinite(b->second.lower) ||
            !std::isfinite(b->second.upper) || b->second.lower > b->second.upper)
            throw std::invalid_argument("nelderMead: parameter '" + name +
                                        "' needs finite bounds [lower, upper] in "
                                        "updating.bounds");
        m_all[name] = b->second.clamp(m_all[name]);
        m_bounds.push_back(b->second);
    }
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
    if (index >= m_layout.size() || !(b.lower <= b.upper) || !std::isfinite(b.lower) ||
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
    m_u.push_back(deformation);
    m_f.push_back(force);
    ++m_sinceTrigger;
    if (!updateRequested || m_sinceTrigger < m_s.cooldownSteps)
        return {};
    m_sinceTrigger = 0;
    ++m_triggers;
    const IdentificationStatus st = m_s.calibrated ? calibratedRefit() : simplexRefit();
    publish();
    return st;
}

IdentificationStatus NelderMeadIdentifier::simplexRefit()
{
    IdentificationStatus st;
    HistoryFitSpec spec;
    spec.law = m_law;
    spec.initial = m_all;
    for (const auto& name : m_s.parameters)
        spec.fitted.push_back({name, m_s.bounds.at(name).lower, m_s.bounds.at(name).upper});
    spec.window = static_cast<std::size_t>(std::max(0, m_s.windowSteps));
    spec.optimizer.maxEvaluations = m_s.maxEvaluations;
    const HistoryFitResult r = HistoryFit(spec).fit(m_u, m_f);
    m_lastSeconds = r.computeSeconds;
    m_lastEvaluations = r.evaluations;
    char buf[240];
    if (!r.ok) {
        st.ok = false;
        st.message = "Nelder-Mead fit failed: " + r.reason;
        return st;
    }
    if (!(r.rmsAfter < r.rmsBefore)) {
        std::snprintf(buf, sizeof buf,
                      "Nelder-Mead trigger %d kept the parameters (RMS %.4g not improved, "
                      "%d evaluations, %.1f ms)",
                      m_triggers, r.rmsBefore, r.evaluations, 1e3 * r.computeSeconds);
        st.message = buf;
        return st;
    }
    for (const auto& name : m_s.parameters)
        m_all[name] = r.parameters.at(name);
    std::snprintf(buf, sizeof buf,
                  "Nelder-Mead trigger %d: RMS force error %.4g -> %.4g (%d evaluations, %.1f "
                  "ms)",
                  m_triggers, r.rmsBefore, r.rmsAfter, r.evaluations, 1e3 * r.computeSeconds);
    st.updated = true;
    st.refit = true;
    st.message = buf;
    return st;
}

CalibrationRequest NelderMeadIdentifier::refitRequest() const
{
    CalibrationRequest request;
    request.law = m_law;
    request.bounds = m_s.bounds;
    request.fitted = m_s.parameters;
    request.window = static_cast<std::size_t>(std::max(0, m_s.windowSteps));
    if (m_law == "boucWen" || m_law == "boucWenPinching") {
        // the model's normalization stays: the estimate is in its units
        request.uRef = m_all.at("uRef");
        request.fRef = m_all.at("fRef");
    }
    return request;
}

bool NelderMeadIdentifier::wholeDefaultSet() const
{
    if (m_law != "boucWen" && m_law != "boucWenPinching")
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

bool NelderMeadIdentifier::refitSpec(CalibrationSpec& spec,
                                     std::vector<std::vector<double>>& globalStarts) const
{
    const bool boucWenFamily = m_law == "boucWen" || m_law == "boucWenPinching";
    if (!boucWenFamily && m_law != "bilinear")
        return false;
    const CalibrationRequest request = refitRequest();
    HistoryScales scales = deriveHistoryScales(m_u, m_f);
    if (!scales.ok && !boucWenFamily)
        return false; // no stiffness or force scale yet for the bilinear starts
    try {
        spec = defaultCalibrationSpec(request, scales);
    } catch (const std::invalid_argument&) {
        return false; // a fitted parameter without a default range (e.g. A0)
    }
    spec.fixed.clear();
    for (const auto& [name, v] : m_all)
        if (std::find(m_s.parameters.begin(), m_s.parameters.end(), name) ==
            m_s.parameters.end())
            spec.fixed[name] = v;
    globalStarts = std::move(spec.starts);
    spec.starts.clear();
    spec.window = static_cast<std::size_t>(std::max(0, m_s.windowSteps));
    const int iterations = std::max(5, m_s.maxEvaluations / int(m_s.parameters.size() + 1));
    spec.global.maxIterations = iterations;
    spec.local.maxIterations = iterations;
    return true;
}

IdentificationStatus NelderMeadIdentifier::calibratedRefit()
{
    CalibrationSpec spec;
    std::vector<std::vector<double>> globalStarts;
    if (!refitSpec(spec, globalStarts))
        return simplexRefit();
    const auto t0 = std::chrono::steady_clock::now();
    const std::size_t window = spec.window;
    IdentificationStatus st;
    const double rmsBefore = HistoryFit::rmsError(m_law, m_all, m_u, m_f, window);
    std::vector<double> current;
    for (const auto& name : m_s.parameters)
        current.push_back(m_all.at(name));

    // Local: warm start from the current estimate.
    spec.starts = {current};
    spec.polished = 1;
    CalibrationResult best = calibrate(m_u, m_f, spec);
    int evaluations = best.residualEvaluations;
    const bool poor = !best.ok || best.nrmse > std::max(kPoorNrmse, 1.25 * m_globalNrmse);
    const bool grown = double(m_u.size()) >= kGlobalGrowth * double(m_globalSize);
    const bool cycled = turningPoints(m_u, 0.02 * range(m_u)).size() >= 2;
    const bool global = cycled && (m_globalSize == 0 || grown || poor);
    if (global && wholeDefaultSet()) {
        // the default calibration as offline (for boucWenPinching: the plain law's optimum,
        // then starts scattered around it), in the model's normalization and the user's box
        CalibrationResult g = calibrateHistory(m_u, m_f, refitRequest());
        evaluations += g.residualEvaluations;
        if (g.ok) {
            ++m_globalFits;
            m_globalSize = m_u.size();
            m_globalNrmse = g.nrmse;
            if (!best.ok || g.rmsError < best.rmsError)
                best = std::move(g);
        }
    } else if (global) {
        spec.starts = std::move(globalStarts);
        spec.starts.push_back(current);
        if (best.ok)
            spec.starts.emplace_back(best.estimate.data(),
                                     best.estimate.data() + best.estimate.size());
        spec.polished = 2;
        CalibrationResult g = calibrate(m_u, m_f, spec);
        evaluations += g.residualEvaluations;
        if (g.ok) {
            ++m_globalFits;
            m_globalSize = m_u.size();
            m_globalNrmse = g.nrmse;
            if (!best.ok || g.rmsError < best.rmsError)
                best = std::move(g);
        }
    }
    m_lastSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    m_lastEvaluations = evaluations;
    const char* kind = global ? "calibration, multi-start" : "calibration, warm start";
    char buf[280];
    if (!best.ok) {
        st.ok = false;
        st.message = "Nelder-Mead fit failed (" + std::string(kind) + "): " + best.reason;
        return st;
    }
    if (!(best.rmsError < rmsBefore)) {
        std::snprintf(buf, sizeof buf,
                      "Nelder-Mead trigger %d kept the parameters (%s: RMS %.4g not improved, "
                      "%d evaluations, %.1f ms)",
                      m_triggers, kind, rmsBefore, evaluations, 1e3 * m_lastSeconds);
        st.message = buf;
        return st;
    }
    for (std::size_t j = 0; j < m_s.parameters.size(); ++j)
        m_all[m_s.parameters[j]] = best.estimate[Eigen::Index(j)];
    std::snprintf(buf, sizeof buf,
                  "Nelder-Mead trigger %d (%s): RMS force error %.4g -> %.4g (%d evaluations, "
                  "%.1f ms)",
                  m_triggers, kind, rmsBefore, best.rmsError, evaluations, 1e3 * m_lastSeconds);
    st.updated = true;
    st.refit = true;
    st.message = buf;
    return st;
}

} // namespace hsmu
