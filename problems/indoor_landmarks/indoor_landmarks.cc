#include "problems/indoor_landmarks/indoor_landmarks.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "core/constraint_contractor.h"
#include "core/contractor_algebra.h"
#include "core/polar_sighting.h"
#include "core/random.h"
#include "problems/car_track/window.h"

namespace icp {

namespace {

constexpr double kSpuriousFloor = 0.05;  // the likelihood's share for spurious returns
// A sighting's two constraints repeated until no component shrinks by 1 %.
constexpr double kSightingRatio = 0.01;
constexpr int kSightingIterations = 20;

// Every heading: [-3 pi, 3 pi] (outward rounded), so that any heading
// interval narrower than 2 pi fits in it once moved by a multiple of 2 pi
// (InHeadingFrame).
const Interval kAnyHeading = Interval(-3, 3) * Pi();

// The headings of t (rad, unwrapped) in the frame of kAnyHeading, the
// prior's: t moved by the multiple of 2 pi that puts its lower bound in
// [-2 pi, 0), so that it never crosses the frame's ends; the whole frame
// when t is 2 pi wide or more. The relaxed solvers intersect the prior
// with the prediction: an unwrapped prediction would cut angles off.
Interval InHeadingFrame(const Interval& t) {
  if (t.IsEmpty()) return t;
  if (!t.IsBounded() || !(t.hi() - t.lo() < 2 * std::numbers::pi)) return kAnyHeading;
  const double turns = std::floor(t.lo() / (2 * std::numbers::pi)) + 1;
  const Interval moved = t - Interval(turns) * TwoPi();
  return moved.IsSubsetOf(kAnyHeading) ? moved : kAnyHeading;
}

double UniformIn(const Interval& x, RandomEngine& rng) { return UniformReal(rng, x.lo(), x.hi()); }

// "The return comes from one of the landmarks of its type": the union of
// each such landmark's sighting contractor, over (x, y, theta).
std::shared_ptr<Contractor> AnyLandmarkOfItsType(const IndoorMap& map,
                                                 const PolarObservation& observation) {
  SharedContractors candidates;
  for (const TypedLandmark& l : map.landmarks) {
    if (l.type != observation.type) continue;
    candidates.push_back(std::make_shared<FixpointContractor>(
        std::make_shared<SequenceContractor>(
            ConstraintContractors(PoseSighting(l.x, l.y, observation, Box(3)))),
        kSightingRatio, kSightingIterations));
  }
  return std::make_shared<UnionContractor>(std::move(candidates));
}

class IndoorLandmarksProblem : public Problem {
 public:
  IndoorLandmarksProblem(const IndoorLandmarksParams& params, IndoorMap map,
                         std::vector<IndoorRecord> records)
      : params_(params),
        map_(std::make_shared<const IndoorMap>(std::move(map))),
        landmarks_(map_, &map_->landmarks),  // the view's map: the same landmarks
        records_(std::move(records)) {
    const IndoorRecord& first = records_[0];
    start_ = Box({Interval(first.x) + Interval(-params_.start_error, params_.start_error),
                  Interval(first.y) + Interval(-params_.start_error, params_.start_error),
                  Interval(first.heading) +
                      Interval(-params_.start_heading_error, params_.start_heading_error)});
    const Box bounds = map_->Bounds();
    anywhere_ = Box({bounds[0], bounds[1], kAnyHeading});
  }
  std::string_view Name() const override { return "indoor-landmarks"; }
  int NumSteps() const override { return static_cast<int>(records_.size()); }
  bool Next(Step* step) override;

 private:
  ProbabilisticView Probabilistic(int k) const;

