#include "problems/chain/chain.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/random.h"
#include "problems/car_track/window.h"

namespace icp {

void Describe(ChainParams& p, ParamSet& set) {
  set.Add("w", &p.w, "window length in steps (3w constraints)", Range::Closed(1, 100000));
  set.Add("step_length", &p.step_length, "mean distance per step, m", Range::Positive(1e6));
  set.Add("odometry_error", &p.odometry_error, "odometry half-width per step, m",
          Range::Positive(1e6));
  set.Add("gyro_error", &p.gyro_error, "gyro half-width per step, rad", Range::Positive(10));
  set.Add("gps_error", &p.gps_error, "GPS half-width on x and y, m", Range::Positive(1e9));
  set.Add("max_turn", &p.max_turn, "largest true heading change per step, rad",
          Range::Closed(0, 1));
  set.Add("heading_known", &p.heading_known, "start heading known to ±0.1 rad (else [-pi, pi])");
}

namespace {
// A measurement interval of half-width e around a noisy reading of truth;
// the noise stays below 0.9 e so the truth is strictly inside.
Interval Measure(double truth, double e, RandomEngine& rng) {
  double reading = truth + UniformReal(rng, -0.9 * e, 0.9 * e);
  return Interval(reading - e, reading + e);
}
}  // namespace

Step MakeChainStep(const ChainParams& p, std::uint64_t seed) {
  RandomEngine rng(seed);
  auto unit = [&] { return UniformReal(rng, -1, 1); };
  const double pi = std::numbers::pi;
  Step step;
  std::vector<CarWindowState> states;
  double x = 0, y = 0, th = pi * unit() * 0.999;
  const Interval th0 =
      p.heading_known ? Interval(th - 0.1, th + 0.1) : Interval(-Pi().hi(), Pi().hi());
  states.push_back({Measure(x, p.gps_error, rng), Measure(y, p.gps_error, rng), th0, 0, 0});
  step.csp_truth = {x, y, th};
  for (int k = 1; k <= p.w; ++k) {
    const double ds = p.step_length * (1 + 0.2 * unit());
    const double dth = p.max_turn * unit();
    const double heading = th + dth / 2;
    x += ds * std::cos(heading);
    y += ds * std::sin(heading);
    th += dth;
    CarWindowState s;
    s.x = Measure(x, p.gps_error, rng);
    s.y = Measure(y, p.gps_error, rng);
    s.ds = Measure(ds, p.odometry_error, rng);
    s.dth = Measure(dth, p.gyro_error, rng);
    states.push_back(s);
    step.csp_truth.insert(step.csp_truth.end(), {x, y, th});
  }
  step.views.space = CarStateSpace();
  step.views.csp = BuildCarWindow(0, states);
  step.truth = {x, y, th};
  return step;
}

std::unique_ptr<Problem> MakeChain(const ParamMap& params, std::uint64_t seed) {
  return std::make_unique<SingleStepProblem>(
      "chain", [p = ParseParams<ChainParams>("chain", params), seed] { return MakeChainStep(p, seed); });
}

}  // namespace icp
