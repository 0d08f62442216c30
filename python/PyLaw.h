#pragma once
// PyLaw: hsmu.Law, one hysteresis law of `hsmu material` driven from NumPy (docs/python.md).

#include <pybind11/pybind11.h>

namespace hsmu::python {

void bindLaw(pybind11::module_& m);

} // namespace hsmu::python
