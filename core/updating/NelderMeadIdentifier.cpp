#include "core/updating/NelderMeadIdentifier.h"

#include "core/hysteresis/HysteresisLaw.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace hsmu {

NelderMeadIdentifier::NelderMeadIdentifier(const HysteresisLaw& model,
                                           const NelderMeadIdentifierSettings& s)
    : m_law(model.lawName()), m_s(s), m_sinceTrigger(s.cooldownSteps)
{
    for (const auto& name : model.parameterNames())
        m_all[name] = *model.parameter(name);
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
    }
}

ParameterValues NelderMeadIdentifier::estimate() const
{
    ParameterValues out;
    for (const auto& name : m_s.parameters)
        out[name] = m_all.at(name);
    return out;
}

ParameterValues NelderMeadIdentifier::standardDeviation() const
{
    ParameterValues out;
    for (const auto& name : m_s.parameters)
        out[name] = 0.0;
    return out;
}

double NelderMeadIdentifier::predictedForce() const
{
    return std::numeric_limits<double>::quiet_NaN();
}

bool NelderMeadIdentifier::setBounds(const std::string& name, const ParameterBounds& b)
{
    auto it = m_s.bounds.find(name);
    if (it == m_s.bounds.end() || !(b.lower <= b.upper) || !std::isfinite(b.lower) ||
        !std::isfinite(b.upper))
        return false;
    it->second = b;
    m_all[name] = b.clamp(m_all[name]);
    return true;
}

IdentificationStatus NelderMeadIdentifier::observe(double deformation, double force,
                                                   bool updateRequested)
{
    m_u.push_back(deformation);
    m_f.push_back(force);
    ++m_sinceTrigger;
    IdentificationStatus st;
    if (!updateRequested || m_sinceTrigger < m_s.cooldownSteps)
        return st;
    m_sinceTrigger = 0;
    ++m_triggers;
    HistoryFitSpec spec;
    spec.law = m_law;
    spec.initial = m_all;
    for (const auto& name : m_s.parameters)
        spec.fitted.push_back({name, m_s.bounds.at(name).lower, m_s.bounds.at(name).upper});
    spec.window = static_cast<std::size_t>(std::max(0, m_s.windowSteps));
    spec.optimizer.maxEvaluations = m_s.maxEvaluations;
    const HistoryFitResult r = HistoryFit(spec).fit(m_u, m_f);
    m_lastSeconds = r.computeSeconds;
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

} // namespace hsmu
