// Stepping by hand: a problem's steps (Problem), an estimator fed one step at
// a time (Estimator) and what it returns (Estimate), as the runner does it
// (harness/runner.cc), with the step measured as the store measures it.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <variant>
#include <vector>

#include "algorithms/registry.h"
#include "harness/metrics.h"
#include "harness/runner.h"
#include "harness/step_judges.h"
#include "problems/registry.h"
#include "core/params.h"
#include "python/module_internal.h"
#include "python/module_views.h"

namespace icp::python {
namespace {

py::dict PropertiesToDict(const Properties& properties) {
  py::dict out;
  for (const Property& p : properties)
    std::visit([&](const auto& v) { out[py::str(p.name)] = v; }, p.value);
  return out;
}

// A list of boxes as an array of shape (boxes, variables, 2).
py::array_t<double> BoxesArray(const std::vector<Box>& boxes, int dims) {
  py::array_t<double> out({static_cast<py::ssize_t>(boxes.size()), static_cast<py::ssize_t>(dims),
                           py::ssize_t{2}});
  auto a = out.mutable_unchecked<3>();
  for (std::size_t b = 0; b < boxes.size(); ++b)
    for (int i = 0; i < dims; ++i) {
      a(b, i, 0) = boxes[b][i].lo();
      a(b, i, 1) = boxes[b][i].hi();
    }
  return out;
}

template <class T>
py::array_t<T> MatArray(const cv::Mat& mat) {
  py::array_t<T> out({static_cast<py::ssize_t>(mat.rows), static_cast<py::ssize_t>(mat.cols)});
  auto a = out.template mutable_unchecked<2>();
  for (int r = 0; r < mat.rows; ++r)
    for (int c = 0; c < mat.cols; ++c) a(r, c) = mat.at<T>(r, c);
  return out;
}

// Which Problem object a step came from: an estimator follows one stream
// of steps, as a run does.
struct Stream {
  std::string problem;
  std::uint64_t seed = 0;
};

struct PyStep {
  std::shared_ptr<const Step> step;
  std::shared_ptr<const Stream> stream;
};

// Python threads may share one Problem or Estimator: with the GIL released
// while they compute, a mutex makes their calls take turns.
class PyProblem {
 public:
  PyProblem(const std::string& name, const py::dict& params, std::uint64_t seed) {
    const ProblemInfo& info = FindProblem(name);
    params_ = info.resolve(info.name, ToParamMap(params));
    stream_ = std::make_shared<const Stream>(Stream{info.name, seed});
    WithoutGil release;  // a long drive takes seconds to simulate
    problem_ = info.make(params_, seed);
  }
  std::string Name() const { return std::string(problem_->Name()); }
  int NumSteps() const { return problem_->NumSteps(); }
  const ParamMap& Params() const { return params_; }
  PyStep Next() {
    auto step = std::make_shared<Step>();
    bool more;
    {
      WithoutGil release;
      std::lock_guard<std::mutex> turn(busy_);
      more = problem_->Next(step.get());
    }
    if (!more) throw py::stop_iteration();
    return PyStep{std::move(step), stream_};
  }

 private:
  ParamMap params_;
  std::shared_ptr<const Stream> stream_;
  std::unique_ptr<Problem> problem_;
  std::mutex busy_;
};

// One step's result: the estimate, the estimator's report and the step's
// measurement as the runner stores it.
struct PyEstimate {
  std::shared_ptr<StepResult> result;
  StepRecord record;
  StateSpace space;  // the step's: contains() reads a heading modulo 2 pi
};

class PyEstimator {
 public:
  PyEstimator(const std::string& name, const py::dict& params, std::uint64_t seed)
      : info_(&FindAlgorithm(name)) {
    params_ = info_->resolve(info_->name, ToParamMap(params));
    estimator_ = info_->make(params_, seed);
  }
  const ParamMap& Params() const { return params_; }
  std::string Needs() const { return std::string(ToString(info_->needs)); }

