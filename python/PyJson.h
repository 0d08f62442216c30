#pragma once
// PyJson: JSON values to Python objects and back (configurations and summaries as dicts).
// Objects <-> dict, arrays <-> list, numbers <-> int / float, strings, bool, null <-> None.
// From Python, tuples and 1-D NumPy arrays are accepted as arrays; anything else raises
// TypeError naming where it was ("config['analysis']['dt']").

#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>

#include <string>

namespace hsmu::python {

pybind11::object toPython(const nlohmann::json& value);
nlohmann::json toJson(pybind11::handle value, const std::string& where);

} // namespace hsmu::python
