// What each car-track step offers: CarTrackProblem::Next builds the window's
// CSP (window.h) and the probabilistic view of the header comment.
#include "problems/car_track/car_track.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/random.h"
#include "problems/car_track/window.h"

namespace icp {

namespace {

constexpr double kPi = std::numbers::pi;

double Uniform(RandomEngine& rng, const Interval& x) { return UniformReal(rng, x.lo(), x.hi()); }

// The central share of x (x itself for share 1).
Interval Central(const Interval& x, double share) {
  if (share == 1 || !x.IsBounded()) return x;
  const double mid = x.Mid(), half = share * x.Width() / 2;
  return Interval(mid - half, mid + half);
}

// The probabilistic view of a step with measurement m (header comment):
// prior, the box of state 0; first, whether this is step 0;
// simulator_noise, whether the model is the simulator's noise (each
// interval's central kSimulatorNoiseShare, with kSimulatorNoiseRoughen) or
// the bounds (the whole intervals, no jitter).
ProbabilisticView CarProbabilisticView(const CarTrackMeasurement& m, const Box& prior, bool first,
                                       bool simulator_noise) {
  const double share = simulator_noise ? kSimulatorNoiseShare : 1.0;
  ProbabilisticView view;
  view.roughen = simulator_noise ? kSimulatorNoiseRoughen : 0.0;
  view.sample_prior = [prior](RandomEngine& rng) {
    if (!prior[0].IsBounded() || !prior[1].IsBounded())
      throw std::invalid_argument(
          "car-track: no GPS fix in the drive to draw the first state from");
    const double x = Uniform(rng, prior[0]);
    const double y = Uniform(rng, prior[1]);
    return std::vector<double>{x, y, Uniform(rng, prior[2])};
  };
  if (first) {
    view.sample_motion = [](std::vector<double>&, RandomEngine&) {};
  } else {
    view.sample_motion = [ds = Central(m.ds, share), dth = Central(m.dth, share)](std::vector<double>& s,
                                                                                  RandomEngine& rng) {
      const double d = Uniform(rng, ds);
      const double turn = Uniform(rng, dth);
      const double heading = s[2] + turn / 2;  // eq. 12
      s[0] += d * std::cos(heading);
      s[1] += d * std::sin(heading);
      s[2] += turn;
    };
  }
  const bool fix = m.x.IsBounded() && m.y.IsBounded();
  const Interval gps_x = Central(m.x, share), gps_y = Central(m.y, share);
  view.log_likelihood = [fix, x = gps_x, y = gps_y](const std::vector<double>& s) {
    if (!fix || (x.Contains(s[0]) && y.Contains(s[1]))) return 0.0;
    return -std::numeric_limits<double>::infinity();
  };
  if (fix)
    view.sample_global = [x = gps_x, y = gps_y](RandomEngine& rng) {
      const double gx = Uniform(rng, x);
      const double gy = Uniform(rng, y);
      return std::vector<double>{gx, gy, UniformReal(rng, -kPi, kPi)};
    };
  return view;
}

}  // namespace

bool CarTrackProblem::Next(Step* step) {
  if (k_ >= num_steps_) return false;
  const int k = k_++;
  *step = Step();
  step->views.step = k;
  step->views.space = CarStateSpace();
  step->views.probabilistic = CarProbabilisticView(measurements_[k], prior_, k == 0, UsesSimulatorNoise(params_));
  if (const CarTrackMeasurement& m = measurements_[k]; m.x.IsBounded() && m.y.IsBounded())
    step->annotations = {{"gps_x_lo", m.x.lo()}, {"gps_x_hi", m.x.hi()},
                         {"gps_y_lo", m.y.lo()}, {"gps_y_hi", m.y.hi()}};
  const CarTrackRecord& newest = records_[k];
  if (newest.has_truth) step->truth = {newest.truth_x, newest.truth_y, newest.truth_theta};
  if (!build_window_) return true;
  const int oldest = std::max(0, k - params_.w);
  std::vector<CarWindowState> states;
  bool truth_known = true;
  for (int j = oldest; j <= k; ++j) {
    const CarTrackMeasurement& m = measurements_[j];
    // The oldest heading is unknown unless it is the drive's first.
    const Interval th =
        j == 0 ? heading0_ : j == oldest ? Interval(-Pi().hi(), Pi().hi()) : Interval();
    states.push_back({m.x, m.y, th, m.ds, m.dth});
    truth_known = truth_known && records_[j].has_truth;
  }
  step->views.csp = BuildCarWindow(oldest, states);
  if (!truth_known) return true;
  // The window's frame: its oldest heading in [-pi, pi] (from step 0, the
  // drive's own frame).
  const double two_pi = 2 * kPi;
  const double shift =
      oldest == 0 ? 0 : std::ceil((records_[oldest].truth_theta - kPi) / two_pi) * two_pi;
  for (int j = oldest; j <= k; ++j) {
    const CarTrackRecord& r = records_[j];
    step->csp_truth.insert(step->csp_truth.end(), {r.truth_x, r.truth_y, r.truth_theta - shift});
  }
  return true;
}

}  // namespace icp