  PyEstimate StepOnce(const PyStep& s, double timeout_s) {
    if (!(timeout_s > 0))  // as solve(timeout=...) and `solve --timeout`
      throw py::value_error("timeout_s = " + FormatDouble(timeout_s) +
                            ": must be a number of seconds > 0 (inf: no limit)");
    // The estimator carries state from step to step (a window, a filter's
    // cloud): another problem's or seed's step would be read as the next.
    if (stream_ && stream_ != s.stream)
      throw py::value_error("this estimator has stepped problem '" + stream_->problem + "' (seed " +
                            std::to_string(stream_->seed) + "); this step is of '" + s.stream->problem +
                            "' (seed " + std::to_string(s.stream->seed) +
                            ") from another icpbench.problem(): make a new estimator for it");
    stream_ = s.stream;
    auto step = [this, &s, timeout_s](const std::atomic<bool>& cancel) {
      std::lock_guard<std::mutex> turn(busy_);
      StopCondition stop = timeout_s < std::numeric_limits<double>::infinity()
                               ? StopCondition::After(std::chrono::duration<double>(timeout_s))
                               : StopCondition();
      stop.WithCancelFlag(&cancel);
      PyEstimate out;
      TakenStep taken = TakeStep(*estimator_, info_->needs, *s.step, stop);
      judges_.Judge(*s.step, &taken);  // the properties icpbench run stores
      taken.result.solve_time_s = taken.record.solve_time_s;
      out.result = std::make_shared<StepResult>(std::move(taken.result));
      out.record = std::move(taken.record);
      out.space = s.step->views.space;
      return out;
    };
    // A Python estimator's code sees Ctrl-C itself.
    if (!IsPythonAlgorithm(info_->name)) return RunCatchingSignals("the step", step);
    WithoutGil release;
    return step(Exiting());
  }
  py::dict RunProperties() {
    Properties properties;
    {
      WithoutGil release;
      std::lock_guard<std::mutex> turn(busy_);
      properties = estimator_->RunProperties();
      for (Property& p : judges_.RunProperties()) properties.push_back(std::move(p));
    }
    return PropertiesToDict(properties);
  }

