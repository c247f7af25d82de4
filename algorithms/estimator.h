// The Estimator interface: the unit the harness compares (DESIGN.md). An
// estimator is made once per run with its parameters and seed, is handed the
// views of one step at a time, and returns an Estimate; it keeps whatever it
// needs between steps (a sliding window's last result, a particle cloud).
// Every CSP contractor becomes one through WindowEstimator
// (algorithms/window/window_estimator.h).
#ifndef ICPBENCH_ALGORITHMS_ESTIMATOR_H_
#define ICPBENCH_ALGORITHMS_ESTIMATOR_H_

#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/contractor.h"
#include "core/estimate.h"
#include "core/view.h"

namespace icp {

struct StepResult {
  std::unique_ptr<Estimate> estimate;
  // status: kStopped when the stop condition cut the step short; message:
  // anything worth keeping ("" for nothing). Work counters are reported as
  // properties.
  ContractSummary summary;
  Properties properties;
  // Seconds of the solving proper, when the estimator times it itself to
  // leave out setup (WindowEstimator: compiling the step's CSP); negative:
  // the harness times the whole Step.
  double solve_time_s = -1;
  // For relaxed solvers that compute every number of outliers at once (the
  // contractor polynomial): the hull of the solution set for q = 0..m.
  std::vector<Box> hulls_by_q;
  // For problems with landmarks: the estimate of every landmark so far (its
  // components, StateRef::Landmark order), by identity; the harness judges
  // their positions against the truth (Step::landmark_position).
  std::map<int, Box> landmarks;
  // For a landmark-observation view (paper 002): the landmark
  // (TypedLandmark::id) each of the step's observations was associated
  // with, -1 for none; unset when the estimator does not associate. The
  // harness scores them against the true identities.
  std::optional<std::vector<int>> associations;
};

// Thrown by an estimator that finds its own result broken (a contractor that
// grew its box): the run is recorded as failed with this message.
class InvalidResult : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Estimator {
 public:
  virtual ~Estimator() = default;
  // The estimate of one step, from the view the estimator needs (present:
  // the harness pairs estimators with problems by view).
  virtual StepResult Step(const Views& views, const StopCondition& stop) = 0;
  // Totals over the steps so far, stored with the run.
  virtual Properties RunProperties() const { return {}; }
};

// Work counters as properties ("revise_calls", "newton_steps", ...).
Properties WorkProperties(const WorkCounters& work);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_ESTIMATOR_H_
