#include "python/PyInterrupt.h"

#include <pybind11/pybind11.h>

#include <chrono>
#include <exception>
#include <future>
#include <optional>
#include <thread>

namespace py = pybind11;

namespace hsmu::python {

bool runInterruptible(const std::function<void()>& work, const std::function<void()>& onInterrupt,
                      bool reraise) {
    std::promise<void> done;
    std::future<void> finished = done.get_future();
    std::thread worker([&] {
        try {
            work();
            done.set_value();
        } catch (...) {
            done.set_exception(std::current_exception());
        }
    });
    std::optional<py::error_already_set> interrupt;
    {
        py::gil_scoped_release release;
        while (finished.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
            py::gil_scoped_acquire acquire;
            if (PyErr_CheckSignals() == 0)
                continue;
            if (interrupt) {
                PyErr_Clear(); // a second Ctrl+C while the first is handled changes nothing
                continue;
            }
            interrupt.emplace(); // fetches the pending Python exception
            onInterrupt();
        }
        worker.join();
    }
    if (interrupt)
        while (PyErr_CheckSignals() != 0) // signals that arrived as the work ended
            PyErr_Clear();
    if (interrupt && reraise)
        throw std::move(*interrupt);
    finished.get(); // re-throws the work's exception
    return interrupt.has_value();
}

} // namespace hsmu::python
