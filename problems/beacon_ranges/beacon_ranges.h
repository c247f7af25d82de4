// The beacon-ranges problem of paper 003 §5.2.3: a robot at an unknown
// position (x, y) measures its distance to beacons at known positions; some
// ranges are outliers. Range i, a reading d_i with half-width e_i to the
// beacon (bx_i, by_i), is the constraint of eq. 5.39 with interval data:
//   sqr(x - bx_i) + sqr(y - by_i) in [max(0, d_i - e_i)^2, (d_i + e_i)^2]
// with both squared bounds rounded outward, so an inlier never excludes the
// true position. An inlier's reading is the true distance plus noise within
// ±e_i/2; an outlier's misses it by at least 1 (and by far more than e_i).
//
// Scenarios (parameter `scenario`):
//   - two-robots: the fixed scene of Figs. 5.5-5.7, read from
//     data/two_robots.csv: robot A (source 0) has 3 ranges, 1 an outlier,
//     robot B (source 1) 4 ranges, 2 outliers. Each alone has several
//     maxima of the count of satisfied ranges; together they have one,
//     around the truth (beacon_ranges_test.cc checks it point by point).
//   - random: one step, `beacons` beacons uniform in the search box, the
//     truth uniform in its inner half, `outliers` of the ranges wrong.
//   - moving: the robot drives `steps` steps along a circle of radius
//     radius/2 at speed 1 per step; each step it ranges the same `beacons`
//     beacons with `outliers` outliers drawn anew, and odometry bounds its
//     displacement (the measurement-set view's predict).
// Every step offers the measurement-set view (one contractor per range), the
// CSP view (that step's ranges alone; empty for ICP once an outlier is in)
// and the probabilistic view (for the particle filter), which draws only
// from the filter's own random engine:
//   - sample_prior and sample_global: uniform in the search box;
//   - sample_motion: the identity, except in the moving scenario after step
//     0, where the displacement is drawn uniformly within the odometry box
//     (reading ± odometry_error on each component, the box predict uses);
//   - log_likelihood: RangeLogLikelihood below, -inf outside the search box.
// The ranges' likelihood is a mixture per range, the share of outliers
// epsilon = outliers / beacons (within [0.05, 0.95]; the two-robots scene
// uses the parameters' too) as a floor uniform over [0, the box's diagonal]
// (an outlier may be anywhere), and 1 - epsilon as a Gaussian of sigma = e
// about the reading: the inliers' error is uniform within ±e/2 (sigma
// e / (2 sqrt 3)), so this sigma is three times wider than theirs, which
// lets a few hundred particles spread over the box find the rings at the
// first steps; a hard bound at ±e would give every particle not within e of
// a ring the floor alone.
#ifndef ICPBENCH_PROBLEMS_BEACON_RANGES_BEACON_RANGES_H_
#define ICPBENCH_PROBLEMS_BEACON_RANGES_BEACON_RANGES_H_

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "core/box.h"
#include "core/params.h"
#include "problems/problem.h"

namespace icp {

struct BeaconRangesParams {
  // two-robots, random or moving (see above).
  std::string scenario = "two-robots";
  // Number of beacons, one range each per step (random, moving).
  int beacons = 6;
  // Number of outlier ranges per step, below beacons (random, moving).
  int outliers = 2;
  // Half-width of every range interval, below 0.5 so that an outlier,
  // wrong by at least 1, misses the truth by a clear margin (random, moving).
  double range_error = 0.1;
  // The search box is [-radius, radius]^2 (random, moving).
  double radius = 10;
  // Number of time steps (moving).
  int steps = 50;
  // Half-width of the odometry interval on each displacement component
  // (moving).
  double odometry_error = 0.1;
};
void Describe(BeaconRangesParams& p, ParamSet& set);

// Parses and validates (outliers < beacons); throws ParamError.
BeaconRangesParams ParseBeaconRanges(const std::string& owner, const ParamMap& values);
// Also reads the two-robots scene, so that a missing file fails early
// (std::invalid_argument).
ParamMap ResolveBeaconRanges(const std::string& owner, const ParamMap& values);

// One range reading to a beacon.
struct RangeMeasurement {
  int source = 0;  // the robot that measured it
  double beacon_x = 0;
  double beacon_y = 0;
  double range = 0;  // the reading d
  double error = 0;  // its half-width e
  bool outlier = false;
};

// The bounds of sqr(x - bx) + sqr(y - by) for a reading: [max(0, d - e)^2,
// (d + e)^2], rounded outward.
Interval SquaredRangeBounds(double range, double error);

// The mixture's floor share (above): its least and greatest value.
constexpr double kMinOutlierShare = 0.05;
constexpr double kMaxOutlierShare = 0.95;
// The share of outlier ranges p declares, outliers / beacons, within them.
double OutlierShare(const BeaconRangesParams& p);
// The log-likelihood of ranges at state (x, y): -inf outside box, else the
// sum over the ranges of log((1 - outlier_share) N(d; |state - beacon|, e)
// + outlier_share / diagonal(box)), d the reading and e its half-width.
double RangeLogLikelihood(const std::vector<RangeMeasurement>& ranges, const Box& box,
                          double outlier_share, const std::vector<double>& state);

// A fixed scene: search box, true position and ranges.
struct BeaconScene {
  Box box;
  std::vector<double> truth;
  std::vector<RangeMeasurement> ranges;
};

// Reads a scene file (format in problems/beacon_ranges/README.md); throws
// std::invalid_argument naming the file (source) and line on a bad one.
BeaconScene ReadBeaconScene(const std::string& path);
BeaconScene ReadBeaconScene(std::istream& in, const std::string& source);
// The shipped scene of Figs. 5.5-5.7.
std::string TwoRobotsScenePath();

std::unique_ptr<Problem> MakeBeaconRanges(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_BEACON_RANGES_BEACON_RANGES_H_
