#pragma once
// PyRecord: hsmu.Record, a run record (HDF5, docs/recording.md) read through the project's own
// RecordReader (SWMR: a record still being written can be read and refreshed), its per-step
// data as NumPy arrays named and unitted as `hsmu export --csv` names its columns.

#include <pybind11/pybind11.h>

namespace hsmu::python {

void bindRecord(pybind11::module_& m);

} // namespace hsmu::python
