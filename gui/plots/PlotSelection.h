#pragma once
// PlotSelection: which DOFs and elements the live plots and the exported PNGs draw when a
// model has many (issue 17: a 10,000-DOF numerical substructure). The record and steps.csv
// keep every column; the plots draw at most kMaxPlottedDofs displacement histories and
// kMaxPlottedElements loops / force histories, spread evenly over the model with the first
// and the last included (for a shear building: the first storey and the roof).
// Thread rules: pure functions.

#include <vector>

namespace hsmu::gui {

inline constexpr int kMaxPlottedDofs = 8;
inline constexpr int kMaxPlottedElements = 8;

/// At most `max` of the indices 0..count-1, ascending and evenly spread, with 0 and
/// count-1 included; all of them when count <= max.
inline std::vector<int> spreadIndices(int count, int max) {
    std::vector<int> out;
    if (count <= 0 || max < 1)
        return out;
    if (count <= max) {
        for (int i = 0; i < count; ++i)
            out.push_back(i);
        return out;
    }
    if (max == 1)
        return {0};
    for (int k = 0; k < max; ++k) {
        const int i = int((long(k) * (count - 1) + (max - 1) / 2) / (max - 1));
        if (out.empty() || i != out.back())
            out.push_back(i);
    }
    return out;
}

/// The entries of `items` at spreadIndices(items.size(), max).
inline std::vector<int> spreadSubset(const std::vector<int>& items, int max) {
    std::vector<int> out;
    for (int k : spreadIndices(int(items.size()), max))
        out.push_back(items[std::size_t(k)]);
    return out;
}

} // namespace hsmu::gui
