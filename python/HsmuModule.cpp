// The Python module `hsmu` (docs/python.md): the engine from Python with NumPy arrays.
#include "core/Version.h"
#include "python/PyLaw.h"

#include <pybind11/pybind11.h>

PYBIND11_MODULE(hsmu, m) {
    m.doc() = "HSMU: hysteresis laws, calibration, identification, records and headless runs "
              "of the HSMU Console engine, with NumPy arrays (docs/python.md).";
    m.attr("__version__") = hsmu::versionString();
    hsmu::python::bindLaw(m);
}
