// The visual-landmarks drive simulator (paper 004 §5.1 and, for repeat, a route
// like Fig. 12's): a car drives a route sampled every `dt` seconds, with
// odometry (distance, eq. 11's delta s) and gyro (delta theta) intervals, GPS
// boxes (for teach) and a camera that sees the landmarks in its image, each
// at a pixel box of +-pixel_error px. The simulator gives the landmarks'
// identities (data association is out of scope, issue 29).
//
// What the paper does not say, and what we chose:
//   - time step 1 s, 100 steps (10 m at 0.1 m/s), the camera 1.5 m above
//     the ground (CameraIntrinsics), the car starting at the origin heading
//     along +x;
//   - the five landmarks of the straight route, at (12, 3, 2), (14, -2.5, 1),
//     (16, 1.5, 3), (18, -4, 2.5) and (30, 0.2, 1.6): the last one almost on
//     the line of travel, so the drive gives it almost no parallax (paper
//     004 measures MPV over the four landmarks that converge); more than
//     five are drawn along its first 40 m;
//   - the "loop" route (about 183 m): 60 m straight, a half circle of radius
//     10 m, 60 m straight, a half circle back to the start; its landmarks
//     are drawn along the route, 3 to 8 m to either side, 0.5 to 4 m high;
//   - drawn landmarks come from their own engine (layout_seed), not from the
//     drive's seed, so a teach run and a repeat run of other seeds, lengths
//     or speeds on the same route share the map;
//   - bounded errors, drawn uniformly within 0.9 of each half-width so that
//     the truth lies strictly inside every interval: odometry +-odometry_error
//     m, gyro +-gyro_error rad per step, GPS +-gps_error m, pixels
//     +-pixel_error px.
// The truth follows eq. 11 exactly with the true delta s and delta theta.
#ifndef ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_VISUAL_DRIVE_H_
#define ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_VISUAL_DRIVE_H_

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/box.h"
#include "core/interval.h"
#include "problems/visual_landmarks/camera_model.h"

namespace icp {

struct VisualDriveParams {
  std::string route = "straight";  // "straight" | "loop"
  int steps = 100;
  double dt = 1;        // s
  double speed = 0.1;   // m/s
  // How many landmarks: the straight route's first five are the fixed ones
  // below, the others (and the loop's) are drawn from layout_seed.
  int landmarks = 5;
  std::uint64_t layout_seed = 1;
  double pixel_error = 1;        // px, half-width of a pixel box
  double odometry_error = 0.005; // m per step, half-width of [delta s]
  double gyro_error = 0.001;     // rad per step, half-width of [delta theta]
  double gps_error = 0.02;       // m, half-width of a GPS box in x and y
  CameraIntrinsics camera;
};

// One landmark seen at a step: its identity (index into the landmarks) and
// its pixel box.
struct LandmarkSighting {
  int landmark = 0;
  Interval u, v;
};

struct VisualDriveStep {
  // The motion from the previous step (eq. 11); [0, 0] at step 0.
  Interval ds, dtheta;
  // The GPS box of the position, x then y.
  Box gps;
  // The landmarks in the image, by increasing identity.
  std::vector<LandmarkSighting> sightings;
};

struct VisualDrive {
  std::vector<std::array<double, 3>> poses;      // the truth, per step (heading unwrapped)
  std::vector<std::array<double, 3>> landmarks;  // the truth
  std::vector<VisualDriveStep> steps;
};

// Throws std::invalid_argument on a bad route or non-positive counts.
VisualDrive SimulateVisualDrive(const VisualDriveParams& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_VISUAL_DRIVE_H_
