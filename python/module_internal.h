// What the three parts of the _icpbench extension share.
#ifndef ICPBENCH_PYTHON_MODULE_INTERNAL_H_
#define ICPBENCH_PYTHON_MODULE_INTERNAL_H_

#include <pybind11/pybind11.h>

#include <atomic>
#include <optional>
#include <string>

#include "core/params.h"

namespace icp::python {

namespace py = pybind11;

// A Python dict of parameters as the command line's key=value strings:
// True/False become true/false, numbers and strings their str().
ParamMap ToParamMap(const py::dict& params);

// C++ work done with the GIL released, counted so that the interpreter's
// exit can wait for it. A daemon thread still inside such work when Python
// finalizes is killed as it retakes the GIL (CPython pthread_exit()s it, and
// the forced unwind through a noexcept destructor aborts the process, exit
// 134). So an atexit hook (BindExit) raises Exiting(), which the work polls
// where it can stop early, stops sweeps as SIGTERM would, and waits up to a
// minute for the count to reach 0; from then on, entering raises
// RuntimeError without releasing the GIL.
class WithoutGil {
 public:
  WithoutGil();  // called with the GIL held
  ~WithoutGil();
  WithoutGil(const WithoutGil&) = delete;
  WithoutGil& operator=(const WithoutGil&) = delete;

 private:
  std::optional<py::gil_scoped_release> release_;
};
// Raised once the interpreter has begun to exit: a cancel flag for
// StopCondition::WithCancelFlag.
const std::atomic<bool>& Exiting();
void BindExit(py::module_& m);   // module_exit.cc: the atexit hook

void BindRuns(py::module_& m);   // module_runs.cc: run_sweep
void BindSteps(py::module_& m);  // module_steps.cc: Problem, Estimator, Estimate
void BindAlgorithms(py::module_& m);  // module_algorithms.cc: estimators written in Python

}  // namespace icp::python

#endif  // ICPBENCH_PYTHON_MODULE_INTERNAL_H_
