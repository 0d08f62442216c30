#include "python/PyJson.h"

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace hsmu::python {

py::object toPython(const nlohmann::json& v) {
    switch (v.type()) {
    case nlohmann::json::value_t::object: {
        py::dict d;
        for (const auto& [key, item] : v.items())
            d[py::str(key)] = toPython(item);
        return d;
    }
    case nlohmann::json::value_t::array: {
        py::list l;
        for (const auto& item : v)
            l.append(toPython(item));
        return l;
    }
    case nlohmann::json::value_t::string:
        return py::str(v.get<std::string>());
    case nlohmann::json::value_t::boolean:
        return py::bool_(v.get<bool>());
    case nlohmann::json::value_t::number_integer:
        return py::int_(v.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
        return py::int_(v.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
        return py::float_(v.get<double>());
    default:
        return py::none();
    }
}

nlohmann::json toJson(py::handle v, const std::string& where) {
    if (v.is_none())
        return nullptr;
    if (py::isinstance<py::bool_>(v))
        return v.cast<bool>();
    if (py::isinstance<py::int_>(v))
        return v.cast<std::int64_t>();
    if (py::isinstance<py::float_>(v))
        return v.cast<double>();
    if (py::isinstance<py::str>(v))
        return v.cast<std::string>();
    if (py::isinstance<py::dict>(v)) {
        nlohmann::json out = nlohmann::json::object();
        for (const auto& [key, item] : v.cast<py::dict>()) {
            if (!py::isinstance<py::str>(key))
                throw py::type_error(where + ": keys must be strings, got " +
                                     std::string(py::repr(key)));
            const std::string k = key.cast<std::string>();
            out[k] = toJson(item, where + "['" + k + "']");
        }
        return out;
    }
    if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v) ||
        py::isinstance<py::array>(v)) {
        nlohmann::json out = nlohmann::json::array();
        std::size_t i = 0;
        for (const auto& item : v)
            out.push_back(toJson(item, where + "[" + std::to_string(i++) + "]"));
        return out;
    }
    // NumPy scalars (numpy.float64 is a float; numpy.int64 is not an int)
    if (py::hasattr(v, "dtype") && py::hasattr(v, "item"))
        return toJson(v.attr("item")(), where);
    throw py::type_error(where + ": cannot be written as JSON (" +
                         std::string(py::str(py::type::of(v).attr("__name__"))) + ")");
}

} // namespace hsmu::python
