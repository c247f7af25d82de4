// What the three parts of the _icpbench extension share.
#ifndef ICPBENCH_PYTHON_MODULE_INTERNAL_H_
#define ICPBENCH_PYTHON_MODULE_INTERNAL_H_

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

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

// A thread of its own for one object's calls (an Estimator stepped by
// hand), so that a call need not start one: the calls run in turn, in the
// order they came.
class Worker {
 public:
  Worker() : thread_([this] { Loop(); }) {}
  ~Worker() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      done_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  Worker(const Worker&) = delete;
  Worker& operator=(const Worker&) = delete;
  std::future<void> Post(std::function<void()> work) {
    std::packaged_task<void()> task(std::move(work));
    std::future<void> done = task.get_future();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      tasks_.push_back(std::move(task));
    }
    wake_.notify_one();
    return done;
  }

 private:
  void Loop() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      wake_.wait(lock, [this] { return done_ || !tasks_.empty(); });
      if (tasks_.empty()) return;  // done_
      std::packaged_task<void()> task = std::move(tasks_.front());
      tasks_.pop_front();
      lock.unlock();
      task();
      lock.lock();
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::packaged_task<void()>> tasks_;
  bool done_ = false;
  std::thread thread_;  // last: started once the rest is ready
};

// Runs work (C++ that honours cancel and needs no GIL) on worker (a new
// thread where worker is null) while this one, every 50 ms, lets Python see
// a Ctrl-C (its handler only flags the signal; the check needs the GIL):
// then cancel is raised and, once work has returned, KeyboardInterrupt. As
// the interpreter exits, cancel is raised and RuntimeError("icpbench: WHAT
// cancelled ...") thrown. A thread other than the main one sees no signal,
// as in Python itself. Called with the GIL held; work's own exceptions
// reach the caller.
template <class Work>
auto RunInterruptibly(std::atomic<bool>& cancel, const std::string& what, Work work,
                      Worker* worker = nullptr) {
  using Result = decltype(work());
  std::optional<Result> result;
  bool interrupted = false, exited = false;
  {
    WithoutGil release;
    auto task = [&result, &work] { result.emplace(work()); };
    std::future<void> running =
        worker != nullptr ? worker->Post(task) : std::async(std::launch::async, task);
    while (running.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
      if (Exiting()) {  // the interpreter's exit waits for this call
        exited = cancel = true;
        continue;
      }
      py::gil_scoped_acquire gil;
      if (!interrupted && PyErr_CheckSignals() != 0) interrupted = cancel = true;
    }
    if (!interrupted && !exited) running.get();  // work's exception, if any
  }
  if (interrupted) throw py::error_already_set();
  if (exited) {
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
