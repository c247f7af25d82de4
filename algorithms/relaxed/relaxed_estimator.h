// What the relaxed-CSP solvers (q-relaxed, polynomial, accumulator) share:
// they read the measurement-set view, allow q wrong measurements among m
// (paper 003 §2.2), and can run as filters over a stream of steps. A point
// is kept when it satisfies at least m - q measurements; q counts the
// measurements allowed to be wrong (IBEX's CtcQInter and Codac count those
// that must hold: their q is m minus ours).
//
// Parameters shared by all three:
//   q       the number of outliers allowed (at least, with auto_q);
//   outlier_share
//           the outlier assumption, scaled to the step: at most
//           q_bound = max(q, floor(outlier_share * m)) of the step's m
//           measurements are wrong (floor of the decimal share as written,
//           exactly). Without auto_q the step uses q = q_bound, and the
//           estimate provably holds the truth whenever the step's true
//           outliers are at most q_bound, and were at every step since the
//           last (re)start (a filter starts from the previous estimate);
//   auto_q  take the smallest q' >= q whose solution set is non-empty, and
//           report it: never more than the true number of outliers, since
//           the truth satisfies every inlier; tighter than q_bound, with no
//           guarantee (it can take fewer than the true outliers);
//   filter  with a view that can predict (a moving robot), start each step
//           from prior ∩ predict(previous hull) instead of the prior alone.
//
// A detected inconsistency (the tracked search finds nothing: an empty
// intersection or an empty set under q_bound, or, with auto_q, a q above
// q_bound) says the track is lost or the assumption failed: the step
// starts again from the prior, a global search (the static recovery of
// paper 003 §6.7). With the default outlier_share 0 and auto_q, a tracked
// step that needs any outlier above q restarts. Step properties: q, q_bound,
// measurements, tracked (1 when the step followed the previous one, 0 on a
// (re)start), inconsistent (1 when a detected inconsistency fired: a restart,
// or a global search that itself contradicts the assumption) and reset (1 on
// a restart from a tracked search); the run property `resets` counts those.
#ifndef ICPBENCH_ALGORITHMS_RELAXED_RELAXED_ESTIMATOR_H_
#define ICPBENCH_ALGORITHMS_RELAXED_RELAXED_ESTIMATOR_H_

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "algorithms/estimator.h"
#include "core/contractor_algebra.h"
#include "core/params.h"

namespace icp {

struct RelaxedParams {
  int q = 0;
  bool auto_q = true;
  bool filter = true;
  double outlier_share = 0;
};
void Describe(RelaxedParams& p, ParamSet& set);

// One step's result of a relaxed solver.
struct RelaxedSolution {
  std::unique_ptr<Estimate> estimate;
  int q = 0;  // the q used, or found with auto_q
  // For q = 0..m, the hull of the solution set (solvers that compute every
  // q at once); empty otherwise.
  std::vector<Box> hulls_by_q;
  ContractSummary summary;
  Properties properties;
};

class RelaxedEstimator : public Estimator {
 public:
  explicit RelaxedEstimator(RelaxedParams params) : params_(params) {}
  StepResult Step(const Views& views, const StopCondition& stop) final;
  Properties RunProperties() const override;

 protected:
  // The solution over prior (the step's search box, filtered) from the
  // view's measurements, with least_q outliers (the least, with params().auto_q).
  virtual RelaxedSolution Solve(const Box& prior, const MeasurementSetView& view,
                                const StateSpace& space, int least_q,
                                const StopCondition& stop) = 0;
  const RelaxedParams& params() const { return params_; }
  WorkCounters& total_work() { return total_work_; }

 private:
  RelaxedParams params_;
  Box previous_hull_;  // empty before the first step or after an empty one
  WorkCounters total_work_;
  std::int64_t resets_ = 0;
};

// max(q, floor(share * m)), the floor taken of the shortest decimal that
// reads back as share (0.3 is 3/10, not the double just below it), in
// exact integer arithmetic.
int QBound(int q, double share, int m);

// The q to use among m measurements: q itself without auto_q, else the
// smallest q' in [q, m] for which nonempty(q') holds (m when none does,
// where every point qualifies). Solvers whose sets grow with q.
int ChooseQ(int q, bool auto_q, int m, const std::function<bool(int)>& nonempty);

}  // namespace icp

#endif  // ICPBENCH_ALGORITHMS_RELAXED_RELAXED_ESTIMATOR_H_
