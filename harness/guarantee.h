// The relaxed solvers' guarantee judged against the truth (paper 003 §6.7,
// issue 35). A relaxed solver states its assumption per step (the step
// properties q_bound and tracked, algorithms/relaxed/relaxed_estimator.h);
// the problem knows the step's true outliers (true_outliers, MeasureStep).
// The estimate is guaranteed to hold the truth when the assumption held at
// that step and, for a filter, at every step since its last (re)start.
#ifndef ICPBENCH_HARNESS_GUARANTEE_H_
#define ICPBENCH_HARNESS_GUARANTEE_H_

#include <optional>
#include <string>
#include <vector>

#include "core/estimate.h"
#include "harness/run_record.h"

namespace icp {

// Loss episodes over a run's steps: maximal stretches of steps whose
// estimate misses the truth. An episode that ends took as many steps to
// re-acquire the truth as it lasted.
class LossEpisodes {
 public:
  // contained: 1, 0, or -1 for a step whose truth is unknown (ignored).
  void Add(int contained);
  int episodes() const { return episodes_; }
  // The length of each episode that ended, in order.
  const std::vector<double>& reacquire_steps() const { return reacquire_steps_; }
  bool lost() const { return lost_; }
  int judged() const { return judged_; }  // steps whose truth is known

 private:
  bool lost_ = false;
  int length_ = 0;
  int episodes_ = 0;
  int judged_ = 0;
  std::vector<double> reacquire_steps_;
};

// Judges a run's steps one at a time, in order. To each step with
// properties q_bound and true_outliers it adds assumption_held (1 or 0: at
// most q_bound true outliers at this step and at every step since the last
// one with tracked = 0; a step without `tracked` is a restart); to each
// such step that misses the truth it adds miss_reason, of the form
// "<category> (<numbers>)": the assumption violated, auto_q's q below the
// true outliers, or, for a step that does not explain its own miss, the
// reason of the step where its loss episode began.
class GuaranteeJudge {
 public:
  void Judge(StepRecord* step);
  // loss_episodes, when a step's truth was known, and reacquire_steps_median
  // when an episode ended.
  Properties RunProperties() const;

 private:
  bool held_since_restart_ = true;
  // Why the current loss episode began, and where.
  std::string episode_category_, episode_detail_;
  int episode_start_ = 0;
  LossEpisodes episodes_;
};

// A miss reason's category: the text before " (".
std::string MissCategory(const std::string& reason);

// Restarts of a run: the relaxed solvers' static recoveries (run property
// resets), or the particle filter's reinitialisations; nullopt when the
// estimator reports neither.
std::optional<double> RunRestarts(const RunRecord& r);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_GUARANTEE_H_
