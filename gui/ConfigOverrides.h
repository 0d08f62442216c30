#pragma once
// ConfigOverrides: the command-line options that change a TestConfig before it is built
// (`hsmu run` and `hsmu --start`): --ground-motion FILE, --record-dt DT [s], --scale S,
// --dt DT [s], --duration T [s], --allow-unstable.
// Thread rules: plain data.

#include "core/config/TestConfig.h"

#include <QString>

#include <optional>

namespace hsmu::gui {

struct ConfigOverrides {
    QString groundMotionFile;       ///< empty: keep the configuration's record
    /// The record's own sample step [s] for a one-column file (values only); 0 = take it
    /// from the file (AT2 header, time column). Distinct from dt, the integration step.
    std::optional<double> recordDt;
    std::optional<double> scale;    ///< ground-motion scale factor [-]
    std::optional<double> dt;       ///< integration step [s]
    std::optional<double> duration; ///< test duration [s]
    bool allowUnstable = false;     ///< only ever switches the option on

    /// Apply to cfg. A ground-motion file is made absolute from the current directory and
    /// read with automatic format and unit detection; recordDt (when set) then replaces the
    /// configuration's groundMotion.dt.
    void applyTo(TestConfig& cfg) const;
};

} // namespace hsmu::gui
