// What the three parts of the _icpbench extension share.
#ifndef ICPBENCH_PYTHON_MODULE_INTERNAL_H_
#define ICPBENCH_PYTHON_MODULE_INTERNAL_H_

#include <pybind11/pybind11.h>

#include <signal.h>

#include <atomic>
#include <csignal>
#include <optional>
#include <string>
#include <utility>

#include "core/params.h"
#include "harness/sweep_recorder.h"

namespace icp::python {

namespace py = pybind11;

// A Python dict of parameters as the command line's key=value strings:
// True/False become true/false, numbers and strings their str().
ParamMap ToParamMap(const py::dict& params);
// The NumPy dtype kind of value ('b' bool, 'i'/'u' integer, 'f' float, ...),
// 0 for a value without a dtype (a Python number, a string).
char DtypeKind(const py::handle& value);

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

// Whether this is Python's main thread, the one that sees Ctrl-C (after a
// fork, the thread that forked).
bool IsMainThread();

// Runs work(cancel) in this thread with the GIL released: C++ that needs no
// GIL and stops soon after cancel is raised. On the main thread (unless
// SIGINT is ignored, as in a sweep's worker) SIGINT, SIGTERM and SIGHUP are
// caught meanwhile by the handlers sweeps use (StopSignals: a signal stops
// a sweep running in another thread too) and raise cancel; afterwards
// KeyboardInterrupt is raised for SIGINT, and SIGTERM or SIGHUP is raised
// again once Python's handlers are back. Another thread sees no signal, as
// in Python; there cancel is the interpreter's exit, after which
// RuntimeError("icpbench: WHAT cancelled, the interpreter is exiting") is
// raised. Called with the GIL held; work's own exceptions reach the caller.
template <class Work>
auto RunCatchingSignals(const std::string& what, Work work) {
  using Result = decltype(work(std::declval<const std::atomic<bool>&>()));
  std::optional<Result> result;
  bool catching = IsMainThread();
  if (catching) {
    struct sigaction now {};
    sigaction(SIGINT, nullptr, &now);
    catching = now.sa_handler != SIG_IGN;
  }
  int caught = 0;
  {
    std::optional<StopSignals> signals;
    if (catching) signals.emplace();
    const std::atomic<bool>& cancel = catching ? StopSignals::Flag() : Exiting();
    {
      WithoutGil release;
      result.emplace(work(cancel));
    }
    if (catching) caught = StopSignals::Caught();
  }  // Python's handlers are back
  if (caught == SIGINT) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  if (caught != 0) std::raise(caught);
  if (!catching && Exiting()) {
    PyErr_SetString(PyExc_RuntimeError, ("icpbench: " + what + " cancelled, the interpreter is exiting").c_str());
    throw py::error_already_set();
  }
  return std::move(*result);
}

// Whether algorithm `name` was registered from Python (register_algorithm):
// its steps run Python code, which needs the GIL and sees Ctrl-C itself.
bool IsPythonAlgorithm(const std::string& name);

void BindRuns(py::module_& m);   // module_runs.cc: run_sweep
void BindSteps(py::module_& m);  // module_steps.cc: Problem, Estimator, Estimate
void BindAlgorithms(py::module_& m);  // module_algorithms.cc: estimators written in Python

}  // namespace icp::python

#endif  // ICPBENCH_PYTHON_MODULE_INTERNAL_H_
