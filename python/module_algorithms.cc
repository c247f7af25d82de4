// Estimators written in Python (icpbench.register_algorithm): registered in
// the algorithm registry like a C++ plugin, so a sweep run by icpbench.run
// runs them in its worker processes beside the C++ ones. Their parameters
// are declared as a C++ plugin's are (a ParamSet: checked by name, type and
// range, defaults filled in) plus `python`, the class's import path, so the
// store says which Python class made a run. A worker is a fork of the
// Python process: the fork hooks (harness/fork_hooks.h) take the GIL around
// fork() and reset the interpreter in the child, as os.fork() does.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/registry.h"
#include "core/params.h"
#include "harness/fork_hooks.h"
#include "harness/plugin_loader.h"
#include "python/module_internal.h"
#include "python/module_views.h"

namespace icp::python {
namespace {

// One registered Python algorithm: its factory (a Python callable taking the
// parameters' texts and the seed, returning the estimator object) and its
// declared parameters with their storage, for a ParamSet.
struct PythonAlgorithm {
  py::object factory;
  std::string class_path;
  std::vector<ParamInfo> declared;  // name, type, default, range ("" or "one of ..."), doc
};

std::map<std::string, PythonAlgorithm>& Registered() {
  static auto* table = new std::map<std::string, PythonAlgorithm>;  // never destroyed: holds Python objects
  return *table;
}

// The ParamSet of a Python algorithm, its fields in `storage`.
struct Fields {
  std::deque<double> doubles;
  std::deque<int> ints;
  std::deque<bool> bools;
  std::deque<std::string> strings;
};
ParamSet Describe(const std::string& owner, Fields* f) {
  const PythonAlgorithm& algorithm = Registered().at(owner);
  ParamSet set(owner);
  for (const ParamInfo& p : algorithm.declared) {
    if (p.type == "double") {
      // Any double, inf included (a Python float may default to math.inf).
      double value = 0;
      ParseDouble(p.default_value, &value);  // repr() of a float: always decimal
      set.Add(p.name, &f->doubles.emplace_back(value), p.doc, Range::Closed(-kInf, kInf));
    } else if (p.type == "int") {
      set.Add(p.name, &f->ints.emplace_back(std::stoi(p.default_value)), p.doc,
              Range::Closed(std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
    } else if (p.type == "bool") {
      set.Add(p.name, &f->bools.emplace_back(p.default_value == "true"), p.doc);
    } else {
      // Its choices, so that the spec is checked before any run, as a C++
      // plugin's is.
      set.Add(p.name, &f->strings.emplace_back(p.default_value), p.doc, ChoicesOf(p));
    }
  }
  set.Add("python", &f->strings.emplace_back(algorithm.class_path),
          "the Python class that implements it (set by register_algorithm)", {algorithm.class_path});
  return set;
}

std::vector<ParamInfo> ListParams(const std::string& owner) {
  Fields fields;
  return Describe(owner, &fields).Describe();
}

ParamMap ResolvePythonParams(const std::string& owner, const ParamMap& values) {
  Fields fields;
  ParamSet set = Describe(owner, &fields);
  set.SetAll(values);
  set.Validate();
  return set.Values();
}

// "ValueError: message", the last line of the Python traceback.
std::string LastLine(const py::error_already_set& e) {
  std::string type = py::str(e.type().attr("__name__"));
  return type + ": " + std::string(py::str(e.value()));
}

class PythonEstimator : public Estimator {
 public:
  PythonEstimator(py::object instance, std::string name)
      : instance_(std::move(instance)), name_(std::move(name)) {}
  ~PythonEstimator() override {
    py::gil_scoped_acquire gil;
    instance_ = py::object();
  }

  StepResult Step(const Views& views, const StopCondition&) override {
    py::gil_scoped_acquire gil;
    StepResult result;
    try {
      py::object out = instance_.attr("step")(PyView{std::make_shared<const Views>(views)});
      result.estimate = std::make_unique<BoxEstimate>(ToBox(out, views.space.size()));
      if (py::hasattr(instance_, "associations"))
        result.associations = instance_.attr("associations")().cast<std::vector<int>>();
      if (py::hasattr(instance_, "properties"))
        for (const auto& [key, value] : instance_.attr("properties")().cast<py::dict>())
          result.properties.push_back(ToProperty(py::str(key), value));
    } catch (py::error_already_set& e) {
      // Ctrl-C and exit() are the user's, not the estimator's failure.
      if (e.matches(PyExc_KeyboardInterrupt) || e.matches(PyExc_SystemExit)) throw;
      throw std::runtime_error(name_ + " (Python) raised " + LastLine(e));
    } catch (const py::cast_error& e) {
      throw std::runtime_error(name_ + " (Python) returned what cannot be read (associations() "
                               "a list of ints, properties() a dict of bool, int, float or str "
                               "values; int within 64 bits): " + e.what());
    }
    result.summary.status = result.estimate->Hull().IsEmpty() ? ContractStatus::kEmpty
                                                              : ContractStatus::kContracted;
    return result;
  }

 private:
  // What step() returned: (lo, hi), an object with .lo and .hi, or None (empty).
  static Box ToBox(const py::object& out, int size) {
    const auto n = static_cast<std::size_t>(size);
    if (out.is_none()) {
      Box empty(n);
      empty.SetEmpty();
      return empty;
    }
    constexpr const char* kShape = "step() must return (lo, hi), an object with .lo and .hi, or None";
    py::object lo, hi;
    if (py::hasattr(out, "lo") && py::hasattr(out, "hi")) {
      lo = out.attr("lo");
      hi = out.attr("hi");
    } else {
      if (!py::isinstance<py::tuple>(out) || py::len(out) != 2) throw py::value_error(kShape);
      lo = out[py::int_(0)];
      hi = out[py::int_(1)];
    }
    std::vector<double> l, h;
    try {
      l = lo.cast<std::vector<double>>();
      h = hi.cast<std::vector<double>>();
    } catch (const py::cast_error&) {
      throw py::value_error(std::string(kShape) + ", the bounds sequences of numbers");
    }
    try {
      return BoxFromBounds(l, h, n);
    } catch (const py::value_error& e) {
      throw py::value_error(std::string("step() returned ") + e.what());
    }
  }
  // A property's value as the store keeps it: NumPy's integers and bools
  // (a count from np.sum) as integers, its floats as reals; anything else
  // but text is refused rather than stored as its str().
  static Property ToProperty(const std::string& name, const py::handle& value) {
    const char kind = DtypeKind(value);  // a NumPy scalar's, not an array's
    const bool numpy_scalar = kind != 0 && py::isinstance(value, py::module_::import("numpy").attr("generic"));
    if (py::isinstance<py::bool_>(value) || py::isinstance<py::int_>(value) ||
        (numpy_scalar && (kind == 'b' || kind == 'i' || kind == 'u'))) {
      const py::int_ integer(py::reinterpret_borrow<py::object>(value));
      int overflow = 0;
      const long long v = PyLong_AsLongLongAndOverflow(integer.ptr(), &overflow);
      if (overflow != 0)
        throw py::cast_error("property '" + name + "' is " + std::string(py::str(py::object(integer))) +
                             ": beyond 64 bits");
      return {name, static_cast<std::int64_t>(v)};
    }
    if (py::isinstance<py::float_>(value) || (numpy_scalar && kind == 'f'))
      return {name, PyFloat_AsDouble(value.ptr())};
    if (py::isinstance<py::str>(value)) return {name, value.cast<std::string>()};
    throw py::cast_error("property '" + name + "' is " + std::string(py::str(py::repr(value))) +
                         " of type " + std::string(py::str(value.get_type().attr("__name__"))));
  }

  py::object instance_;
  std::string name_;
};

std::unique_ptr<Estimator> MakePythonEstimator(const ParamMap& params, std::uint64_t seed) {
  py::gil_scoped_acquire gil;
  const std::string class_path = params.at("python");
  for (const auto& [name, algorithm] : Registered()) {
    if (algorithm.class_path != class_path) continue;
    ParamMap texts = params;
    texts.erase("python");
    try {
      return std::make_unique<PythonEstimator>(algorithm.factory(texts, seed), name);
    } catch (py::error_already_set& e) {
      throw std::runtime_error(name + " (Python) raised " + LastLine(e));
    }
  }
  throw std::invalid_argument("no Python algorithm implemented by " + class_path);
}

// The GIL around the fork that starts a worker, and the interpreter reset in
// it (PyOS_AfterFork_Child), as os.fork() does.
void InstallForkHooks() {
  static PyGILState_STATE state;
  SetForkHooks({[] {
                  state = PyGILState_Ensure();
                  PyOS_BeforeFork();
                },
                [] {
                  PyOS_AfterFork_Parent();
                  PyGILState_Release(state);
                },
                [] {
                  PyOS_AfterFork_Child();
                  PyGILState_Release(state);
                }});
}

void Register(const std::string& name, py::object factory, const std::string& class_path,
              const std::string& needs, const std::vector<ParamInfo>& declared,
              const std::string& description) {
  View view;
  if (needs == "csp") view = View::kCsp;
  else if (needs == "measurement-set") view = View::kMeasurementSet;
  else if (needs == "probabilistic") view = View::kProbabilistic;
  else if (needs == "landmark-observations") view = View::kLandmarkObservations;
  else throw py::value_error("needs='" + needs +
                             "': must be csp, measurement-set, probabilistic or landmark-observations");
  // The names a C++ plugin may use (they are spec keys and parts of run keys).
  if (const std::string rule = NameRuleViolation(name); !rule.empty())
    throw py::value_error("algorithm '" + name + "' is not a valid name: " + rule);
  // The same class under the same name again (redefined in a notebook
  // cell): its new definition replaces the old, the view it needs kept.
  const auto same = Registered().find(name);
  const bool redefinition = same != Registered().end() && same->second.class_path == class_path;
  if (redefinition && FindAlgorithm(name).needs != view)
    throw py::value_error("algorithm '" + name + "' is registered with another needs: a "
                          "redefinition keeps its view (restart Python to change it)");
  if (!redefinition) {
    for (const AlgorithmInfo& a : Algorithms())
      if (a.name == name) throw py::value_error("algorithm '" + name + "' is already registered");
    for (const auto& [other, algorithm] : Registered())
      if (algorithm.class_path == class_path)
        throw py::value_error(class_path + " is already registered as '" + other + "'");
  }
  for (const ParamInfo& p : declared) {
    if (p.name == "python" || p.name == "seed")
      throw py::value_error("'" + p.name + "' is a reserved parameter name");
    if (const std::string rule = NameRuleViolation(p.name); !rule.empty())
      throw py::value_error("parameter '" + p.name + "' is not a valid name: " + rule);
  }
  // Checked before the registry knows the name: a failure leaves no trace
  // (a redefinition that fails leaves the previous one).
  std::optional<PythonAlgorithm> previous;
  if (redefinition) previous = same->second;
  Registered()[name] = {std::move(factory), class_path, declared};
  try {
    ResolvePythonParams(name, {});  // the declared defaults must pass their own checks
  } catch (const std::exception& e) {
    if (previous) Registered()[name] = *previous;
    else Registered().erase(name);
    throw py::value_error(name + ": " + e.what());
  }
  const std::string line = description.empty() ? class_path + " (Python)" : description;
  if (redefinition) {
    DescribeAlgorithm(name, line);
    return;
  }
  RegisterAlgorithm({name, line, &MakePythonEstimator, &ListParams, &ResolvePythonParams, view, {name, 5000, ""}});
  InstallForkHooks();
}

}  // namespace

bool IsPythonAlgorithm(const std::string& name) { return Registered().count(name) > 0; }

void BindAlgorithms(py::module_& m) {
  py::class_<ParamInfo>(m, "ParamInfo")
      .def(py::init<std::string, std::string, std::string, std::string, std::string>(),
           py::arg("name"), py::arg("type"), py::arg("default_value"), py::arg("range"),
           py::arg("doc"))
      .def_readonly("name", &ParamInfo::name);
  m.def("register_python_algorithm", &Register, py::arg("name"), py::arg("factory"),
        py::arg("class_path"), py::arg("needs"), py::arg("params"), py::arg("description"));
}

}  // namespace icp::python
