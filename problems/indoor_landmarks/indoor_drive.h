// The indoor-landmarks problem's parameters and its simulated drive (paper
// 002 §3-4): a differential-drive robot at the end of a corridor, with wheel
// odometry and an omnidirectional range-and-bearing sensor that returns
// typed landmarks (corner, edge, other).
//
// Paths (one acquisition every 0.30 m, as in the paper): `a` drives 35 steps
// along the corridor at y = 0.85 m and turns left into the hall over the
// last 10 (9 deg a step); `b` starts 0.30 m to its left and turns right;
// both are the paper's 46 acquisitions. `random` wanders the corridor and
// the hall for `steps` acquisitions (a turn of up to 0.2 rad a step, more
// when a wall is within 0.4 m ahead).
//
// Odometry: the true wheel radii and track width are drawn once per run
// within 0.9 of their bounds around the nominal values; each step's wheel
// rotations are the ones that produce the true motion (eq. 2-4), read with
// an error within 0.9 of rotation_error.
//
// Returns: every landmark within max_range and the field of view whose line
// of sight crosses no wall, each missed with probability dropout_rate, read
// with range and bearing errors within 0.9 of their bounds; plus spurious
// returns, spurious_rate per acquisition on average (its whole part every
// time, one more with the probability of its fraction), each a ghost
// of a visible landmark (same type, 0.15-0.5 m away in a random direction,
// as a reflection or a mis-segmented corner makes). Returns are listed by
// bearing, as the sensor scans.
#ifndef ICPBENCH_PROBLEMS_INDOOR_LANDMARKS_INDOOR_DRIVE_H_
#define ICPBENCH_PROBLEMS_INDOOR_LANDMARKS_INDOOR_DRIVE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "core/params.h"
#include "core/view.h"
#include "problems/indoor_landmarks/indoor_map.h"

namespace icp {

struct IndoorLandmarksParams {
  // Which drive: a, b (the paper's two 46-acquisition paths) or random.
  std::string path = "a";
  // Number of acquisitions; at most 46 on paths a and b.
  int steps = 46;
  // The map file; empty: the shipped corridor end (data/corridor_end.csv).
  std::string map;
  // Nominal wheel radius and its error bound, m.
  double wheel_radius = 0.04;
  double radius_error = 0.0004;
  // Nominal track width (between the wheels) and its error bound, m.
  double track = 0.35;
  double track_error = 0.004;
  // Error bound of a wheel's rotation over a step, rad.
  double rotation_error = 0.05;
  // Error bounds of a return's range (m) and bearing (rad).
  double range_error = 0.03;
  double bearing_error = 0.02;
  // The sensor's range (m) and field of view (deg, centred on the heading).
  double max_range = 6;
  double fov = 360;
  // Mean number of spurious returns per acquisition; probability that a
  // landmark in sight is not returned.
  double spurious_rate = 1;
  double dropout_rate = 0.1;
  // Half-widths of the known start box: position (m) and heading (rad).
  double start_error = 0.05;
  double start_heading_error = 0.035;
};
void Describe(IndoorLandmarksParams& p, ParamSet& set);

// One acquisition.
struct IndoorRecord {
  double x = 0, y = 0, heading = 0;     // the true pose (heading unwrapped)
  WheelOdometry odometry;               // the motion from the previous acquisition (unset at 0)
  std::vector<PolarObservation> observations;
  std::vector<int> identities;          // per observation: its landmark, -1 spurious
};

// Throws ParamError when the drive's start, (0.8, 0.85) or on path b
// (0.8, 1.15), lies off the map or within 0.4 m of one of its walls.
void CheckIndoorStart(const IndoorLandmarksParams& params, const IndoorMap& map);

// The drive of a run: one record per acquisition. Throws ParamError as
// CheckIndoorStart.
std::vector<IndoorRecord> SimulateIndoorDrive(const IndoorLandmarksParams& params,
                                              const IndoorMap& map, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_INDOOR_LANDMARKS_INDOOR_DRIVE_H_
