#include "problems/city_roads/city_roads.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "core/constraint_system.h"
#include "core/random.h"
#include "problems/marina_sonar/marina_map.h"
#include "problems/planar.h"

namespace icp {

void Describe(CityRoadsParams& p, ParamSet& set) {
  set.Add("steps", &p.steps, "number of steps (the 1500 m route takes about 150 at 10 m/s)",
          Range::Closed(1, 100000));
  set.Add("dt", &p.dt, "time step, s", Range::Positive(20));
  set.Add("speed", &p.speed, "mean speed of the car, m/s, varying by ±10 %",
          Range{0.1, 50, false, false});
  set.Add("speed_error", &p.speed_error, "half-width of the speed reading, m/s",
          Range::Positive(10));
  set.Add("compass_error", &p.compass_error, "half-width of the compass reading, rad",
          Range::Positive(1));
  set.Add("start_error", &p.start_error, "half-width of the known start box on x and y, m",
          Range::Positive(300));
  set.Add("w", &p.w, "window length of the CSP view in steps (2w motion constraints)",
          Range::Closed(1, 100000));
  set.Add("roads", &p.roads,
          "the car is on the roads (the image contractor); false: dead reckoning alone");
}

namespace {

// The street centre lines, m, each way.
constexpr double kStreets[] = {25, 75, 125, 175, 225, 275};
constexpr double kRoadHalfWidth = 5;  // m
// The likelihood's fall-off with the distance to a road and its floor.
constexpr double kLikelihoodSigma = 1;  // m
constexpr double kLikelihoodFloor = 0.01;

// x + [-e, e], outward rounded.
Interval Around(double x, double e) { return Interval(x) + Interval(-e, e); }

// The point at arc length s (modulo the route's length) of a closed route.
std::pair<double, double> RoutePoint(const std::vector<std::vector<double>>& route, double s) {
  double length = 0;
  for (std::size_t i = 0; i + 1 < route.size(); ++i)
    length += std::hypot(route[i + 1][0] - route[i][0], route[i + 1][1] - route[i][1]);
  s = std::fmod(s, length);
  for (std::size_t i = 0; i + 1 < route.size(); ++i) {
    const double dx = route[i + 1][0] - route[i][0], dy = route[i + 1][1] - route[i][1];
    const double leg = std::hypot(dx, dy);
    if (s <= leg) return {route[i][0] + dx * s / leg, route[i][1] + dy * s / leg};
    s -= leg;
  }
  return {route.back()[0], route.back()[1]};
}

struct Displacement {
  Interval dx, dy;
};

class CityRoadsProblem : public Problem {
 public:
  CityRoadsProblem(const CityRoadsParams& params, MarinaMap map, std::vector<CityRecord> records)
      : params_(params), map_(std::move(map)), records_(std::move(records)) {
    const CityRecord& first = records_[0];
    start_box_ = Intersect(Box({Around(first.truth_x, params_.start_error),
                                Around(first.truth_y, params_.start_error)}),
                           map_.bounds);
    const Interval dt(params_.dt);
    for (const CityRecord& r : records_) {
      const Interval v = Around(r.speed, params_.speed_error);
      const Interval th = Around(r.heading, params_.compass_error);
      motion_.push_back({dt * v * Cos(th), dt * v * Sin(th)});  // from this step to the next
    }
  }
  std::string_view Name() const override { return "city-roads"; }
  int NumSteps() const override { return params_.steps; }
  bool Next(Step* step) override;

