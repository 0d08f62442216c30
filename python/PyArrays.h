#pragma once
// PyArrays: the checks every NumPy input of the module goes through, so that a wrong dtype,
// a wrong shape or a non-finite value gets the same clear exception everywhere.
//   TypeError  : not an array of real numbers (complex, bool, object, strings, ...)
//   ValueError : not 1-D, empty where that is not allowed, or holding NaN / infinity
// Integer and float32 input is converted to float64; float64 C-contiguous input is not copied.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace hsmu::python {

using RealArray = pybind11::array_t<double, pybind11::array::c_style>;

/// `value` as a 1-D float64 array. `what` names the argument in messages ("deformation").
RealArray realVector(pybind11::handle value, const std::string& what, bool requireFinite = true);

/// A new 1-D float64 array of n elements (uninitialised).
RealArray newVector(std::size_t n);

} // namespace hsmu::python
