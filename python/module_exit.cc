#include <csignal>
#include <chrono>
#include <thread>

#include "harness/sweep_recorder.h"
#include "python/module_internal.h"

namespace icp::python {

namespace {
std::atomic<bool> exiting{false};
std::atomic<int> in_flight{0};
}  // namespace

WithoutGil::WithoutGil() {
  if (exiting) {
    PyErr_SetString(PyExc_RuntimeError, "icpbench: the interpreter is exiting; nothing more is started");
    throw py::error_already_set();
  }
  ++in_flight;
  release_.emplace();
}

// The count drops only once the GIL is back: until then the exit waits.
WithoutGil::~WithoutGil() {
  release_.reset();
  --in_flight;
}

const std::atomic<bool>& Exiting() { return exiting; }

bool IsMainThread() {
  // Never destroyed: a Python object must not outlive the interpreter's end.
  static const auto* main_thread = new py::object(py::module_::import("threading").attr("main_thread"));
  return PyThread_get_thread_ident() == (*main_thread)().attr("ident").cast<unsigned long>();
}

void BindExit(py::module_& m) {
  // atexit hooks run before CPython starts to finalize, with the threads
  // still able to take the GIL: this one gives it up while it waits.
  auto hook = [] {
    exiting = true;
    py::gil_scoped_release release;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (in_flight > 0 && std::chrono::steady_clock::now() < deadline) {
      StopSignals::Request(SIGTERM);  // again: a sweep that just began reset it
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  };
  py::module_::import("atexit").attr("register")(py::cpp_function(hook));
}

}  // namespace icp::python
