#include "problems/chain/chain.h"

#include <cmath>
#include <numbers>
#include <string>

#include "core/random.h"

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
  ConstraintSystem& csp = step.csp;
  double x = 0, y = 0, th = pi * unit() * 0.999;
  auto add_state = [&](int k, double xt, double yt, double tht, const Interval& th_domain) {
    const std::string i = "[" + std::to_string(k) + "]";
    csp.AddVariable("x" + i, Measure(xt, p.gps_error, rng));
    csp.AddVariable("y" + i, Measure(yt, p.gps_error, rng));
    csp.AddVariable("th" + i, th_domain);
    step.truth.insert(step.truth.end(), {xt, yt, tht});
  };
  add_state(0, x, y, th,
            p.heading_known ? Interval(th - 0.1, th + 0.1) : Interval(-Pi().hi(), Pi().hi()));
  for (int k = 1; k <= p.w; ++k) {
    const double ds = p.step_length * (1 + 0.2 * unit());
    const double dth = p.max_turn * unit();
    const double heading = th + dth / 2;
    x += ds * std::cos(heading);
    y += ds * std::sin(heading);
    th += dth;
    add_state(k, x, y, th, Interval());
    Expr ds_m = csp.Constant(Measure(ds, p.odometry_error, rng));
    Expr dth_m = csp.Constant(Measure(dth, p.gyro_error, rng));
    const int b = 3 * (k - 1);  // previous state's first variable
    Expr xp = csp.Var(b), yp = csp.Var(b + 1), thp = csp.Var(b + 2);
    Expr xk = csp.Var(b + 3), yk = csp.Var(b + 4), thk = csp.Var(b + 5);
    Expr mid_heading = thp + dth_m / 2.0;
    csp.AddConstraint(xk, Relation::kEq, xp + ds_m * Cos(mid_heading));
    csp.AddConstraint(yk, Relation::kEq, yp + ds_m * Sin(mid_heading));
    csp.AddConstraint(thk, Relation::kEq, thp + dth_m);
  }
  const int last = 3 * p.w;
  step.reported = {{"x", last}, {"y", last + 1}, {"theta", last + 2}};
  step.x = 0;
  step.y = 1;
  return step;
}

namespace {
class ChainProblem : public Problem {
 public:
  ChainProblem(const ChainParams& params, std::uint64_t seed) : params_(params), seed_(seed) {}
  std::string_view Name() const override { return "chain"; }
  int NumSteps() const override { return 1; }
  bool Next(const Box*, Step* step) override {
    if (done_) return false;
    done_ = true;
    *step = MakeChainStep(params_, seed_);
    return true;
  }

 private:
  ChainParams params_;
  std::uint64_t seed_;
  bool done_ = false;
};
}  // namespace

std::unique_ptr<Problem> MakeChain(const ParamMap& params, std::uint64_t seed) {
  return std::make_unique<ChainProblem>(ParseParams<ChainParams>("chain", params), seed);
}

}  // namespace icp