 private:
  const AlgorithmInfo* info_;
  ParamMap params_;
  std::unique_ptr<Estimator> estimator_;
  StepJudges judges_;
  std::shared_ptr<const Stream> stream_;  // of the steps stepped so far
  std::mutex busy_;
};

const Estimate& EstimateOf(const PyEstimate& e) { return *e.result->estimate; }

}  // namespace

void BindSteps(py::module_& m) {
  py::register_exception<InvalidResult>(m, "InvalidResult", PyExc_RuntimeError);

  py::class_<PyStep>(m, "Step", "One step of a problem: its truth and the views it offers.")
      .def_property_readonly("index", [](const PyStep& s) { return s.step->views.step; })
      .def_property_readonly("names", [](const PyStep& s) { return s.step->views.space.names; })
      .def_property_readonly("truth", [](const PyStep& s) { return Array(s.step->truth); },
                             "The true state (empty when unknown).")
      .def_property_readonly("annotations",
                             [](const PyStep& s) { return PropertiesToDict(s.step->annotations); })
      .def_property_readonly("view", [](const PyStep& s) {
        return PyView{std::shared_ptr<const Views>(s.step, &s.step->views)};
      }, "What an estimator sees of the step (icpbench.View).")
      .def("__repr__", [](const PyStep& s) {
        return "<icpbench.Step " + std::to_string(s.step->views.step) + ">";
      });

  py::class_<PyProblem>(m, "Problem", "A problem's steps, one at a time (an iterator).")
      .def(py::init<const std::string&, const py::dict&, std::uint64_t>(), py::arg("name"),
           py::arg("params"), py::arg("seed"))
      .def_property_readonly("name", &PyProblem::Name)
      .def_property_readonly("num_steps", &PyProblem::NumSteps)
      .def_property_readonly("params", &PyProblem::Params, "The effective parameters.")
      .def("__iter__", [](PyProblem& p) -> PyProblem& { return p; })
      .def("__next__", &PyProblem::Next);

  py::class_<PyEstimate>(m, "Estimate", "What an estimator returned for one step.")
      .def_property_readonly("kind", [](const PyEstimate& e) { return std::string(EstimateOf(e).Kind()); })
      .def_property_readonly("status", [](const PyEstimate& e) { return e.record.status; })
      .def_property_readonly("lo", [](const PyEstimate& e) -> py::object {
        return BoundsOf(EstimateOf(e).Hull())[0];
      })
      .def_property_readonly("hi", [](const PyEstimate& e) -> py::object {
        return BoundsOf(EstimateOf(e).Hull())[1];
      })
      .def_property_readonly("centre", [](const PyEstimate& e) {
        std::vector<double> centre = EstimateOf(e).Centre();
        // As lo and hi, one value per component: NaN where there is no centre.
        if (centre.empty()) centre.assign(EstimateOf(e).Hull().size(), std::numeric_limits<double>::quiet_NaN());
        return Array(centre);
      }, "The estimate's centre (NaN throughout for an empty one).")
      .def("contains", [](const PyEstimate& e, const std::vector<double>& point) {
        const Estimate& estimate = EstimateOf(e);
        if (point.size() != estimate.Hull().size())
          throw py::value_error("a point needs " + std::to_string(estimate.Hull().size()) +
                                " components, got " + std::to_string(point.size()));
        return ContainsState(e.space, estimate, point);
      }, py::arg("point"), "Whether point lies in the estimate (a heading compared modulo 2 pi, as contained).")
      .def_property_readonly("contained", [](const PyEstimate& e) -> py::object {
        if (e.record.contained < 0) return py::none();
        return py::bool_(e.record.contained == 1);
      }, "Whether the truth is in the estimate, as the store records it (None: truth unknown).")
      .def_property_readonly("area", [](const PyEstimate& e) { return e.record.area; })
      .def_property_readonly("centre_error", [](const PyEstimate& e) { return e.record.centre_error; })
      .def_property_readonly("solve_time_s", [](const PyEstimate& e) { return e.result->solve_time_s; })
      .def_property_readonly("values", [](const PyEstimate& e) {
        py::dict out;
        for (const VariableRecord& v : e.record.vars) out[py::str(v.name)] = py::make_tuple(v.lo, v.hi);
        return out;
      }, "The reported variables' bounds, {name: (lo, hi)}, as the store's step_values.")
      .def_property_readonly("properties", [](const PyEstimate& e) {
        return PropertiesToDict(e.record.properties);
      }, "The step's properties as the store's step_properties: the estimator's, the judges' "
         "(assumption_held, covered_*, associations_*, post_*), the problem's annotations, the "
         "estimate's extras")
      .def_property_readonly("boxes", [](const PyEstimate& e) -> py::object {
        const auto* paving = dynamic_cast<const PavingEstimate*>(e.result->estimate.get());
        if (!paving) return py::none();
        const int d = paving->Hull().size();
        py::dict out;
        out["inner"] = BoxesArray(paving->inner(), d);
        out["boundary"] = BoxesArray(paving->boundary(), d);
        return out;
      }, "A paving's boxes, {'inner', 'boundary'} arrays of shape (boxes, variables, 2); else None.")
      .def_property_readonly("counts", [](const PyEstimate& e) -> py::object {
        const auto* acc = dynamic_cast<const AccumulatorEstimate*>(e.result->estimate.get());
        if (!acc) return py::none();
        return MatArray<std::int32_t>(acc->counts());
      }, "An accumulator's counts (rows, columns); else None.")
      .def_property_readonly("particles", [](const PyEstimate& e) -> py::object {
        const auto* cloud = dynamic_cast<const ParticleEstimate*>(e.result->estimate.get());
        if (!cloud) return py::none();
        return MatArray<double>(cloud->particles());
      }, "A particle filter's particles (particles, components); else None.")
      .def_property_readonly("weights", [](const PyEstimate& e) -> py::object {
        const auto* cloud = dynamic_cast<const ParticleEstimate*>(e.result->estimate.get());
        if (!cloud) return py::none();
        return Array(cloud->weights());
      });

  py::class_<PyEstimator>(m, "Estimator", "An algorithm fed one step at a time.")
      .def(py::init<const std::string&, const py::dict&, std::uint64_t>(), py::arg("name"),
           py::arg("params"), py::arg("seed"))
      .def_property_readonly("params", &PyEstimator::Params, "The effective parameters.")
      .def_property_readonly("needs", &PyEstimator::Needs)
      .def("step", &PyEstimator::StepOnce, py::arg("step"),
           py::arg("timeout_s") = std::numeric_limits<double>::infinity())
      .def("run_properties", &PyEstimator::RunProperties);
}

}  // namespace icp::python
