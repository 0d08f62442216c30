#pragma once
// Inspector (docs/method.md, The four modules): watches the specimen's health and the model's
// fit, and decides when updating is needed.
//
//   fit error   e = RMS(F_aux - F_meas) / RMS(F_meas) over a sliding window of W seconds
//               (normalized RMS error; RMS(F_meas) floored at 1e-6 x the peak |F_meas| so
//               far; 0, undefined, until a nonzero force has been measured);
//               e > threshold raises a Warning once per excursion and requests updating.
//   fracture    sudden strength loss: at one step the measured force magnitude falls short of
//               the auxiliary model's prediction by more than fractureDrop x the peak measured
//               |F| so far and by more than 5x the window's RMS residual, once the peak
//               force reached minimumForce and while the model fitted (error below the
//               threshold at the previous step) (Critical, latched).
//   estimator   the identifier rejected an update or diverged (Warning, reason passed on).
//   pinned      an identified parameter sat on a bound for pinnedTime seconds (Warning; the
//               parameters are checked in name order, the order of alarms raised together).
//   tracking    the RTHS benchmark's indices over a sliding window of measured vs commanded
//               deformation (in s and fractions here): J1 = delay [s] maximizing their
//               normalized cross-correlation, as the console's live RTHS window computes it
//               (core/rths/TrackingWindow.h, M1': every lag summed over the same steps and
//               divided by the shifted command's energy; lags up to a quarter of the window,
//               refined by a parabola), J2 = RMS(d_m - d_c) / RMS(d_c), J3 = max|d_m - d_c| /
//               max|d_c| (core/rths/TrackingMetrics.h, M2, M3; Warning when J2 > its limit).
// Thresholds can change between steps (effective next step).

#include "core/util/Alarm.h"
#include "core/identification/ParameterLayout.h"
#include "core/identification/ParameterSet.h"

#include <deque>
#include <span>
#include <string>
#include <vector>

namespace hsmu {

struct InspectorSettings {
    double window = 2.0;          ///< fit-error window [s]
    double threshold = 0.10;      ///< fit error that requests updating [-]
    double fractureDrop = 0.25;   ///< fraction of peak |F| lost at once that flags a fracture
    double minimumForce = 0.0;    ///< peak |F| below which no fracture is flagged [force units]
    double pinnedTime = 5.0;      ///< [s] on a bound before a warning
    double trackingWindow = 2.0;  ///< [s]
    double trackingJ2Limit = 0.05; ///< [-]
    double trackingInterval = 0.5; ///< how often J1-J3 are computed [s]
};

struct TrackingIndices {
    double j1 = 0.0; ///< delay [s]
    double j2 = 0.0; ///< normalized RMS error [-]
    double j3 = 0.0; ///< normalized peak error [-]
};

/// What the inspector needs each step (physical units of the specimen).
struct InspectorInput {
    int step = 0;
    double time = 0.0;
    double measuredForce = 0.0;
    double auxiliaryForce = 0.0;
    double measuredDeformation = 0.0;
    double commandedDeformation = 0.0;
    bool estimatorOk = true;
    std::string estimatorMessage;
    /// The identified values and their bounds in the identifier's layout (the same layout
    /// every step; none: no pinned check). NaN bounds: not bounded (skipped).
    const ParameterLayout* parameters = nullptr;
    std::span<const double> parameterValues;
    std::span<const ParameterBounds> parameterBounds;
};

class Inspector {
public:
    explicit Inspector(const InspectorSettings& s = {}, double dt = 0.01);
    void setSettings(const InspectorSettings& s) { m_s = s; }
    const InspectorSettings& settings() const { return m_s; }

    /// Evaluate one committed step; alarms raised now are appended to `alarms`.
    void observe(const InspectorInput& in, std::vector<Alarm>& alarms);

    double fitError() const { return m_fitError; }
    bool updateRequested() const { return m_updateRequested; }
    bool fractureDetected() const { return m_fracture; }
    double fractureTime() const { return m_fractureTime; }
    const TrackingIndices& tracking() const { return m_tracking; }

private:
    struct PinState {
        std::string name;
        bool pinned = false; ///< on a bound since `since`
        double since = 0.0;
        bool raised = false;
    };
    void trackingIndices();
    /// The pinned check of one parameter (the "pinned" alarm of the header).
    void checkPinned(PinState& pin, double v, const ParameterBounds& b, const InspectorInput& in,
                     std::vector<Alarm>& alarms);
    PinState& pinState(const std::string& name);
    /// Resolve m_pinIndex / m_pinOrder for `layout` (when it is not the one resolved).
    void resolvePins(const ParameterLayout& layout);
    InspectorSettings m_s;
    double m_dt;
    std::deque<double> m_residual, m_measured;    // fit window
    double m_sumR2 = 0.0, m_sumF2 = 0.0;
    std::deque<double> m_cmd, m_meas;             // tracking window
    std::vector<double> m_cmdBuf, m_measBuf;      // their contiguous copies (kept)
    double m_fitError = 0.0;
    bool m_updateRequested = false;
    bool m_aboveThreshold = false;
    double m_peakForce = 0.0;
    double m_lastDeformation = 0.0;
    bool m_fracture = false;
    double m_fractureTime = 0.0;
    std::vector<PinState> m_pins;
    const std::vector<std::string>* m_pinLayout = nullptr; // names m_pinIndex was resolved for
    std::vector<std::size_t> m_pinIndex; // m_pins position of each layout entry
    std::vector<std::size_t> m_pinOrder; // layout positions in name order (the check order)
    TrackingIndices m_tracking;
    double m_nextTracking = 0.0;
    bool m_trackingRaised = false;
};

} // namespace hsmu
