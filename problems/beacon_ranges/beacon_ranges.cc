#include "problems/beacon_ranges/beacon_ranges.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/constraint_system.h"
#include "core/random.h"
#include "problems/log_file.h"
#include "problems/planar.h"

namespace icp {

void Describe(BeaconRangesParams& p, ParamSet& set) {
  set.Add("scenario", &p.scenario, "the fixed scene of Figs. 5.5-5.7, one random step, or a drive",
          {"two-robots", "random", "moving"});
  set.Add("beacons", &p.beacons, "number of beacons (random, moving)", Range::Closed(1, 100000));
  set.Add("outliers", &p.outliers, "outlier ranges per step, < beacons (random, moving)",
          Range::Closed(0, 100000));
  set.Add("range_error", &p.range_error, "half-width of each range interval (random, moving)",
          Range{0, 0.5, true, true});
  set.Add("radius", &p.radius, "search box [-radius, radius]^2 (random, moving)",
          Range::Closed(2, 1e6));
  set.Add("steps", &p.steps, "number of time steps (moving)", Range::Closed(1, 1000000));
  set.Add("odometry_error", &p.odometry_error,
          "half-width of the odometry displacement on x and y (moving)", Range::Positive(1e6));
}

BeaconRangesParams ParseBeaconRanges(const std::string& owner, const ParamMap& values) {
  auto p = ParseParams<BeaconRangesParams>(owner, values);
  if (p.outliers >= p.beacons)
    throw ParamError(owner + ".outliers = " + std::to_string(p.outliers) +
                     ": must be < beacons (" + std::to_string(p.beacons) + ")");
  return p;
}

ParamMap ResolveBeaconRanges(const std::string& owner, const ParamMap& values) {
  if (ParseBeaconRanges(owner, values).scenario == "two-robots")
    ReadBeaconScene(TwoRobotsScenePath());
  return ResolveParams<BeaconRangesParams>(owner, values);
}

Interval SquaredRangeBounds(double range, double error) {
  const Interval d(range), e(error);
  const Interval lo = Sqr(Max(Interval(0), d - e));
  return Interval(lo.lo(), Sqr(d + e).hi());
}

std::string TwoRobotsScenePath() {
  return std::string(ICPBENCH_BEACON_RANGES_DATA) + "/two_robots.csv";
}

namespace {
std::vector<std::string> SplitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string f;
  while (std::getline(in, f, ',')) {
    const auto b = f.find_first_not_of(" \t\r");
    const auto e = f.find_last_not_of(" \t\r");
    fields.push_back(b == std::string::npos ? "" : f.substr(b, e - b + 1));
  }
  return fields;
}
}  // namespace

BeaconScene ReadBeaconScene(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(path + ": cannot open the beacon scene");
  return ReadBeaconScene(in, path);
}

BeaconScene ReadBeaconScene(std::istream& in, const std::string& path) {
  BeaconScene scene;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    if (++number == 1) StripByteOrderMark(line);
    const std::string where = path + ":" + std::to_string(number) + ": ";
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::vector<std::string> f = SplitFields(line);
    auto num = [&](std::size_t i) {
      double v = 0;
      const auto [end, ec] = std::from_chars(f[i].data(), f[i].data() + f[i].size(), v);
      if (f[i].empty() || ec != std::errc() || end != f[i].data() + f[i].size() || !std::isfinite(v))
        throw std::invalid_argument(where + "field " + std::to_string(i + 1) + ": '" +
                                    QuoteForMessage(f[i]) + "' is not a finite number");
      return v;
    };
    auto expect = [&](std::size_t n) {
      if (f.size() != n)
        throw std::invalid_argument(where + "'" + f[0] + "' takes " + std::to_string(n - 1) +
                                    " fields, not " + std::to_string(f.size() - 1));
    };
    if (f[0] == "box") {
      expect(5);
      scene.box = Box({Interval(num(1), num(2)), Interval(num(3), num(4))});
      if (scene.box.IsEmpty()) throw std::invalid_argument(where + "empty box");
    } else if (f[0] == "truth") {
      expect(3);
      scene.truth = {num(1), num(2)};
    } else if (f[0] == "range") {
      expect(7);
      RangeMeasurement r;
      const double source = num(1), outlier = num(6);
      if (source != std::floor(source) || source < 0 || source > 1000)
        throw std::invalid_argument(where + "source must be an integer in [0, 1000]");
      if (outlier != 0 && outlier != 1) throw std::invalid_argument(where + "outlier must be 0 or 1");
      r.source = static_cast<int>(source);
      r.beacon_x = num(2);
      r.beacon_y = num(3);
      r.range = num(4);
      r.error = num(5);
      r.outlier = outlier == 1;
      if (r.range < 0 || r.error <= 0)
        throw std::invalid_argument(where + "range must be >= 0 and error > 0");
      scene.ranges.push_back(r);
    } else {
      throw std::invalid_argument(where + "unknown row kind '" + QuoteForMessage(f[0]) +
                                  "' (box, truth, range)");
    }
  }
  if (scene.box.size() != 2 || scene.truth.size() != 2 || scene.ranges.empty())
    throw std::invalid_argument(path + ": a scene needs a box, a truth and at least one range");
  if (!scene.box.Contains(scene.truth))
    throw std::invalid_argument(path + ": the truth lies outside the box");
  return scene;
}

