// The visual-landmarks problem (paper 004): a car with odometry, a gyro and a
// monocular camera that sees landmarks, in two phases.
//   teach   GPS boxes on the poses, the landmarks unknown: each landmark is
//           six intervals (x_c, y_c, z_c, alpha, phi, d), an infinite cone
//           from its first sighting (camera_model.h), which the sightings
//           from other poses shrink (mapping, §3, §5.1);
//   repeat  no GPS: a map of landmark boxes (a teach run's, `map`, or a
//           surveyed one, the true positions +- map_error) locates the car
//           from a known start (§4).
// Step k yields the CSP of the window of poses k-w..k (Xi = w, eq. 26):
// poses x[j], y[j], th[j] linked by the motion of eq. 11 (car_track/window.h),
// every landmark seen in the window as a state of its own identity
// (StateRef::Landmark(n, component), named L<n>.xc ... L<n>.d, L<n>.x,
// L<n>.y, L<n>.z: the cone and its position, camera_model.h) with eq. 12
// (AddConeDefinition), and three constraints per sighting (AddObservation,
// eq. 13-19). Its ICSPs (eq. 20-21: one per motion, one per sighting, which
// holds its landmark's eq. 12 too) are listed in CspView::icsps for `lic`.
//
// Initial domains (measurements alone; an estimator carries its own
// results): th[j] is the start heading (the truth +- heading_error) plus the
// gyro's sum to j; in teach x[j], y[j] are the GPS box of step j; in repeat
// they are the start fix (the truth +- gps_error) at step 0 and dead
// reckoning from it later. A landmark's domains in teach are its cone at its
// first sighting (InitialCone over the pose domains of that step); while
// that step is in the window, x_c = x[first] and y_c = y[first] join its
// ICSP. In repeat a landmark is its map box: (x_c, y_c, z_c) the box,
// alpha = phi = d = 0, (x, y, z) the box. A sighting of a landmark the map lacks is ignored.
//
// With `log`, a logged drive (feature_log.h) replaces the simulator; where
// it gives no reference pose or landmark position, the step has no truth
// for it (a log without the first pose starts from the whole circle of
// headings, and repeat from its first GPS fix).
//
// Sound: every measurement interval holds the truth (visual_drive.h), the
// truth follows eq. 11 exactly, and the cone and the map box hold each
// landmark (a map box that does not is refused at construction), so the
// truth is a solution of every step's CSP (Step::csp_truth).
#ifndef ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_VISUAL_LANDMARKS_H_
#define ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_VISUAL_LANDMARKS_H_

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>

#include "core/params.h"
#include "problems/problem.h"
#include "problems/visual_landmarks/landmark_map.h"
#include "problems/visual_landmarks/visual_drive.h"

namespace icp {

struct VisualLandmarksParams {
  std::string phase = "teach";  // teach | repeat
  int w = 10;                   // Xi, the window in steps
  std::string route = "straight";
  int steps = 100;
  double dt = 1;       // s
  double speed = 0.1;  // m/s
  int landmarks = 5;
  int layout_seed = 1;
  double pixel_error = 1;
  double odometry_error = 0.005;
  double gyro_error = 0.001;
  double gps_error = 0.02;
  double heading_error = 0.01;  // rad, half-width of the known start heading
  double focal = 320;
  double cu = 320;
  double cv = 240;
  int image_width = 640;
  int image_height = 480;
  double camera_height = 1.5;
  std::string map;          // repeat: a landmark map file (landmark_map.h)
  double map_error = 0.05;  // repeat without a map file: the surveyed map's half-width
  // The landmarks the map metrics score (Step::scored_landmarks): those
  // whose rays from their first and last sightings part by at least this
  // many degrees (paper 004's fifth landmark, almost on the line of travel,
  // has 0.2 degrees and is not among its "converged" four).
  double min_parallax = 5;
  // How each sighting is written (camera_model.h AddObservation): "both"
  // (on the cone and on the position, five constraints) or "cone" (the
  // paper's form alone, three), for comparison.
  std::string observation = "both";
  // A feature-track log (feature_log.h) replacing the simulator: its
  // odometry, gyro, GPS and matched features; the simulator's parameters
  // but the intrinsics play no part, and steps is at most its rows.
  std::string log;
};
void Describe(VisualLandmarksParams& p, ParamSet& set);
ParamMap ResolveVisualLandmarks(const std::string& owner, const ParamMap& values);

// The drive's parameters from the problem's.
VisualDriveParams DriveParams(const VisualLandmarksParams& p);

class VisualLandmarksProblem : public Problem {
 public:
  // Throws std::invalid_argument when a map box does not hold its landmark
  // or names a landmark the route does not have.
  VisualLandmarksProblem(const VisualLandmarksParams& params, std::uint64_t seed);
  std::string_view Name() const override { return "visual-landmarks"; }
  int NumSteps() const override {
    return std::min(params_.steps, static_cast<int>(drive_.steps.size()));
  }
  bool Next(Step* step) override;
  const VisualDrive& drive() const { return drive_; }

 private:
  bool teach() const { return params_.phase == "teach"; }
  // The angle between landmark n's rays from its first sighting and its
  // last one (step last), degrees (teach; n seen).
  double Parallax(int n, int last) const;

  VisualLandmarksParams params_;
  VisualDriveParams drive_params_;
  VisualDrive drive_;
  std::vector<Box> poses_;                  // per step: x, y, th domains
  std::vector<int> first_sighting_;         // per landmark, -1 if never seen
  std::vector<Box> landmark_domains_;       // per landmark: its six domains
  std::vector<std::array<double, kLandmarkComponents>> landmark_truth_;
  std::vector<bool> usable_;                // per landmark: in the map (repeat) or seen (teach)
  std::vector<int> scored_;                 // the landmarks with parallax (teach)
  std::vector<bool> truth_known_;           // per landmark: its landmark_truth_ is known
  int k_ = 0;
};

std::unique_ptr<Problem> MakeVisualLandmarks(const ParamMap& params, std::uint64_t seed);

}  // namespace icp

#endif  // ICPBENCH_PROBLEMS_VISUAL_LANDMARKS_VISUAL_LANDMARKS_H_
