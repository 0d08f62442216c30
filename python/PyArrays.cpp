#include "python/PyArrays.h"

#include <cmath>
#include <sstream>

namespace py = pybind11;

namespace hsmu::python {

namespace {

std::string shapeText(const py::array& a) {
    std::ostringstream s;
    s << '(';
    for (py::ssize_t i = 0; i < a.ndim(); ++i)
        s << (i ? ", " : "") << a.shape(i);
    s << (a.ndim() == 1 ? ",)" : ")");
    return s.str();
}

} // namespace

RealArray realVector(py::handle value, const std::string& what, bool requireFinite) {
    const py::array a = py::array::ensure(value);
    if (!a)
        throw py::type_error(what + ": expected a 1-D array of real numbers");
    const char kind = a.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u')
        throw py::type_error(what + ": expected real numbers (float64), got dtype " +
                             std::string(py::str(a.dtype())));
    if (a.ndim() != 1)
        throw py::value_error(what + ": expected a 1-D array, got shape " + shapeText(a));
    RealArray out = RealArray::ensure(a);
    if (!out)
        throw py::type_error(what + ": cannot be converted to float64");
    if (requireFinite) {
        const double* p = out.data();
        for (py::ssize_t i = 0; i < out.size(); ++i)
            if (!std::isfinite(p[i]))
                throw py::value_error(what + ": value " + std::to_string(i) + " is not finite (" +
                                      std::string(py::str(py::float_(p[i]))) + ")");
    }
    return out;
}

RealArray newVector(std::size_t n) {
    return RealArray(static_cast<py::ssize_t>(n));
}

} // namespace hsmu::python
