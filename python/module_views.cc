#include "python/module_views.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include "algorithms/registry.h"
#include "algorithms/window/window_estimator.h"
#include "core/polar_sighting.h"
#include "core/random.h"

namespace icp::python {

py::array_t<double> Array(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::tuple BoundsOf(const Box& box) {
  std::vector<double> lo, hi;
  for (std::size_t i = 0; i < box.size(); ++i) {
    lo.push_back(box[i].lo());
    hi.push_back(box[i].hi());
  }
  return py::make_tuple(Array(lo), Array(hi));
}

Box BoxFromBounds(const py::handle& lo, const py::handle& hi, std::size_t size) {
  return BoxFromBounds(lo.cast<std::vector<double>>(), hi.cast<std::vector<double>>(), size);
}

Box BoxFromBounds(const std::vector<double>& l, const std::vector<double>& h, std::size_t size) {
  if (l.size() != size || h.size() != size)
    throw py::value_error(std::to_string(l.size()) + " lower and " + std::to_string(h.size()) +
                          " upper bounds for a box of " + std::to_string(size) + " components");
  Box box(size);
  // Empty is written lo +inf, hi -inf throughout (as the module returns it);
  // any other NaN or crossed bound is a bug of the caller's, not "no
  // solution" (0/0 or swapped arrays would read as an empty set).
  const bool empty = size > 0 && std::all_of(l.begin(), l.end(), [](double x) { return x == kInf; }) &&
                     std::all_of(h.begin(), h.end(), [](double x) { return x == -kInf; });
  if (empty) {
    box.SetEmpty();
    return box;
  }
  for (std::size_t i = 0; i < size; ++i) {
    // [+inf, +inf] and [-inf, -inf] hold no real number: an overflow in one
    // component would otherwise empty the whole box.
    if (!(l[i] <= h[i]) || l[i] == kInf || h[i] == -kInf)
      throw py::value_error("lo " + FormatDouble(l[i]) + " and hi " + FormatDouble(h[i]) +
                            " at component " + std::to_string(i) +
                            " (NaN or lo > hi, or an infinite point; an empty box is None, "
                            "or lo +inf and hi -inf throughout)");
    box[i] = Interval(l[i], h[i]);
  }
  return box;
}

namespace {

const Views& Of(const PyView& v) { return *v.views; }

const CspView& CspOf(const PyView& v) {
  if (!v.views->csp) throw py::value_error("this step offers no csp view");
  return *v.views->csp;
}

const MeasurementSetView& MeasurementsOf(const PyView& v) {
  if (!v.views->measurement_set) throw py::value_error("this step offers no measurement-set view");
  return *v.views->measurement_set;
}

const ProbabilisticView& ModelOf(const PyView& v) {
  if (!v.views->probabilistic) throw py::value_error("this step offers no probabilistic view");
  return *v.views->probabilistic;
}

// box contracted by the contractor make() builds, with the GIL released
// and Ctrl-C stopping it (RunCatchingSignals).
Box Contracted(const Box& box, const std::function<std::unique_ptr<Contractor>()>& make) {
  return RunCatchingSignals("the contraction", [&](const std::atomic<bool>& cancel) {
    ContractContext context(StopCondition().WithCancelFlag(&cancel));
    Box out = box;
    make()->Contract(out, context);
    return out;
  });
}

// Contracts (lo, hi) over the CSP's variables with a registered CSP contractor.
py::tuple ContractCsp(const PyView& v, const py::handle& lo, const py::handle& hi,
                      const std::string& algorithm, const py::dict& params) {
  const CspView& view = CspOf(v);
  const AlgorithmInfo& info = FindAlgorithm(algorithm);
  if (info.contractor == nullptr)
    throw py::value_error("'" + algorithm + "' is not a CSP contractor");
  Box box = BoxFromBounds(lo, hi, static_cast<std::size_t>(view.csp.num_variables()));
  const ParamMap contractor_params = ToParamMap(params);
  if (contractor_params.count("carry"))
    throw py::value_error("carry is a parameter of an estimator over windows; contract() contracts "
                          "the box it is given");
  if (box.IsEmpty()) return BoundsOf(box);
  return BoundsOf(Contracted(box, [&] { return info.contractor(contractor_params, view.csp); }));
}

const LandmarkObservationView& ObservationsOf(const PyView& v) {
  if (!v.views->landmark_observations)
    throw py::value_error("this step offers no landmark-observations view");
  return *v.views->landmark_observations;
}

py::tuple IntervalOf(const Interval& x) { return py::make_tuple(x.lo(), x.hi()); }

// The map as arrays: id, type, x, y.
py::dict MapOf(const PyView& v) {
  const LandmarkObservationView& view = ObservationsOf(v);
  std::vector<double> x, y;
  std::vector<int> id, type;
  for (const TypedLandmark& l : *view.map) {
    id.push_back(l.id);
    type.push_back(l.type);
    x.push_back(l.x);
    y.push_back(l.y);
  }
  py::dict out;
  out["id"] = py::array_t<int>(static_cast<py::ssize_t>(id.size()), id.data());
  out["type"] = py::array_t<int>(static_cast<py::ssize_t>(type.size()), type.data());
  out["x"] = Array(x);
  out["y"] = Array(y);
  return out;
}

// The returns as arrays: type, range (lo, hi) and bearing (lo, hi).
py::dict ReturnsOf(const PyView& v) {
  const LandmarkObservationView& view = ObservationsOf(v);
  std::vector<int> type;
  std::vector<Interval> range, bearing;
  for (const PolarObservation& o : view.observations) {
    type.push_back(o.type);
    range.push_back(o.range);
    bearing.push_back(o.bearing);
  }
  py::dict out;
  out["type"] = py::array_t<int>(static_cast<py::ssize_t>(type.size()), type.data());
  out["range"] = BoundsOf(Box(std::move(range)));
  out["bearing"] = BoundsOf(Box(std::move(bearing)));
  return out;
}

py::object OdometryOf(const PyView& v) {
  const LandmarkObservationView& view = ObservationsOf(v);
  if (!view.odometry) return py::none();
  const WheelOdometry& o = *view.odometry;
  py::dict out;
  out["right_radius"] = IntervalOf(o.right_radius);
  out["left_radius"] = IntervalOf(o.left_radius);
  out["track"] = IntervalOf(o.track);
  out["right_rotation"] = IntervalOf(o.right_rotation);
  out["left_rotation"] = IntervalOf(o.left_rotation);
  out["distance"] = IntervalOf(OdometryDistance(o));
  out["turn"] = IntervalOf(OdometryTurn(o));
  return out;
}

// Contracts a pose box (x, y, theta) by return i seen from the landmark
// with identity `landmark` (eq. 10-11, core/polar_sighting.h) with a
// registered CSP contractor.
py::tuple ContractSighting(const PyView& v, std::size_t i, int landmark, const py::handle& lo,
                           const py::handle& hi, const std::string& algorithm) {
  const LandmarkObservationView& view = ObservationsOf(v);
  if (i >= view.observations.size())
    throw py::index_error("return " + std::to_string(i) + " of " +
                          std::to_string(view.observations.size()));
  const TypedLandmark* l = nullptr;
  for (const TypedLandmark& candidate : *view.map)
    if (candidate.id == landmark) l = &candidate;
  if (l == nullptr) throw py::value_error("no landmark " + std::to_string(landmark) + " in the map");
  const AlgorithmInfo& info = FindAlgorithm(algorithm);
  if (info.contractor == nullptr) throw py::value_error("'" + algorithm + "' is not a CSP contractor");
  Box box = BoxFromBounds(lo, hi, 3);
  if (box.IsEmpty()) return BoundsOf(box);
  const ConstraintSystem csp = PoseSighting(l->x, l->y, view.observations[i], box);
  return BoundsOf(Contracted(box, [&] { return info.contractor({}, csp); }));
}

py::tuple ContractMeasurement(const PyView& v, std::size_t i, const py::handle& lo,
                              const py::handle& hi) {
  const MeasurementSetView& view = MeasurementsOf(v);
  if (i >= view.measurements.size())
    throw py::index_error("measurement " + std::to_string(i) + " of " +
                          std::to_string(view.measurements.size()));
  Box box = BoxFromBounds(lo, hi, view.prior.size());
  if (!box.IsEmpty()) {
    ContractContext context;
    view.measurements[i]->Contract(box, context);
  }
  return BoundsOf(box);
}

py::array_t<double> Samples(const PyView& v, std::size_t n, std::uint64_t seed, bool global) {
  const ProbabilisticView& model = ModelOf(v);
  const auto& sample = global && model.sample_global ? model.sample_global : model.sample_prior;
  RandomEngine engine(seed);
  const auto d = static_cast<py::ssize_t>(v.views->space.size());
  py::array_t<double> out({static_cast<py::ssize_t>(n), d});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t k = 0; k < n; ++k) {
    const std::vector<double> s = sample(engine);
    for (py::ssize_t c = 0; c < d; ++c) a(k, c) = s[c];
  }
  return out;
}

}  // namespace

void BindViews(py::module_& m) {
  py::class_<PyView>(m, "View", "What an estimator may see of a step (no truth).")
      .def_property_readonly("index", [](const PyView& v) { return Of(v).step; })
      .def_property_readonly("names", [](const PyView& v) { return Of(v).space.names; },
                             "The state's components (an estimate is a box over them).")
      .def_property_readonly("offers", [](const PyView& v) {
        std::vector<std::string> views;
        for (View k : {View::kCsp, View::kMeasurementSet, View::kProbabilistic,
                       View::kLandmarkObservations})
          if (Of(v).Offers(k)) views.emplace_back(ToString(k));
        return views;
      })
      // csp
      .def_property_readonly("csp_variables", [](const PyView& v) { return CspOf(v).csp.names(); })
      .def_property_readonly("csp_domains", [](const PyView& v) { return BoundsOf(CspOf(v).csp.domains()); },
                             "The CSP's initial box as (lo, hi) arrays.")
      .def("newest_state", [](const PyView& v, const py::handle& lo, const py::handle& hi) {
        const CspView& view = CspOf(v);
        const Box box = BoxFromBounds(lo, hi, static_cast<std::size_t>(view.csp.num_variables()));
        return BoundsOf(NewestState(view, box, Of(v).space.size()));
      }, py::arg("lo"), py::arg("hi"), "The newest state's bounds of a box over the CSP's variables.")
      .def("contract", &ContractCsp, py::arg("lo"), py::arg("hi"), py::arg("algorithm") = "hc4",
           py::arg("params") = py::dict(),
           "Contracts a box over the CSP's variables with a registered CSP contractor.")
      // measurement-set
      .def_property_readonly("prior", [](const PyView& v) { return BoundsOf(MeasurementsOf(v).prior); })
      .def_property_readonly("num_measurements",
                             [](const PyView& v) { return MeasurementsOf(v).measurements.size(); })
      .def("contract_measurement", &ContractMeasurement, py::arg("i"), py::arg("lo"), py::arg("hi"),
           "Contracts a box over the state with measurement i's contractor.")
      // landmark observations
      .def_property_readonly("observation_prior",
                             [](const PyView& v) { return BoundsOf(ObservationsOf(v).prior); },
                             "The start box at step 0, later every pose the robot may be in.")
      .def_property_readonly("landmark_map", &MapOf, "The map's landmarks: id, type, x, y arrays.")
      .def_property_readonly("type_names", [](const PyView& v) { return ObservationsOf(v).type_names; })
      .def_property_readonly("returns", &ReturnsOf,
                             "The typed returns: type, range (lo, hi), bearing (lo, hi).")
      .def_property_readonly("odometry", &OdometryOf,
                             "The wheel odometry since the last step as (lo, hi) intervals; None at step 0.")
      .def("contract_sighting", &ContractSighting, py::arg("i"), py::arg("landmark"), py::arg("lo"),
           py::arg("hi"), py::arg("algorithm") = "hc4",
           "Contracts a pose box by return i seen from a landmark (paper 002 eq. 10-11).")
      // probabilistic
      .def("sample_prior", [](const PyView& v, std::size_t n, std::uint64_t seed) {
        return Samples(v, n, seed, false);
      }, py::arg("n"), py::arg("seed"))
      .def("sample_global", [](const PyView& v, std::size_t n, std::uint64_t seed) {
        return Samples(v, n, seed, true);
      }, py::arg("n"), py::arg("seed"))
      .def("log_likelihood", [](const PyView& v, const std::vector<double>& state) {
        const ProbabilisticView& model = ModelOf(v);
        if (state.size() != static_cast<std::size_t>(v.views->space.size()))
          throw py::value_error("a state needs " + std::to_string(v.views->space.size()) +
                                " components, got " + std::to_string(state.size()));
        return model.log_likelihood(state);
      }, py::arg("state"))
      .def("__repr__", [](const PyView& v) {
        return "<icpbench.View of step " + std::to_string(Of(v).step) + ">";
      });
}

}  // namespace icp::python
