#pragma once
// PyRun: hsmu.run and hsmu.presets: a test run headless as `hsmu run` runs it (docs/python.md).
// The stepping loop is TestSession::runToEnd (core/session), the one loop of every front end;
// the columns are StepCsvWriter's (core/output), the summary RunSummary's.

#include <pybind11/pybind11.h>

namespace hsmu::python {

void bindRun(pybind11::module_& m);

} // namespace hsmu::python
