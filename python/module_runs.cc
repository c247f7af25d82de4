// run_sweep: the command line's `run` (harness/runner.h) for a spec's text,
// with its progress written to Python's sys.stderr (a terminal or a
// notebook's cell) a line at a time.
#include <pybind11/pybind11.h>

#include <ostream>
#include <streambuf>
#include <string>

#include "harness/runner.h"
#include "harness/spec.h"
#include "python/module_internal.h"

namespace icp::python {
namespace {

// Collects what the runner writes and hands each line (ended by \n, or by
// \r for a terminal's redrawn bar) to sys.stderr, taking the GIL for it.
class PythonStderrBuffer : public std::streambuf {
 protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) return 0;
    line_ += static_cast<char>(c);
    if (c == '\n' || c == '\r') Flush();
    return c;
  }
  int sync() override {
    Flush();
    return 0;
  }

 private:
  void Flush() {
    if (line_.empty()) return;
    py::gil_scoped_acquire gil;
    // sys.stderr may be None (pythonw, a daemon) or a stream without
    // flush: the progress is then dropped, the runs are not.
    py::object err = py::module_::import("sys").attr("stderr");
    if (!err.is_none() && py::hasattr(err, "write")) {
      err.attr("write")(line_);
      if (py::hasattr(err, "flush")) err.attr("flush")();
    }
    line_.clear();
  }
  std::string line_;
};

// spec: a spec file's path (is_path) or a spec's text, named source in errors.
py::dict Run(const std::string& spec_or_path, bool is_path, const std::string& source,
             const std::string& out_dir, int jobs, bool force, bool no_retry) {
  if (jobs < 1) throw std::invalid_argument("jobs must be at least 1");
  const Spec spec = is_path ? LoadSpec(spec_or_path) : ParseSpec(spec_or_path, source);
  RunnerOptions options;
  options.out_dir = out_dir;
  options.jobs = jobs;
  options.force = force;
  options.no_retry = no_retry;
  const py::object err = py::module_::import("sys").attr("stderr");
  const bool terminal = !err.is_none() && py::hasattr(err, "isatty") && py::bool_(err.attr("isatty")());
  PythonStderrBuffer buffer;
  std::ostream progress(&buffer);
  SweepSummary s;
  {
    WithoutGil release;
    s = RunSweep(spec, options, progress, terminal);
    progress.flush();
  }
  py::dict summary;
  summary["planned"] = s.planned;
  summary["already_stored"] = s.already_stored;
  summary["ok"] = s.ok;
  summary["failed"] = s.failed;
  summary["timed_out"] = s.timed_out;
  summary["skipped"] = s.skipped;
  summary["interrupted_by"] = s.interrupted_by;
  summary["stopped"] = s.stopped;
  return summary;
}

}  // namespace

void BindRuns(py::module_& m) {
  m.def("run_sweep", &Run, py::arg("spec"), py::arg("is_path"), py::arg("source"), py::arg("out"),
        py::arg("jobs"), py::arg("force"), py::arg("no_retry"),
        "Runs a spec (a path or a text) as `icpbench run` does; returns the sweep's counts.");
}

}  // namespace icp::python