double OutlierShare(const BeaconRangesParams& p) {
  return std::clamp(static_cast<double>(p.outliers) / p.beacons, kMinOutlierShare, kMaxOutlierShare);
}

double RangeLogLikelihood(const std::vector<RangeMeasurement>& ranges, const Box& box,
                          double outlier_share, const std::vector<double>& state) {
  if (state.size() != 2 || !box.Contains(state)) return -std::numeric_limits<double>::infinity();
  const double floor = outlier_share / std::hypot(box[0].Width(), box[1].Width());
  const double inlier = (1 - outlier_share) / std::sqrt(2 * std::numbers::pi);
  double sum = 0;
  for (const RangeMeasurement& r : ranges) {
    const double z = (std::hypot(state[0] - r.beacon_x, state[1] - r.beacon_y) - r.range) / r.error;
    sum += std::log(inlier / r.error * std::exp(-z * z / 2) + floor);
  }
  return sum;
}

namespace {
std::vector<double> UniformIn(const Box& box, RandomEngine& rng) {
  const double x = UniformReal(rng, box[0].lo(), box[0].hi());
  return {x, UniformReal(rng, box[1].lo(), box[1].hi())};
}

// The probabilistic view of one step's ranges (the header): the search box
// as prior and global prior, no motion, the mixture likelihood.
ProbabilisticView RangeProbabilisticView(const Box& box, const std::vector<RangeMeasurement>& ranges,
                                         double outlier_share) {
  ProbabilisticView view;
  view.sample_prior = [box](RandomEngine& rng) { return UniformIn(box, rng); };
  view.sample_global = view.sample_prior;
  view.sample_motion = [](std::vector<double>&, RandomEngine&) {};
  view.log_likelihood = [box, ranges, outlier_share](const std::vector<double>& state) {
    return RangeLogLikelihood(ranges, box, outlier_share, state);
  };
  return view;
}

Step RangeStep(int time, const Box& box, const std::vector<double>& truth,
               const std::vector<RangeMeasurement>& ranges, double outlier_share) {
  ConstraintSystem csp;
  Expr x = csp.AddVariable("x", box[0]);
  Expr y = csp.AddVariable("y", box[1]);
  std::vector<bool> outliers;
  std::vector<int> sources;
  bool several_sources = false;
  for (const RangeMeasurement& r : ranges) {
    csp.AddConstraint(Sqr(x - r.beacon_x) + Sqr(y - r.beacon_y),
                      SquaredRangeBounds(r.range, r.error));
    outliers.push_back(r.outlier);
    sources.push_back(r.source);
    several_sources = several_sources || r.source != 0;
  }
  if (!several_sources) sources.clear();
  Step step = MakePlanarStep(time, csp, truth, std::move(outliers), std::move(sources));
  step.views.probabilistic = RangeProbabilisticView(box, ranges, outlier_share);
  return step;
}

// A reading of the distance from p to beacon b: within ±e/2 of the truth
// for an inlier; wrong by s in [1, radius/2] for an outlier, away from zero
// when a shorter range would be negative.
RangeMeasurement Measure(const std::vector<double>& p, const std::vector<double>& b,
                         bool outlier, const BeaconRangesParams& params, RandomEngine& rng) {
  RangeMeasurement r;
  r.beacon_x = b[0];
  r.beacon_y = b[1];
  r.error = params.range_error;
  r.outlier = outlier;
  const double distance = std::hypot(p[0] - b[0], p[1] - b[1]);
  if (outlier) {
    const double s = UniformReal(rng, 1, params.radius / 2);
    const bool shorter = UniformInt(rng, 0, 1) == 0 && distance - s >= 0;
    r.range = shorter ? distance - s : distance + s;
  } else {
    r.range = std::max(0.0, distance + UniformReal(rng, -r.error / 2, r.error / 2));
  }
  return r;
}

std::vector<double> UniformPoint(double half_width, RandomEngine& rng) {
  return {UniformReal(rng, -half_width, half_width), UniformReal(rng, -half_width, half_width)};
}

Box SearchBox(double radius) { return Box({Interval(-radius, radius), Interval(-radius, radius)}); }

// random (one step) and moving (a drive along a circle) share the beacons
// and the measurement model.
class SimulatedProblem : public Problem {
 public:
  SimulatedProblem(const BeaconRangesParams& params, std::uint64_t seed)
      : params_(params), rng_(seed), moving_(params.scenario == "moving") {
    for (int i = 0; i < params_.beacons; ++i) beacons_.push_back(UniformPoint(params_.radius, rng_));
    start_angle_ = UniformReal(rng_, 0, 2 * std::numbers::pi);
  }
  std::string_view Name() const override { return "beacon-ranges"; }
  int NumSteps() const override { return moving_ ? params_.steps : 1; }
  bool Next(Step* step) override {
    if (time_ >= NumSteps()) return false;
    const std::vector<double> truth = moving_ ? OnCircle(time_) : UniformPoint(params_.radius / 2, rng_);
    const std::vector<bool> outliers = DrawOutliers(params_.beacons, params_.outliers, rng_);
    std::vector<RangeMeasurement> ranges;
    for (int i = 0; i < params_.beacons; ++i)
      ranges.push_back(Measure(truth, beacons_[i], outliers[i], params_, rng_));
    *step = RangeStep(time_, SearchBox(params_.radius), truth, ranges, OutlierShare(params_));
    if (moving_ && time_ > 0) {
      const Box move = Odometry(truth);
      step->views.measurement_set->predict = [move](const Box& previous) {
        if (previous.size() != 2)
          throw std::invalid_argument("beacon-ranges predict: the box must be (x, y)");
        return Box({previous[0] + move[0], previous[1] + move[1]});
      };
      step->views.probabilistic->sample_motion = [move](std::vector<double>& s, RandomEngine& rng) {
        const double dx = UniformReal(rng, move[0].lo(), move[0].hi());
        s[0] += dx;
        s[1] += UniformReal(rng, move[1].lo(), move[1].hi());
      };
    }
    previous_ = truth;
    ++time_;
    return true;
  }

