#pragma once
// PrettyJson: JSON written exactly as nlohmann::json::dump(2) writes it (same bytes: keys in
// std::string order, 2-space indentation, numbers and strings through nlohmann's serializer),
// with some objects streamed from plain arrays instead of built as a DOM. A 10,000-DOF run's
// summary.json holds five {name: value} objects of 10,000 entries each; as a DOM they cost
// about 170,000 allocations to build, dump and free (issue 27, docs/benchmarks.md).
// Thread rules: none (no state).

#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace hsmu {

/// One streamed {name: value} object: names[i] -> values[i] (null when not finite), or, with
/// units, names[i] -> {"unit": units[i], "value": values[i]}. Names sort as std::string; of
/// equal names the last one wins (as assigning into a nlohmann object). values.size() and
/// units (when given) must equal names.size().
struct NamedValues {
    std::vector<std::string> names;
    std::vector<double> values;
    std::vector<std::string> units; ///< empty: bare values
};

/// Writes `j` as j.dump(2) but for the objects at the JSON pointers of `streamed` (e.g.
/// "/final/displacement_m"), which are written from their NamedValues whatever `j` holds there
/// (a pointer `j` lacks is inserted in key order; its parent object must exist).
void writePrettyJson(std::ostream& out, const nlohmann::json& j,
                     const std::map<std::string, NamedValues>& streamed);

} // namespace hsmu
