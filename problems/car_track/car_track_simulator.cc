// The car-track simulator: the closed track as a curvature profile and the
// simulated drive over it (SimulateCarTrack), truth and sensor readings.
#include "problems/car_track/car_track.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "core/random.h"

namespace icp {

namespace {

constexpr double kPi = std::numbers::pi;
// The track as a curvature profile along the arc length: straights (angle 0)
// and bends whose curvature rises and falls smoothly (2 sin^2 profile, so the
// heading changes by `angle` over `length` metres with no curvature jump).
// Four left corners and an S-bend on each long side; 5560 m, one lap at
// 13.9 m/s and 5 Hz in 2000 steps. It closes exactly in continuous geometry.
struct Segment {
  double length;  // m
  double angle;   // heading change over the segment, rad
};
constexpr Segment kTrack[] = {
    {440, 0}, {200, 0.35}, {200, -0.35}, {440, 0}, {400, kPi / 2}, {700, 0}, {400, kPi / 2},
    {440, 0}, {200, 0.35}, {200, -0.35}, {440, 0}, {400, kPi / 2}, {700, 0}, {400, kPi / 2},
};

double TrackLength() {
  double total = 0;
  for (const Segment& s : kTrack) total += s.length;
  return total;
}

// Heading change from the start of the track to arc length s >= 0.
double TrackHeading(double s) {
  static const double kLength = TrackLength();
  const double laps = std::floor(s / kLength);
  double u = s - laps * kLength;
  double heading = laps * 2 * kPi;
  for (const Segment& seg : kTrack) {
    if (u >= seg.length) {
      heading += seg.angle;
      u -= seg.length;
      continue;
    }
    heading += seg.angle * (u / seg.length - std::sin(2 * kPi * u / seg.length) / (2 * kPi));
    break;
  }
  return heading;
}

}  // namespace

std::vector<CarTrackRecord> SimulateCarTrack(const CarTrackParams& p, std::uint64_t seed) {
  RandomEngine rng(seed);
  auto unit = [&] { return UniformReal(rng, -1, 1); };
  // Bounded noise: at most 0.9 of each bound, so the truth stays strictly
  // inside every measurement interval and rounding cannot push it out.
  auto noise = [&](double bound) { return kSimulatorNoiseShare * bound * unit(); };

  const double theta0 = 0.999 * kPi * unit();
  const double speed_phase = kPi * unit();
  const double r_left = p.wheel_radius + noise(p.radius_error);
  const double r_right = p.wheel_radius + noise(p.radius_error);
  // Cumulative wheel rotation in ticks; the encoders read its floor.
  double rot_left = UniformReal(rng, 0, 1), rot_right = UniformReal(rng, 0, 1);

  std::vector<CarTrackRecord> records;
  records.reserve(p.steps);
  double x = 0, y = 0, th = theta0, s = 0;
  for (int k = 0; k < p.steps; ++k) {
    double gyro = 0;
    if (k > 0) {
      // The true motion (ds, dth) and the truth by eq. 12 exactly.
      const double v = p.speed * (1 + 0.05 * std::sin(2 * kPi * k / (60 * p.rate) + speed_phase));
      const double ds = v / p.rate;
      const double dth = TrackHeading(s + ds) - TrackHeading(s);
      s += ds;
      const double heading = th + dth / 2;
      x += ds * std::cos(heading);
      y += ds * std::sin(heading);
      th += dth;
      // Each rear wheel travels ds -+ (track_width / 2) dth, so their mean is
      // ds: eq. 13 holds exactly for the true radii and tick counts.
      const double d_left = ds - p.track_width / 2 * dth;
      const double d_right = ds + p.track_width / 2 * dth;
      const double per_metre = p.ticks_per_rev / (2 * kPi);
      rot_left += d_left * per_metre / r_left + noise(p.odo_slip);
      rot_right += d_right * per_metre / r_right + noise(p.odo_slip);
      gyro = dth + noise(p.gyro_error);
    }
    // Converting a double beyond int64 is undefined behaviour (tiny radius,
    // huge ticks_per_rev and odo_slip over a long drive).
    constexpr double kMaxTicks = 0x1p62;
    if (!(std::fabs(rot_left) < kMaxTicks && std::fabs(rot_right) < kMaxTicks))
      throw ParamError("car-track: the simulated tick count exceeds 2^62 at step " +
                       std::to_string(k) +
                       "; lower ticks_per_rev, odo_slip or steps, or raise wheel_radius");
    CarTrackRecord r;
    r.t = k / p.rate;
    r.odo_left_ticks = static_cast<std::int64_t>(std::floor(rot_left));
    r.odo_right_ticks = static_cast<std::int64_t>(std::floor(rot_right));
    r.gyro_dtheta = gyro;
    r.has_gps = true;
    r.gps_x = x + noise(p.gps_error);
    r.gps_y = y + noise(p.gps_error);
    r.gps_ex = r.gps_ey = p.gps_error;
    r.has_truth = true;
    r.truth_x = x;
    r.truth_y = y;
    r.truth_theta = th;
    records.push_back(r);
  }
  return records;
}

}  // namespace icp
