// _icpbench: the C++ half of the Python module (python/icpbench/__init__.py
// is the other). Errors reach Python as the command line words them: bad
// input (a parameter, a spec, a Minibex file, a locked output directory) as
// ValueError, the environment (disk, processes, descriptors) as OSError.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/minibex_parser.h"
#include "harness/environment_error.h"
#include "harness/list_command.h"
#include "harness/results_store.h"
#include "harness/solve_command.h"
#include "python/module_internal.h"
#include "python/module_views.h"

namespace icp::python {

char DtypeKind(const py::handle& value) {
  if (!py::hasattr(value, "dtype")) return 0;
  const std::string kind = py::str(value.attr("dtype").attr("kind"));
  return kind.size() == 1 ? kind[0] : 0;
}

ParamMap ToParamMap(const py::dict& params) {
  ParamMap map;
  for (const auto& [key, value] : params) {
    const std::string name = py::str(key);
    // NumPy's bool is a bool too (its text, "True", is not one).
    if (py::isinstance<py::bool_>(value) || DtypeKind(value) == 'b')
      map[name] = PyObject_IsTrue(value.ptr()) == 1 ? "true" : "false";
    else if (py::isinstance<py::float_>(value))  // a float's repr round-trips (NumPy 2's
      map[name] = py::str(py::repr(py::float_(PyFloat_AsDouble(value.ptr()))));  // says np.float64(...))
    else
      map[name] = py::str(value);
  }
  return map;
}

namespace {

// What solve() parsed and built, by file, algorithm and parameters, so that
// a loop solving one file parses it and builds its contractor once (the
// contractor is contracted again, as `solve --repeat` does). An entry holds
// the text it was built from and serves only that text: a file replaced
// with the same size and time (cp -p, rsync) is not answered from the old
// one. A few entries at most. Texts (solve(text) writes each to a
// temporary file) share the key "<minibex text>", one entry per algorithm
// and parameters, so a loop over one text parses it once.
struct Prepared {
  std::string text;
  std::shared_ptr<const ConstraintSystem> system;
  std::shared_ptr<Contractor> contractor;
};
std::map<std::string, Prepared>& PreparedCache() {
  static std::map<std::string, Prepared> cache;
  return cache;
}
// `solve`: the JSON the command line prints (solve --format json) and the
// variables' names in order.
py::tuple SolveJson(const std::string& file, const std::string& algorithm, const py::dict& params,
                    int repeat, double timeout_s, bool is_text) {
  SolveOptions options;
  options.file = file;
  std::string text = ReadMinibexFile(file);
  std::string key = (is_text ? "<minibex text>" : file) + "|" + algorithm;
  for (const auto& [name, value] : ToParamMap(params)) key += "|" + name + "=" + value;
  // Taken out of the cache while in use (the GIL, held here, orders the
  // cache's changes): a contractor serves one contraction at a time, so a
  // thread solving the same file meanwhile builds its own.
  Prepared prepared;
  if (auto entry = PreparedCache().extract(key); entry && entry.mapped().text == text)
    prepared = std::move(entry.mapped());
  if (!prepared.system) {
    prepared.system = std::make_shared<const ConstraintSystem>(ParseMinibex(text, file));
    prepared.text = std::move(text);
  }
  options.parsed = prepared.system;
  options.contractor = prepared.contractor;
  options.algorithm = algorithm;
  for (const auto& [key, value] : ToParamMap(params)) options.params.push_back(key + "=" + value);
  options.format = "json";
  options.repeat = repeat;
  options.timeout_s = timeout_s;
  const SolveResult result = RunCatchingSignals("solve", [&options](const std::atomic<bool>& cancel) {
    options.cancel = &cancel;
    return Solve(options);
  });
  prepared.contractor = result.contractor;
  auto& cache = PreparedCache();
  if (cache.size() >= 16) cache.clear();
  cache[key] = std::move(prepared);
  return py::make_tuple(SolveResultToJson(result), result.csp.names());
}

}  // namespace

}  // namespace icp::python

PYBIND11_MODULE(_icpbench, m) {
  namespace py = pybind11;
  using namespace icp::python;
  m.doc() = "The C++ half of the icpbench module; use `import icpbench`.";

  // The order matters: pybind11 tries the newest registration first.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const icp::EnvironmentError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const icp::StoreError& e) {  // the command line's exit 2, too
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const std::filesystem::filesystem_error& e) {  // creating an output
      const int code = e.code().value();
      if (icp::IsEnvironmentErrno(code)) {
        const std::string message = std::string(e.what()) + " (" + icp::EnvironmentAdvice(code) + ")";
        PyErr_SetObject(PyExc_OSError, py::make_tuple(code, message).ptr());
      } else {
        PyErr_SetString(PyExc_ValueError, e.what());
      }
    } catch (const py::cast_error& e) {  // an argument of the wrong kind: bad input
      PyErr_SetString(PyExc_ValueError,
                      (std::string("an argument or a returned value of the wrong type (") + e.what() +
                       ")").c_str());
    } catch (const py::builtin_exception& e) {  // StopIteration, IndexError, ...: as raised
      e.set_error();
    } catch (const std::runtime_error& e) {  // a malformed file: the command line's exit 2
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  m.def("list_json", &icp::ListPlugins, py::arg("what"), py::arg("format") = "json",
        "The registry `what` (algorithms or problems) as `icpbench list WHAT --format json`.");
  m.def("solve_json", &SolveJson, py::arg("file"), py::arg("algorithm"), py::arg("params"),
        py::arg("repeat"), py::arg("timeout_s"), py::arg("is_text") = false,
        "(solve --format json text, variable names) for a Minibex file.");
  BindExit(m);
  BindViews(m);
  BindRuns(m);
  BindSteps(m);
  BindAlgorithms(m);
}
