// Paper 002 (Delafosse et al. 2004: a robot at a corridor's end tracking
// typed landmarks) in the report and the figures, from the indoor-landmarks
// runs of spec experiments `indoor` and `indoor-spurious` (specs/default.yaml):
//
//   the tables "Paper 002: ..." (accuracy) and "Paper 002: associations
//   and time per step": per configuration and path, pooled over seeds, the
//   share of steps whose box holds the true pose (all steps, and those
//   where the estimator's assumption held), the widest box in x, y (m) and
//   theta (deg), the position and heading errors of the box's centre, with
//   the paper's values beside them; then the associations right / wrong /
//   missed, how often a step with a wrong association lost the truth, and
//   the time per step;
//
//   the figures fig9_odometry (dead-reckoning's x-y boxes on paths a and
//   b on the corridor's walls, with the truth) and fig11_landmarks
//   (landmark-tracking's at its defaults as its x and y interval errors
//   over the steps, lo - truth and hi - truth: its boxes are a few cm wide,
//   hidden under the track on the map), smallest seed.
#ifndef ICPBENCH_EXPERIMENTS_PAPER002_PAPER002_H_
#define ICPBENCH_EXPERIMENTS_PAPER002_PAPER002_H_

#include <string>
#include <vector>

#include "harness/run_record.h"
#include "plots/figures.h"
#include "report/report.h"

namespace icp {

inline constexpr const char* kPaper002Experiment = "indoor";

// Paper 002 §4, Fig. 11: with landmarks, boxes "lower than 20 cm in X and
// Y, and 11 degrees in orientation", errors of "10 cm in position and one
// degree in orientation".
struct Paper002Published {
  double widest_xy = 0.20;        // m
  double widest_theta_deg = 11;
  double position_error = 0.10;   // m
  double heading_error_deg = 1;
};
inline constexpr Paper002Published kPaper002;

// What one run's steps say (NaN without step rows or truth).
struct IndoorRunStats {
  double widest_x = 0, widest_y = 0;  // m, the widest box over the steps
  double widest_theta_deg = 0;
  double position_error = 0;          // m, mean distance box centre - truth
  double heading_error_deg = 0;       // mean |centre - truth| of theta, wrapped
  // The share of steps after the first whose 3-D box (x, y, theta: the
  // paper's Fig. 9 draws 3-D subpavings) is larger than the step before's
  // (1: it grows at every step).
  double growth_share = 0;
};
IndoorRunStats IndoorStats(const RunRecord& run);

std::vector<TextTable> Paper002Tables(const std::vector<RunRecord>& runs);
void Paper002Figures(const std::vector<RunRecord>& runs, const std::string& out_dir,
                     PlotOutput* out);

}  // namespace icp

#endif  // ICPBENCH_EXPERIMENTS_PAPER002_PAPER002_H_
