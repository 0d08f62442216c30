#pragma once
// ConfigOverrides: the command-line options that change a TestConfig before it is built
// (`hsmu run` and `hsmu --start`): --ground-motion FILE, --record-dt DT [s], --scale S,
// --dt DT [s], --duration T [s], --allow-unstable.
// The numbers are NumberOverrides' (Qt-free, also the Qt-free `hsmu run`'s).
// Thread rules: plain data.

#include "gui/NumberOverrides.h"

#include <QString>

namespace hsmu::gui {

struct ConfigOverrides : NumberOverrides {
    QString groundMotionFile; ///< empty: keep the configuration's record

    /// Apply to cfg. A ground-motion file is made absolute from the current directory and
    /// read with automatic format and unit detection; then the numbers (NumberOverrides).
    void applyTo(TestConfig& cfg) const;
};

} // namespace hsmu::gui
