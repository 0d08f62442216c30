#pragma once
// PyInterrupt: run a long piece of the engine (a calibration, an identification, a test run)
// with the GIL released, while the calling thread keeps answering Ctrl+C.
//
// Python handles SIGINT only when its main thread runs Python code; a C++ call that holds it
// for minutes would make Ctrl+C wait. So the work runs on a worker thread and the calling
// thread, every 50 ms, takes the GIL and runs the signal handlers (PyErr_CheckSignals): on a
// KeyboardInterrupt (or any exception a handler raises) it calls onInterrupt() once (set a
// cancel flag, hold the test), waits for the work to end, then re-raises the exception unless
// reraise is false (a run that ends cleanly held returns its result instead). Further
// interrupts while the first is handled change nothing (as SignalHold's for `hsmu run`).
// Exceptions of the work are re-thrown on the calling thread.
// Thread rules: call with the GIL held.

#include <functional>

namespace hsmu::python {

/// Returns true if an interrupt arrived (and was swallowed: reraise false).
bool runInterruptible(const std::function<void()>& work, const std::function<void()>& onInterrupt,
                      bool reraise = true);

} // namespace hsmu::python
