// Paper 004's map metrics from the landmark estimates of a run (DESIGN.md
// "States that do not move"): per step, each landmark's position box (eq.
// 12, Step::landmark_position) and whether it holds the truth (eq. 31); per
// run, from each landmark's last box, MPV (eq. 32) and MDW (Table 2).
#ifndef ICPBENCH_HARNESS_LANDMARK_METRICS_H_
#define ICPBENCH_HARNESS_LANDMARK_METRICS_H_

#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "core/box.h"
#include "core/estimate.h"
#include "problems/problem.h"

namespace icp {

// The landmark boxes a step's properties hold (L<n>_x_lo ... L<n>_z_hi, as
// LandmarkJudge writes them), by landmark: {x_lo, x_hi, y_lo, y_hi, z_lo,
// z_hi}, NaN for a bound the properties lack.
std::map<int, std::array<double, 6>> LandmarkBoxesOf(const Properties& properties);

class LandmarkJudge {
 public:
  // Adds, when the step reports landmarks: landmarks and landmarks_contained
  // (how many are reported and how many hold the truth), and for each
  // landmark n, L<n>_x_lo, L<n>_x_hi, L<n>_y_lo, ..., L<n>_z_hi and L<n>_held
  // (1 or 0; absent when the truth is unknown).
  void Judge(const Step& step, const std::map<int, Box>& landmarks, Properties* out);
  // None when no step reported a landmark; else landmarks_mapped,
  // landmarks_scored, landmark_consistency (the share of the
  // (step, landmark) boxes that held the truth) and, over the last boxes of
  // the problem's scored landmarks (Step::scored_landmarks, those its drive
  // can locate), mpv (eq. 32, m^3) and mdw_x, mdw_y, mdw_z (Table 2's mean
  // widths, m); +inf when an estimator left one of them unbounded or never
  // reported it; and each judged landmark's true position, L<n>_truth_x,
  // L<n>_truth_y, L<n>_truth_z (for figures).
  Properties RunProperties() const;

 private:
  std::map<int, std::array<Interval, 3>> last_;
  std::vector<int> scored_;
  std::map<int, std::array<double, 3>> truth_;
  std::int64_t judged_ = 0;
  std::int64_t held_ = 0;
};

}  // namespace icp

#endif  // ICPBENCH_HARNESS_LANDMARK_METRICS_H_
