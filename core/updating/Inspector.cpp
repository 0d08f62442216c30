#include "core/updating/Inspector.h"

#include "core/rths/TrackingMetrics.h"
#include "core/rths/TrackingWindow.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hsmu {

namespace {
std::string format(const char* fmt, double a, double b = 0.0)
{
    char buf[200];
    std::snprintf(buf, sizeof buf, fmt, a, b);
    return buf;
}
} // namespace

Inspector::Inspector(const InspectorSettings& s, double dt) : m_s(s), m_dt(dt > 0 ? dt : 0.01) {}

void Inspector::observe(const InspectorInput& in, std::vector<Alarm>& alarms)
{
    auto raise = [&](AlarmSeverity sev, AlarmKind kind, std::string msg, const char* code,
                     std::vector<std::string> args) {
        alarms.push_back({in.time, in.step, sev, kind, std::move(msg), code, std::move(args)});
    };
    auto text = [](const char* fmt, double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, fmt, v);
        return std::string(buf);
    };

    // Sliding-window fit error, running sums with a periodic exact refresh against drift.
    const double r = in.auxiliaryForce - in.measuredForce;
    m_residual.push_back(r);
    m_measured.push_back(in.measuredForce);
    m_sumR2 += r * r;
    m_sumF2 += in.measuredForce * in.measuredForce;
    const auto windowSteps = static_cast<std::size_t>(std::max(1.0, std::round(m_s.window / m_dt)));
    while (m_residual.size() > windowSteps) {
        m_sumR2 -= m_residual.front() * m_residual.front();
        m_sumF2 -= m_measured.front() * m_measured.front();
        m_residual.pop_front();
        m_measured.pop_front();
    }
    if (in.step % 1000 == 0) {
        m_sumR2 = m_sumF2 = 0.0;
        for (std::size_t i = 0; i < m_residual.size(); ++i) {
            m_sumR2 += m_residual[i] * m_residual[i];
            m_sumF2 += m_measured[i] * m_measured[i];
        }
    }
    m_peakForce = std::max(m_peakForce, std::abs(in.measuredForce));
    // Undefined (0, no request) until a force has been measured: relative to a specimen that
    // has carried nothing yet, any model force was an error of 1e14 % (Gill's first sample).
    const double floor = 1e-6 * std::max(m_peakForce, 1e-12);
    m_fitError = m_peakForce > 0.0 ? std::sqrt(std::max(m_sumR2, 0.0) /
                                               std::max(m_sumF2, floor * floor * m_residual.size()))
                                   : 0.0;
    const bool above = m_residual.size() >= windowSteps / 2 && m_fitError > m_s.threshold;
    m_updateRequested = above;
    if (above && !m_aboveThreshold)
        raise(AlarmSeverity::Warning, AlarmKind::FitError,
              format("model error %.1f %% above the threshold %.1f %%", 100 * m_fitError,
                     100 * m_s.threshold),
              "fit-error", {text("%.1f", 100 * m_fitError), text("%.1f", 100 * m_s.threshold)});
    const bool fittedBefore = !m_aboveThreshold && m_residual.size() > 1;
    m_aboveThreshold = above;

    // Sudden strength loss: the measured force falls short of the model's by a large part of
    // the peak force at one step, and by far more than the recent residual (noise, misfit).
    const double shortfall = std::abs(in.auxiliaryForce) - std::abs(in.measuredForce);
    const bool sameSide = in.auxiliaryForce * in.measuredForce >= 0.0;
    const double recentRms = std::sqrt(std::max(m_sumR2 - r * r, 0.0) /
                                       std::max<std::size_t>(m_residual.size() - 1, 1));
    if (!m_fracture && fittedBefore && m_peakForce >= m_s.minimumForce && m_peakForce > 0.0 &&
        sameSide && shortfall > m_s.fractureDrop * m_peakForce && shortfall > 5.0 * recentRms) {
        m_fracture = true;
        m_fractureTime = in.time;
        raise(AlarmSeverity::Critical, AlarmKind::Fracture,
              format("sudden strength loss: measured force %.3g short of the model's by %.3g",
                     in.measuredForce, shortfall),
              "fracture", {text("%.3g", in.measuredForce), text("%.3g", shortfall)});
    }
    m_lastDeformation = in.measuredDeformation;

    if (!in.estimatorOk)
        raise(AlarmSeverity::Warning, AlarmKind::EstimatorRejected,
              "identification step rejected: " + in.estimatorMessage, "estimator-rejected",
              {in.estimatorMessage});

    if (in.parameters) {
        resolvePins(*in.parameters);
        const std::size_t n = std::min(
            {in.parameters->size(), in.parameterValues.size(), in.parameterBounds.size()});
        for (std::size_t k : m_pinOrder)
            if (k < n && !std::isnan(in.parameterBounds[k].lower))
                checkPinned(m_pins[m_pinIndex[k]], in.parameterValues[k], in.parameterBounds[k],
                            in, alarms);
    }

    m_cmd.push_back(in.commandedDeformation);
    m_meas.push_back(in.measuredDeformation);
    const auto trackSteps =
        static_cast<std::size_t>(std::max(2.0, std::round(m_s.trackingWindow / m_dt)));
    while (m_cmd.size() > trackSteps) {
        m_cmd.pop_front();
        m_meas.pop_front();
    }
    if (in.time + 1e-12 >= m_nextTracking) {
        m_nextTracking = in.time + m_s.trackingInterval;
        trackingIndices();
        const bool bad = m_tracking.j2 > m_s.trackingJ2Limit;
        if (bad && !m_trackingRaised)
            raise(AlarmSeverity::Warning, AlarmKind::TrackingError,
                  format("actuator tracking error J2 = %.1f %% (delay J1 = %.4f s)",
                         100 * m_tracking.j2, m_tracking.j1),
                  "tracking", {text("%.1f", 100 * m_tracking.j2), text("%.4f", m_tracking.j1)});
        m_trackingRaised = bad;
    }
}

