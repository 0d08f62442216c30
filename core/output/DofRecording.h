#pragma once
// DofRecording: which numerical DOFs a run record keeps in /dofs/u, v, a and how often
// (issue 27; docs/recording.md "Chosen and decimated DOFs"; `hsmu run --record-dofs LIST
// --record-every N`, the configuration's "record" block, docs/configuration.md). Only the
// numerical DOF matrices are chosen or decimated: every element's, specimen's, actuator's,
// channel's, updating, alarm and note dataset is always recorded in full at every step.
// Thread rules: none (plain data and functions of it).

#include <cstddef>
#include <string>
#include <vector>

namespace hsmu {

struct DofRecording {
    /// The DOFs kept (indices into the structure's DOFs, 0-based, ascending, unique); empty:
    /// every DOF.
    std::vector<int> dofs;
    /// The rows kept: the steps whose index is a multiple of `every` (>= 1; 1: every step).
    int every = 1;

    /// Every DOF at every step: the default record, byte for byte.
    bool full() const { return dofs.empty() && every == 1; }
    /// The indices are ascending, unique and below `nDofs`, and `every` >= 1.
    bool validFor(std::size_t nDofs) const;
};

/// Parses a DOF list "0-9,100,Roof" (comma-separated items: a 0-based index, a range A-B of
/// indices, both included, or a DOF name as the configuration names it; blanks around items
/// ignored; an item of digits is an index even if a DOF has that name) against `dofNames`.
/// Returns the indices ascending and unique; empty when the list names every DOF. Throws
/// std::invalid_argument with the reason (no option prefix): an empty list or item, an index
/// or range out of 0..n-1, an unknown name, and a specimen's name (`specimenNames`: the
/// experimental elements), which is refused because its channels are always recorded.
std::vector<int> parseDofList(const std::string& text, const std::vector<std::string>& dofNames,
                              const std::vector<std::string>& specimenNames);

/// The indices as the shortest list parseDofList reads back ("0-99,200"); "all" when empty.
std::string describeDofList(const std::vector<int>& dofs);

} // namespace hsmu
