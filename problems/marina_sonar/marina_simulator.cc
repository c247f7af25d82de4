// The marina-sonar simulator: the route round the shipped marina and the
// simulated drive along it, its DVL, compass and sonar readings.
#include "problems/marina_sonar/marina_sonar.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "core/random.h"

namespace icp {

namespace {

constexpr double kPi = std::numbers::pi;

// Turn rate limit of the simulated robot, rad/s, raised at speeds above
// 0.5 m/s so that it turns within kMinTurnRadius metres at any speed: a
// wider turn overshoots the waypoints and circles them through the quays.
constexpr double kMaxTurnRate = 0.2;
constexpr double kMinTurnRadius = 2.5;
// The distance at which it heads for the next waypoint, m, raised to 1.2
// steps when a step is longer (a step may not jump over the circle).
constexpr double kWaypointRadius = 3;
constexpr double kStepsToArrive = 1.2;
// Rays across the beam whose shortest hit is the echo.
constexpr int kBeamRays = 5;

class Simulator {
 public:
  Simulator(const MarinaSonarParams& p, const MarinaMap& map, std::uint64_t seed)
      : p_(p), map_(map), rng_(seed) {}

  std::vector<MarinaRecord> Run() {
    const std::vector<std::vector<double>> route = MarinaRoute();
    double x = route[0][0], y = route[0][1];
    std::size_t target = 1;
    double th = std::atan2(route[1][1] - y, route[1][0] - x);
    const double speed_phase = UniformReal(rng_, 0, 2 * kPi);
    const double drift_phase = UniformReal(rng_, 0, 2 * kPi);
    // Sensor biases for the whole drive (a DVL misalignment, a magnetic
    // deviation), within 0.6 of each bound; the noise adds up to 0.3 more.
    // Dead reckoning drifts by the biases, as in the thesis' Fig. 6.7.
    const double bias_u = 0.6 * p_.dvl_error * UniformReal(rng_, -1, 1);
    const double bias_v = 0.6 * p_.dvl_error * UniformReal(rng_, -1, 1);
    const double bias_th = 0.6 * p_.compass_error * UniformReal(rng_, -1, 1);
    std::vector<MarinaRecord> records;
    // At the default speed and dt both are their constants, so the default
    // drive is what it has always been.
    const double arrival = std::max(kWaypointRadius, kStepsToArrive * p_.speed * p_.dt);
    const double max_turn = p_.dt * std::max(kMaxTurnRate, p_.speed / kMinTurnRadius);
    for (int k = 0; k < p_.steps; ++k) {
      while (target < route.size() &&
             std::hypot(route[target][0] - x, route[target][1] - y) < arrival)
        ++target;
      if (target == route.size()) break;  // the route is driven
      const double desired = std::atan2(route[target][1] - y, route[target][0] - x);
      const double turn = std::remainder(desired - th, 2 * kPi);
      th += std::clamp(turn, -max_turn, max_turn);
      const double t = k * p_.dt;
      // True body-frame velocity: the speed varies by ±10 %, a current
      // pushes sideways by up to 5 % of it.
      const double u = p_.speed * (1 + 0.1 * std::sin(2 * kPi * t / 120 + speed_phase));
      const double v = 0.05 * p_.speed * std::sin(2 * kPi * t / 90 + drift_phase);
      MarinaRecord r;
      r.t = t;
      r.dvl_u = u + bias_u + Noise(p_.dvl_error, 0.3);
      r.dvl_v = v + bias_v + Noise(p_.dvl_error, 0.3);
      r.dvl_error = p_.dvl_error;
      r.heading = th + bias_th + Noise(p_.compass_error, 0.3);
      r.heading_error = p_.compass_error;
      r.has_truth = true;
      r.truth_x = x;
      r.truth_y = y;
      const int n = p_.returns_per_step;
      for (int j = 0; j < n; ++j) {
        const double alpha =
            std::remainder(static_cast<double>(static_cast<std::int64_t>(k) * n + j) * p_.beam_step,
                           2 * kPi);
        if (std::optional<MarinaReturn> ret = Return(x, y, th, alpha)) r.returns.push_back(*ret);
      }
      records.push_back(std::move(r));
      x += p_.dt * (u * std::cos(th) - v * std::sin(th));
      y += p_.dt * (u * std::sin(th) + v * std::cos(th));
    }
    return records;
  }

