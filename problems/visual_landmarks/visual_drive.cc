#include "problems/visual_landmarks/visual_drive.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/random.h"

namespace icp {

namespace {

constexpr double kPi = std::numbers::pi;

// The loop: 60 m straight, a left half circle of radius 10 m, 60 m
// straight, a left half circle; the heading after arc length s.
double LoopHeading(double s) {
  constexpr double kStraight = 60, kRadius = 10;
  const double bend = kPi * kRadius;
  const double lap = 2 * (kStraight + bend);
  const double laps = std::floor(s / lap);
  double u = s - laps * lap;
  double heading = laps * 2 * kPi;
  for (int half = 0; half < 2 && u > 0; ++half) {
    u -= kStraight;
    if (u <= 0) break;
    heading += std::min(u, bend) / kRadius;
    u -= bend;
  }
  return heading;
}

// The loop's point and heading at arc length s (the analytic curve; the
// simulated drive follows eq. 11's chords of it).
std::array<double, 3> LoopPoint(double s) {
  constexpr double kStraight = 60, kRadius = 10;
  const double bend = kPi * kRadius;
  double u = std::fmod(s, 2 * (kStraight + bend));
  if (u < kStraight) return {u, 0, 0};
  u -= kStraight;
  if (u < bend)
    return {kStraight + kRadius * std::sin(u / kRadius), kRadius - kRadius * std::cos(u / kRadius),
            u / kRadius};
  u -= bend;
  if (u < kStraight) return {kStraight - u, 2 * kRadius, kPi};
  u -= kStraight;
  return {-kRadius * std::sin(u / kRadius), kRadius + kRadius * std::cos(u / kRadius),
          kPi + u / kRadius};
}

// The landmarks: the straight route's five first, the loop's drawn along
// it; more than five on the straight route are drawn along its first 40 m.
// From their own engine (layout_seed), so every drive of a route, whatever
// its seed, length or speed, sees the same map.
std::vector<std::array<double, 3>> LandmarkLayout(const VisualDriveParams& p) {
  std::vector<std::array<double, 3>> out;
  if (p.route == "straight")
    out = {{12, 3, 2}, {14, -2.5, 1}, {16, 1.5, 3}, {18, -4, 2.5}, {30, 0.2, 1.6}};
  out.resize(std::min<std::size_t>(out.size(), p.landmarks));
  RandomEngine rng(p.layout_seed);
  constexpr double kLoopLength = 2 * (60 + kPi * 10);
  while (static_cast<int>(out.size()) < p.landmarks) {
    const std::array<double, 3> at = p.route == "loop"
                                         ? LoopPoint(UniformReal(rng, 0, kLoopLength))
                                         : std::array<double, 3>{UniformReal(rng, 5, 40), 0, 0};
    const double side = UniformReal(rng, 0, 1) < 0.5 ? -1 : 1;
    const double offset = side * UniformReal(rng, 3, 8);
    out.push_back({at[0] - offset * std::sin(at[2]), at[1] + offset * std::cos(at[2]),
                   UniformReal(rng, 0.5, 4)});
  }
  return out;
}

// x in value +- 0.9 half_width, drawn uniformly, inside value +- half_width.
Interval Measure(RandomEngine& rng, double value, double half_width) {
  const double reading = value + UniformReal(rng, -0.9, 0.9) * half_width;
  return Interval(reading - half_width, reading + half_width);
}

}  // namespace

VisualDrive SimulateVisualDrive(const VisualDriveParams& p, std::uint64_t seed) {
  if (p.route != "straight" && p.route != "loop")
    throw std::invalid_argument("visual drive: route must be straight or loop, not '" + p.route + "'");
  if (p.steps < 1) throw std::invalid_argument("visual drive: steps must be at least 1");
  if (p.landmarks < 1) throw std::invalid_argument("visual drive: landmarks must be at least 1");
  RandomEngine rng(seed);
  VisualDrive drive;
  const double ds = p.speed * p.dt;
  std::array<double, 3> pose{0, 0, 0};
  for (int k = 0; k < p.steps; ++k) {
    double dtheta = 0;
    if (k > 0) {
      if (p.route == "loop") dtheta = LoopHeading(k * ds) - LoopHeading((k - 1) * ds);
      pose = {pose[0] + ds * std::cos(pose[2] + dtheta / 2),
              pose[1] + ds * std::sin(pose[2] + dtheta / 2), pose[2] + dtheta};
    }
    drive.poses.push_back(pose);
    VisualDriveStep step;
    step.ds = k > 0 ? Measure(rng, ds, p.odometry_error) : Interval(0.0);
    step.dtheta = k > 0 ? Measure(rng, dtheta, p.gyro_error) : Interval(0.0);
    step.gps = Box{Measure(rng, pose[0], p.gps_error), Measure(rng, pose[1], p.gps_error)};
    drive.steps.push_back(step);
  }
  drive.landmarks = LandmarkLayout(p);
  for (int k = 0; k < p.steps; ++k) {
    for (int n = 0; n < static_cast<int>(drive.landmarks.size()); ++n) {
      const auto pixel = Project(drive.poses[k], drive.landmarks[n], p.camera);
      if (!pixel) continue;
      drive.steps[k].sightings.push_back(
          {n, Measure(rng, pixel->u, p.pixel_error), Measure(rng, pixel->v, p.pixel_error)});
    }
  }
  return drive;
}

}  // namespace icp