  IndoorLandmarksParams params_;
  std::shared_ptr<const IndoorMap> map_;
  std::shared_ptr<const std::vector<TypedLandmark>> landmarks_;
  std::vector<IndoorRecord> records_;
  Box start_, anywhere_;
  int k_ = 0;
};

bool IndoorLandmarksProblem::Next(Step* step) {
  if (k_ >= NumSteps()) return false;
  const int k = k_++;
  const IndoorRecord& r = records_[k];
  *step = Step();
  step->views.step = k;
  step->views.space = CarStateSpace();
  step->truth = {r.x, r.y, r.heading};
  step->observation_truth = r.identities;

  LandmarkObservationView view;
  view.prior = k == 0 ? start_ : anywhere_;
  if (k > 0) view.odometry = r.odometry;
  view.observations = r.observations;
  view.map = landmarks_;
  view.type_names = kIndoorLandmarkTypes;
  step->views.landmark_observations = std::move(view);

  MeasurementSetView set;
  set.prior = k == 0 ? start_ : anywhere_;
  for (const PolarObservation& o : r.observations) {
    set.measurements.push_back(AnyLandmarkOfItsType(*map_, o));
    Box at_truth({Interval(r.x), Interval(r.y), Interval(r.heading)});
    ContractContext context;
    set.measurements.back()->Contract(at_truth, context);
    set.outliers.push_back(at_truth.IsEmpty());
  }
  if (k > 0)
    set.predict = [odometry = r.odometry](const Box& previous) {
      if (previous.size() != 3)
        throw std::invalid_argument("indoor-landmarks predict: the box must be (x, y, theta)");
      Box next = PredictPose(previous, odometry);
      next[2] = InHeadingFrame(next[2]);
      return next;
    };
  step->views.measurement_set = std::move(set);
  step->views.probabilistic = Probabilistic(k);
  return true;
}

ProbabilisticView IndoorLandmarksProblem::Probabilistic(int k) const {
  const IndoorRecord& r = records_[k];
  ProbabilisticView pv;
  pv.sample_prior = [box = start_](RandomEngine& rng) {
    return std::vector<double>{UniformIn(box[0], rng), UniformIn(box[1], rng), UniformIn(box[2], rng)};
  };
  pv.sample_global = [box = anywhere_](RandomEngine& rng) {
    return std::vector<double>{UniformIn(box[0], rng), UniformIn(box[1], rng), UniformIn(box[2], rng)};
  };
  if (k == 0) {
    pv.sample_motion = [](std::vector<double>&, RandomEngine&) {};
  } else {
    pv.sample_motion = [o = r.odometry](std::vector<double>& s, RandomEngine& rng) {
      const double right = UniformIn(o.right_radius, rng) * UniformIn(o.right_rotation, rng);
      const double left = UniformIn(o.left_radius, rng) * UniformIn(o.left_rotation, rng);
      const double d = (right + left) / 2, turn = (right - left) / UniformIn(o.track, rng);
      s[0] += d * std::cos(s[2] + turn / 2);
      s[1] += d * std::sin(s[2] + turn / 2);
      s[2] += turn;
    };
  }
  pv.log_likelihood = [observations = r.observations, landmarks = landmarks_,
                       sr = params_.range_error,
                       sb = params_.bearing_error](const std::vector<double>& s) {
    double sum = 0;
    for (const PolarObservation& o : observations) {
      const double range = 0.5 * (o.range.lo() + o.range.hi());
      const double bearing = 0.5 * (o.bearing.lo() + o.bearing.hi());
      double best = 0;
      for (const TypedLandmark& l : *landmarks) {
        if (l.type != o.type) continue;
        const double er = (std::hypot(l.x - s[0], l.y - s[1]) - range) / sr;
        const double eb =
            std::remainder(std::atan2(l.y - s[1], l.x - s[0]) - s[2] - bearing, 2 * std::numbers::pi) / sb;
        best = std::max(best, std::exp(-0.5 * (er * er + eb * eb)));
      }
      sum += std::log((1 - kSpuriousFloor) * best + kSpuriousFloor);
    }
    return sum;
  };
  return pv;
}

IndoorMap LoadMap(const IndoorLandmarksParams& p) {
  return ReadIndoorMap(p.map.empty() ? ShippedCorridorMapPath() : p.map);
}

// The rules that tie parameters together.
IndoorLandmarksParams ParseChecked(const std::string& owner, const ParamMap& values) {
  const IndoorLandmarksParams p = ParseParams<IndoorLandmarksParams>(owner, values);
  if (p.path != "random" && p.steps > 46)
    throw ParamError(owner + ".steps = " + std::to_string(p.steps) + ": path " + p.path +
                     " has 46 acquisitions (path=random drives any number)");
  if (!(p.radius_error < p.wheel_radius))
    throw ParamError(owner + ".radius_error = " + FormatDouble(p.radius_error) +
                     ": must be below wheel_radius (" + FormatDouble(p.wheel_radius) + ")");
  if (!(p.track_error < p.track))
    throw ParamError(owner + ".track_error = " + FormatDouble(p.track_error) +
                     ": must be below track (" + FormatDouble(p.track) + ")");
  return p;
}

}  // namespace

ParamMap ResolveIndoorLandmarks(const std::string& owner, const ParamMap& values) {
  const IndoorLandmarksParams p = ParseChecked(owner, values);
  CheckIndoorStart(p, LoadMap(p));
  return ResolveParams<IndoorLandmarksParams>(owner, values);
}

std::unique_ptr<Problem> MakeIndoorLandmarks(const ParamMap& params, std::uint64_t seed) {
  const IndoorLandmarksParams p = ParseChecked("indoor-landmarks", params);
  IndoorMap map = LoadMap(p);
  std::vector<IndoorRecord> records = SimulateIndoorDrive(p, map, seed);
  return std::make_unique<IndoorLandmarksProblem>(p, std::move(map), std::move(records));
}

}  // namespace icp
