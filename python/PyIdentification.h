#pragma once
// PyIdentification: hsmu.calibrate, hsmu.identify and hsmu.read_measured: the offline
// identification of `hsmu replay --import` on NumPy arrays (docs/python.md).

#include <pybind11/pybind11.h>

namespace hsmu::python {

void bindIdentification(pybind11::module_& m);

} // namespace hsmu::python