 private:
  CityRoadsParams params_;
  MarinaMap map_;  // the roads are its set pixels
  std::vector<CityRecord> records_;
  std::vector<Displacement> motion_;
  Box start_box_;
  int k_ = 0;
};

bool CityRoadsProblem::Next(Step* step) {
  if (k_ >= params_.steps) return false;
  const int k = k_++;
  *step = Step();
  step->views.step = k;
  step->views.space = PlanarStateSpace();
  const CityRecord& r = records_[k];
  step->truth = {r.truth_x, r.truth_y};

  // The CSP: the motion over the window, the roads beside it.
  const int oldest = std::max(0, k - params_.w);
  CspView view;
  ConstraintSystem& csp = view.csp;
  std::optional<Expr> xp, yp;
  for (int j = oldest; j <= k; ++j) {
    const std::string index = "[" + std::to_string(j) + "]";
    const Box& domain = j == 0 ? start_box_ : map_.bounds;
    Expr xj = csp.AddVariable("x" + index, domain[0]);
    Expr yj = csp.AddVariable("y" + index, domain[1]);
    const int at = static_cast<int>(view.states.size());
    view.states.push_back({j, 0});
    view.states.push_back({j, 1});
    if (params_.roads)
      view.extra_contractors.push_back(std::make_shared<ImageContractor>(map_.image, at, at + 1));
    if (j > oldest) {
      csp.AddConstraint(xj, Relation::kEq, *xp + csp.Constant(motion_[j - 1].dx));
      csp.AddConstraint(yj, Relation::kEq, *yp + csp.Constant(motion_[j - 1].dy));
    }
    xp = xj;
    yp = yj;
    step->csp_truth.insert(step->csp_truth.end(), {records_[j].truth_x, records_[j].truth_y});
  }
  view.newest = k;
  step->views.csp = std::move(view);

  // The measurement set: the roads.
  MeasurementSetView set;
  set.prior = k == 0 ? start_box_ : map_.bounds;
  if (params_.roads) {
    set.measurements.push_back(std::make_shared<ImageContractor>(map_.image));
    set.outliers = {false};
  }
  if (k > 0)
    set.predict = [m = motion_[k - 1]](const Box& previous) {
      if (previous.size() != 2)
        throw std::invalid_argument("city-roads predict: the box must be (x, y)");
      return Box({previous[0] + m.dx, previous[1] + m.dy});
    };
  step->views.measurement_set = std::move(set);

  // The probabilistic view.
  ProbabilisticView pv;
  pv.sample_prior = [box = start_box_](RandomEngine& rng) {
    return std::vector<double>{UniformReal(rng, box[0].lo(), box[0].hi()),
                               UniformReal(rng, box[1].lo(), box[1].hi())};
  };
  if (k == 0) {
    pv.sample_motion = [](std::vector<double>&, RandomEngine&) {};
  } else {
    const CityRecord& before = records_[k - 1];
    pv.sample_motion = [v = before.speed, ve = params_.speed_error, th = before.heading,
                        te = params_.compass_error,
                        dt = params_.dt](std::vector<double>& s, RandomEngine& rng) {
      const double speed = v + UniformReal(rng, -ve, ve), h = th + UniformReal(rng, -te, te);
      s[0] += dt * speed * std::cos(h);
      s[1] += dt * speed * std::sin(h);
    };
  }
  pv.log_likelihood = [map = map_, roads = params_.roads](const std::vector<double>& s) {
    // The robot is in the city: a state off the map is impossible, roads or
    // not (the CSP's domains say the same).
    if (!map.bounds[0].Contains(s[0]) || !map.bounds[1].Contains(s[1]))
      return -std::numeric_limits<double>::infinity();
    if (!roads) return 0.0;
    const double d = WallDistance(map, s[0], s[1]);
    return std::log((1 - kLikelihoodFloor) *
                        std::exp(-d * d / (2 * kLikelihoodSigma * kLikelihoodSigma)) +
                    kLikelihoodFloor);
  };
  step->views.probabilistic = std::move(pv);
  return true;
}

}  // namespace

cv::Mat DrawCityMap() {
  const int side = static_cast<int>(std::lround(kCitySide / kCityPixelSize));
  cv::Mat img(side, side, CV_8UC1, cv::Scalar(0));
  const int half = static_cast<int>(std::lround(kRoadHalfWidth / kCityPixelSize));
  for (const double c : kStreets) {
    const int at = static_cast<int>(std::lround(c / kCityPixelSize));
    // A street along y (columns at - half .. at + half - 1) and one along x
    // (rows counted from the top).
    cv::rectangle(img, cv::Rect(at - half, 0, 2 * half, side), cv::Scalar(255), cv::FILLED);
    cv::rectangle(img, cv::Rect(0, side - at - half, side, 2 * half), cv::Scalar(255), cv::FILLED);
  }
  return img;
}

ImageFrame CityMapFrame() { return ImageFrame{0, 0, kCityPixelSize}; }

std::string ShippedCityMapPath() { return std::string(ICPBENCH_CITY_ROADS_DATA) + "/city.png"; }

std::vector<std::vector<double>> CityRoute() {
  return {{25, 25},   {275, 25},  {275, 125}, {125, 125}, {125, 175}, {275, 175},
          {275, 275}, {225, 275}, {225, 225}, {175, 225}, {175, 275}, {25, 275},
          {25, 175},  {75, 175},  {75, 75},   {25, 75},   {25, 25}};
}

std::vector<CityRecord> SimulateCityRoads(const CityRoadsParams& p, std::uint64_t seed) {
  RandomEngine rng(seed);
  const std::vector<std::vector<double>> route = CityRoute();
  std::vector<CityRecord> records(p.steps);
  double s = 0;
  auto [x, y] = RoutePoint(route, s);
  for (int k = 0; k < p.steps; ++k) {
    CityRecord& r = records[k];
    r.truth_x = x;
    r.truth_y = y;
    // The next position along the route; the car drives the chord to it.
    s += p.speed * UniformReal(rng, 0.9, 1.1) * p.dt;
    const auto [nx, ny] = RoutePoint(route, s);
    const double chord = std::hypot(nx - x, ny - y);
    r.speed = chord / p.dt + UniformReal(rng, -0.9, 0.9) * p.speed_error;
    r.heading = std::atan2(ny - y, nx - x) + UniformReal(rng, -0.9, 0.9) * p.compass_error;
    // The next truth is where the true speed and heading lead (the chord's
    // end up to rounding), so the motion model holds exactly.
    x = nx;
    y = ny;
  }
  return records;
}

ParamMap ResolveCityRoads(const std::string& owner, const ParamMap& values) {
  ParseParams<CityRoadsParams>(owner, values);
  CheckMarinaMap(ShippedCityMapPath());
  return ResolveParams<CityRoadsParams>(owner, values);
}

std::unique_ptr<Problem> MakeCityRoads(const ParamMap& params, std::uint64_t seed) {
  const CityRoadsParams p = ParseParams<CityRoadsParams>("city-roads", params);
  return std::make_unique<CityRoadsProblem>(p, LoadMarinaMap(ShippedCityMapPath()),
                                            SimulateCityRoads(p, seed));
}

}  // namespace icp
