// What is judged of each step an estimator took, beyond MeasureStep: the
// post-localized states, the credible regions' coverage, the landmarks, the
// associations and the set-membership guarantee, with the state each keeps
// across a run's steps. The runner and the Python module's stepping by hand
// share it, so a step's properties are the same wherever it is taken.
#ifndef ICPBENCH_HARNESS_STEP_JUDGES_H_
#define ICPBENCH_HARNESS_STEP_JUDGES_H_

#include "harness/association_metrics.h"
#include "harness/coverage.h"
#include "harness/guarantee.h"
#include "harness/landmark_metrics.h"
#include "harness/metrics.h"
#include "harness/runner.h"
#include "problems/problem.h"

namespace icp {

class StepJudges {
 public:
  // Adds to taken->record.properties the estimator's properties, the judges'
  // and the step's annotations, the estimate's extras and its message; throws
  // InvalidResult where the estimator's answer is malformed (associations of
  // the wrong length).
  void Judge(const Step& step, TakenStep* taken);
  // The judges' properties of the run so far (guarantee, coverage, landmarks,
  // associations), after the estimator's own.
  Properties RunProperties() const;

 private:
  PostStateJudge post_states_;
  GuaranteeJudge guarantee_;
  CoverageCounter coverage_;
  LandmarkJudge landmarks_;
  AssociationJudge associations_;
};

}  // namespace icp

#endif  // ICPBENCH_HARNESS_STEP_JUDGES_H_