void Inspector::resolvePins(const ParameterLayout& layout)
{
    const std::vector<std::string>& names = layout.names();
    if (m_pinLayout == &names && m_pinIndex.size() == names.size())
        return;
    m_pinIndex.clear();
    for (const auto& name : names)
        m_pinIndex.push_back(static_cast<std::size_t>(&pinState(name) - m_pins.data()));
    m_pinOrder.resize(names.size());
    for (std::size_t k = 0; k < names.size(); ++k)
        m_pinOrder[k] = k;
    std::stable_sort(m_pinOrder.begin(), m_pinOrder.end(),
                     [&](std::size_t a, std::size_t b) { return names[a] < names[b]; });
    m_pinLayout = &names;
}

Inspector::PinState& Inspector::pinState(const std::string& name)
{
    for (PinState& p : m_pins)
        if (p.name == name)
            return p;
    m_pinLayout = nullptr; // m_pins may move: resolve the positional layout again
    m_pins.push_back({name});
    return m_pins.back();
}

void Inspector::checkPinned(PinState& pin, double v, const ParameterBounds& b,
                            const InspectorInput& in, std::vector<Alarm>& alarms)
{
    const double tol = 1e-6 * std::max(1e-12, b.upper - b.lower);
    const bool pinned = std::abs(v - b.lower) <= tol || std::abs(v - b.upper) <= tol;
    if (!pinned) {
        pin.pinned = false;
        pin.raised = false;
        return;
    }
    if (!pin.pinned) {
        pin.pinned = true;
        pin.since = in.time;
    }
    if (!pin.raised && in.time - pin.since >= m_s.pinnedTime) {
        pin.raised = true;
        char value[32], since[32];
        std::snprintf(value, sizeof value, "%.4g", v);
        std::snprintf(since, sizeof since, "%.1f", in.time - pin.since);
        alarms.push_back({in.time, in.step, AlarmSeverity::Warning, AlarmKind::ParameterPinned,
                          pin.name + format(" has been at its bound %.4g for %.1f s", v,
                                            in.time - pin.since),
                          "parameter-pinned", {pin.name, value, since}});
    }
}

void Inspector::trackingIndices()
{
    const std::size_t n = m_cmd.size();
    if (n < 4)
        return;
    // The RTHS criteria over the window: J2, J3 as TrackingMetrics.h (M2, M3) for `hsmu run`'s
    // summary and `hsmu rths`; J1 as the console's live RTHS window (TrackingWindow.h, M1': one
    // live delay estimator; M1's plain sum leans towards the lags whose shifted command carries
    // more energy on a window of a few periods). J1 searches lags up to a quarter of the window.
    m_cmdBuf.assign(m_cmd.begin(), m_cmd.end());
    m_measBuf.assign(m_meas.begin(), m_meas.end());
    m_tracking.j1 = rths::windowDelay(m_cmdBuf, m_measBuf, m_dt, int(n / 4)) * 1e-3;
    m_tracking.j2 = rths::normalizedRmsError(m_cmdBuf, m_measBuf) * 1e-2;
    m_tracking.j3 = rths::peakError(m_cmdBuf, m_measBuf) * 1e-2;
}

} // namespace hsmu