 private:
  // Speed 1 per step on a circle of radius radius/2 about the origin.
  std::vector<double> OnCircle(int t) const {
    const double rc = params_.radius / 2;
    const double angle = start_angle_ + t / rc;
    return {rc * std::cos(angle), rc * std::sin(angle)};
  }

  // The motion from previous_ to truth: the odometry reads the true
  // displacement with noise within ±odometry_error/2, and bounds it by the
  // reading ± odometry_error (the displacement box returned), so the true
  // position is always inside predict(a box holding the previous one).
  Box Odometry(const std::vector<double>& truth) {
    const double e = params_.odometry_error;
    Box move;
    for (int c = 0; c < 2; ++c) {
      const double reading = truth[c] - previous_[c] + UniformReal(rng_, -e / 2, e / 2);
      move.push_back(Interval(reading) + Interval(-e, e));
    }
    return move;
  }

  BeaconRangesParams params_;
  RandomEngine rng_;
  bool moving_;
  std::vector<std::vector<double>> beacons_;
  double start_angle_ = 0;
  int time_ = 0;
  std::vector<double> previous_;
};
}  // namespace

std::unique_ptr<Problem> MakeBeaconRanges(const ParamMap& params, std::uint64_t seed) {
  const BeaconRangesParams p = ParseBeaconRanges("beacon-ranges", params);
  if (p.scenario == "two-robots")
    return std::make_unique<SingleStepProblem>(
        "beacon-ranges", [scene = ReadBeaconScene(TwoRobotsScenePath()), share = OutlierShare(p)] {
          return RangeStep(0, scene.box, scene.truth, scene.ranges, share);
        });
  return std::make_unique<SimulatedProblem>(p, seed);
}

}  // namespace icp