 private:
  // Uniform within share (0.9 by default) of bound, so that the truth is
  // strictly inside every interval and rounding cannot push it out.
  double Noise(double bound, double share = 0.9) {
    return share * bound * UniformReal(rng_, -1, 1);
  }

  // The return of the beam at angle alpha on the robot at (x, y), heading th.
  std::optional<MarinaReturn> Return(double x, double y, double th, double alpha) {
    const double e = p_.range_error;
    const double limit = p_.max_range + 3 * e;
    double d = kInf, hit_angle = 0;
    for (int i = 0; i < kBeamRays; ++i) {
      const double offset = (-0.9 + 1.8 * i / (kBeamRays - 1)) * p_.beam_half_width;
      const double a = th + alpha + offset;
      const std::optional<double> t = CastRay(*map_.image, x, y, a, limit);
      if (t && *t < d) {
        d = *t;
        hit_angle = a;
      }
    }
    // Every draw is made whatever the case, so that a change of case does
    // not shift the later draws.
    const bool draw_outlier = UniformReal(rng_, 0, 1) < p_.outlier_rate;
    bool echo = UniformInt(rng_, 0, 1) == 0;
    const double noise = Noise(e);
    const double share = UniformReal(rng_, 0, 1);
    MarinaReturn r;
    r.beam_angle = alpha;
    r.range_error = e;
    r.beam_half_width = p_.beam_half_width;
    r.has_outlier_flag = true;
    if (d <= limit) {
      if (draw_outlier) {
        // A multiple echo at twice the wall distance, received within range;
        // a fish short of the wall. Both miss the wall distance d by more
        // than e.
        const bool echo_ok = d > 3 * e && 2 * d + 0.9 * e <= p_.max_range;
        const bool fish_ok = d > 4 * e;
        if (echo && !echo_ok) echo = false;
        if (!echo && !fish_ok) echo = echo_ok;
        if (echo && echo_ok) {
          r.range = 2 * d + noise;
          r.outlier = true;
          return r;
        }
        if (fish_ok) {
          r.range = e + share * (d - 4 * e);  // in [e, d - 3e]
          r.outlier = true;
          return r;
        }
      }
      r.range = std::max(0.0, d + noise);
      r.has_hit = true;
      r.hit_x = x + d * std::cos(hit_angle);
      r.hit_y = y + d * std::sin(hit_angle);
      return r;
    }
    // No wall within max_range + 3e along the beam.
    if (draw_outlier) {
      r.range = e + share * (p_.max_range - 2 * e);  // a fish, in [e, max_range - e]
      r.outlier = true;
      return r;
    }
    if (p_.out_of_range == "drop") return std::nullopt;
    r.range = p_.max_range;
    r.outlier = true;
    return r;
  }

  const MarinaSonarParams& p_;
  const MarinaMap& map_;
  RandomEngine rng_;
};

}  // namespace

std::vector<std::vector<double>> MarinaRoute() {
  // Clockwise round the basin from its east side: south, west along y = 100,
  // north along x = 80, east along y = 180 (25 m clear of the pontoons, the
  // jetty and the island), then out through the canal mouth and 190 m along
  // the canal's axis y = 140.
  return {{190, 140}, {195, 105}, {85, 100}, {80, 180}, {190, 180},
          {205, 140}, {240, 140}, {430, 140}};
}

std::vector<MarinaRecord> SimulateMarinaSonar(const MarinaSonarParams& params, const MarinaMap& map,
                                              std::uint64_t seed) {
  return Simulator(params, map, seed).Run();
}

}  // namespace icp
