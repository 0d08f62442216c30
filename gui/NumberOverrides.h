#pragma once
// NumberOverrides: the numeric command-line options that change a TestConfig before it is
// built, without Qt (the Qt-free `hsmu run`, gui/cli/FastRun.h; ConfigOverrides adds the
// ground-motion file): --record-dt DT [s], --scale S [-], --dt DT [s], --duration T [s],
// --allow-unstable.
// Thread rules: plain data.

#include "core/config/TestConfig.h"

#include <optional>

namespace hsmu::gui {

struct NumberOverrides {
    /// The record's own sample step [s] for a one-column file (values only); 0 = take it
    /// from the file (AT2 header, time column). Distinct from dt, the integration step.
    std::optional<double> recordDt;
    std::optional<double> scale;    ///< ground-motion scale factor [-]
    std::optional<double> dt;       ///< integration step [s]
    std::optional<double> duration; ///< test duration [s]
    bool allowUnstable = false;     ///< only ever switches the option on

    /// Apply to cfg: recordDt (when set) replaces groundMotion.dt, and so on.
    void applyTo(TestConfig& cfg) const;
};

} // namespace hsmu::gui
