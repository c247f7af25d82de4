// Paper 002's association scores (issue 30): an estimator that associates
// returns with map landmarks (StepResult::associations) against the true
// identities (Step::observation_truth).
#ifndef ICPBENCH_HARNESS_ASSOCIATION_METRICS_H_
#define ICPBENCH_HARNESS_ASSOCIATION_METRICS_H_

#include <cstdint>
#include <optional>
#include <vector>

#include "core/estimate.h"
#include "problems/problem.h"

namespace icp {

class AssociationJudge {
 public:
  // When the estimator associates (associations set) and the step has true
  // identities, adds associations_right (a landmark's
  // return given its landmark), associations_wrong (a return given another
  // landmark, or a spurious return given any), associations_missed (a
  // landmark's return given none) and assumption_held (1 while every
  // association of the run so far was right: the estimate's guarantee
  // needs it, so its misses are counted apart). `contained` is the step's
  // StepRecord::contained (1, 0, or -1 unknown). Throws
  // std::invalid_argument when the associations are not one per return.
  void Judge(const Step& step, const std::optional<std::vector<int>>& associations,
             int contained, Properties* out);
  // None when no step was judged; else the totals associations_right,
  // associations_wrong, associations_missed, wrong_association_steps (steps
  // with a wrong association) and wrong_association_losses (those whose
  // estimate missed the truth).
  Properties RunProperties() const;

 private:
  std::int64_t right_ = 0, wrong_ = 0, missed_ = 0;
  std::int64_t wrong_steps_ = 0, wrong_losses_ = 0;
  bool judged_ = false;
  bool all_right_ = true;
};

}  // namespace icp

#endif  // ICPBENCH_HARNESS_ASSOCIATION_METRICS_H_
