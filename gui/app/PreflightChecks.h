#pragma once
// PreflightChecks: what the pre-flight check flags for the operator's attention (shown in
// amber above the confirmation; they do not block the start):
//   - every setup value that differs from the last confirmed run of the same configuration
//     (dt [s], duration [s], ground motion and its scale [-], integrator, controller, steps,
//     PGA [m/s^2]), as "old -> new";
//   - a step count above kUnusualSteps, a PGA above kUnusualPga [m/s^2] (about 1.2 g, above
//     nearly every recorded ground motion), a zero PGA, a time step below kSmallDt [s].
// runSettingsOf() is what is compared, and what ConsoleSettings keeps per configuration name.
// Thread rules: GUI thread only.

#include "gui/app/PreflightReport.h"

#include <QCoreApplication>
#include <QStringList>
#include <QVariantMap>

namespace hsmu {
struct TestConfig;
}

namespace hsmu::gui {

class PreflightChecks {
    Q_DECLARE_TR_FUNCTIONS(PreflightChecks)

public:
    static constexpr int kUnusualSteps = 100000;
    static constexpr double kUnusualPga = 12.0;  ///< [m/s^2]
    static constexpr double kSmallDt = 1e-4;     ///< [s]

    /// The run's settings to compare with the last confirmed run (string values).
    static QVariantMap runSettingsOf(const TestConfig& cfg, const QString& controller,
                                     const PreflightReport& report);
    /// Translated warnings, one per flagged value (empty: nothing unusual).
    static QStringList warnings(const PreflightReport& report, const QVariantMap& current,
                                const QVariantMap& lastRun);
};

} // namespace hsmu::gui
