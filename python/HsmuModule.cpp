// The Python module `hsmu` (docs/python.md): the engine from Python with NumPy arrays.
#include "core/Version.h"
#include "core/config/JsonCursor.h"
#include "core/groundmotion/GroundMotionError.h"
#include "core/offline/MeasuredDataCsv.h"
#include "core/record/RecordError.h"
#include "python/PyIdentification.h"
#include "python/PyLaw.h"
#include "python/PyRecord.h"
#include "python/PyRun.h"

#include <pybind11/pybind11.h>

PYBIND11_MODULE(hsmu, m) {
    m.doc() = "HSMU: hysteresis laws, calibration, identification, records and headless runs "
              "of the HSMU Console engine, with NumPy arrays (docs/python.md).";
    m.attr("__version__") = hsmu::versionString();
    // The engine's errors as Python's: bad input is a ValueError, an unreadable file an OSError.
    pybind11::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p)
                std::rethrow_exception(p);
        } catch (const hsmu::ConfigError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const hsmu::MeasuredDataError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const hsmu::GroundMotionError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const hsmu::RecordError& e) {
            PyErr_SetString(PyExc_OSError, e.what());
        }
    });
    hsmu::python::bindLaw(m);
    hsmu::python::bindIdentification(m);
    hsmu::python::bindRecord(m);
    hsmu::python::bindRun(m);
}
