#pragma once
// PlotReferences: the reference lines the console's plots draw besides the data: the
// identification bounds of each parameter (the law's own units, normalized by uRef / fRef for
// Bouc-Wen: docs/method.md, Normalized units; the paper's bounds: docs/method.md, The paper's
// bounds (Table III)) and the inspector's fit-error threshold [-].
// Taken from a TestConfig (live) or from the configuration JSON stored in a record (replay).
// Thread rules: plain data, copy freely.

#include "core/config/TestConfig.h"
#include "core/identification/ParameterSet.h"

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace hsmu::gui {

struct PlotReferences {
    ParameterBoundsMap bounds; ///< per identified parameter name
    double fitThreshold = std::numeric_limits<double>::quiet_NaN(); ///< NaN: none
    /// Each experimental link2d element (name, its geometry and setup), configuration order.
    std::vector<std::pair<std::string, Link2dSpec>> link2dSpecimens;

    /// The configuration's updating bounds (a UKF: Table III for every parameter not listed)
    /// and inspector threshold (none without updating); the link2d specimens.
    static PlotReferences of(const TestConfig& cfg);
    /// The same from a record's stored configuration JSON; empty (no lines) if the text does
    /// not parse as a configuration.
    static PlotReferences ofConfigurationJson(const std::string& json);
};

} // namespace hsmu::gui
