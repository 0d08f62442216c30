#pragma once
// RunLayout: what the outputs of a run need to know about its structure (names, types, units),
// copied out of the Structure so that writers, statistics and the GUI's plots can label
// StepRecords without touching the live Structure (which belongs to the test's thread).
// Index i of dofs / elements matches index i of StepRecord::u / StepRecord::elements.
// Thread rules: plain data, copy freely.

#include "core/output/ElementUnits.h"

#include <string>
#include <vector>

namespace hsmu {

class Structure;

struct ElementInfo {
    std::string name;
    std::string type;          ///< configuration type, e.g. "rotationalBaseSpring"
    bool experimental = false; ///< a specimen (commanded and measured deformation)
    /// Hysteretic: a specimen, or a numerical element whose law is not "elastic".
    bool nonlinear = false;
    ElementUnits units;
};

struct RunLayout {
    std::vector<std::string> dofNames; ///< full DOFs, displacement in m
    std::vector<ElementInfo> elements;

    /// Valid before or after Structure::finalize().
    static RunLayout of(const Structure& structure);
};

} // namespace hsmu
