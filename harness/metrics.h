// Per-run metrics from per-step records (DESIGN.md "Metrics").
#ifndef ICPBENCH_HARNESS_METRICS_H_
#define ICPBENCH_HARNESS_METRICS_H_

#include <cstdint>
#include <deque>
#include <utility>
#include <vector>

#include "core/estimate.h"
#include "harness/run_record.h"
#include "problems/problem.h"

namespace icp {

// The metrics of one step from its estimate and truth, whatever the kind of
// estimate: each component's hull bounds and truth, containment of the truth
// (paper 004 eq. 31), the x-y area and the centre error. A periodic
// component's truth is moved by the multiple of its period nearest to the
// hull's midpoint, so a heading estimated in another frame (2 pi apart) is
// judged exactly. With a measurement-set view whose outliers are known, the
// property `true_outliers` (their number). status, solve time and the
// estimator's properties are left to the caller.
StepRecord MeasureStep(const Step& step, const Estimate& estimate);
// Whether point, a state of space, lies in estimate, a periodic component (a
// heading) compared modulo its period: what `contained` records of a truth.
bool ContainsState(const StateSpace& space, const Estimate& estimate, std::vector<double> point);

// The levels, in per cent, whose credible regions' coverage is measured.
inline constexpr int kCoverageLevels[] = {50, 90, 95};
// Whether the truth lies in the estimate's credible region at each level
// (Estimate::CredibleRegion; a periodic component's truth moved as in
// MeasureStep): the properties covered_50, covered_90 and covered_95, 1 or
// 0. None when the truth is unknown or the estimate is a set (no region).
Properties CoverageProperties(const Step& step, const Estimate& estimate);

// Why an estimate cannot be the answer to the step, or "" when it can: a
// malformed part (Estimate::Malformed), a hull of the wrong dimension, a
// NaN bound, or, for an estimate that claims an enclosure (not a particle
// cloud), a component outside the step's domains (the CSP view's newest
// state, the measurement set's prior; a periodic component is compared
// modulo its period).
std::string InvalidEstimateReason(const Views& views, const Estimate& estimate);

// Judges the post-localized state an estimator reports (the properties
// post_step, post_<name>_lo and post_<name>_hi: paper 004 §4.2, see
// WindowEstimator) against that state's own truth, kept from the step that
// estimated it: adds post_<name>_truth (a periodic one moved as in
// MeasureStep), post_contained (1 or 0), post_area and post_centre_error
// (when the state is planar). It keeps the truths of the steps not reported
// yet: as many as the window is long, since post_step never goes back.
class PostStateJudge {
 public:
  void Judge(const Step& step, Properties* properties);

 private:
  std::deque<std::pair<int, std::vector<double>>> truths_;  // (step, truth), by step
};

// The post-localized states of a run: one record per state time (its step
// field), from the last step that reported it (the box it kept once it left
// the window), with its bounds, truth, contained, area and centre error;
// in the order of the states. Empty when no step reports post_step.
// ComputeMetrics over them gives the post-localization's consistency,
// corridors and mean area.
std::vector<StepRecord> PostLocalizedStates(const std::vector<StepRecord>& steps);

// The metrics of a run accumulated one step at a time, so a run of any
// length is measured without keeping its steps (only their solve times, for
// the median and the bootstrap). Finish gives exactly what ComputeMetrics
// gives over the same steps in the same order.
class MetricsAccumulator {
 public:
  void Add(const StepRecord& step);
  RunMetrics Finish(std::uint64_t bootstrap_seed = 1) const;

 private:
  struct CorridorSums {
    Corridor corridor;
    double sum_lower = 0;
    double sum_upper = 0;
    int count = 0;
  };
  int steps_ = 0;
  double area_sum_ = 0;
  int areas_ = 0;
  double squared_error_sum_ = 0;
  int errors_ = 0;
  int judged_ = 0;
  int consistent_ = 0;
  std::vector<double> times_;
  std::vector<CorridorSums> corridors_;  // in order of first appearance
};

// Aggregates steps: mean area, consistency rate, centre RMSE, corridors, and
// mean/median/p90 solve time with a bootstrap 95% interval of the mean
// (resamples drawn with a generator seeded by bootstrap_seed, so reports are
// reproducible).
RunMetrics ComputeMetrics(const std::vector<StepRecord>& steps, std::uint64_t bootstrap_seed = 1);

// A step's estimate holds nothing: the estimator said so, or a variable's
// interval is empty (lo > hi, the +inf/-inf convention of VariableRecord, or
// NaN bounds).
bool IsEmptyEstimate(const StepRecord& s);

// The mean of values; NaN for none.
double Mean(const std::vector<double>& values);

// The p-quantile (0 <= p <= 1) of values by linear interpolation between
// order statistics; NaN for no values.
double Quantile(std::vector<double> values, double p);

}  // namespace icp

#endif  // ICPBENCH_HARNESS_METRICS_H_
