#include "algorithms/relaxed/relaxed_estimator.h"

#include <optional>
#include <stdexcept>
#include <string>

namespace icp {

void Describe(RelaxedParams& p, ParamSet& set) {
  set.Add("q", &p.q,
          "outliers allowed: a point is kept when it satisfies m - q of the m measurements "
          "(IBEX's CtcQInter counts the other way: its q is m minus this one)",
          Range::AtLeast(0));
  set.Add("auto_q", &p.auto_q,
          "use the smallest q' >= q whose solution set is non-empty, and report it as `q`");
  set.Add("filter", &p.filter,
          "on a stream of steps, start each from prior ∩ predict(previous hull)");
  set.Add("max_outlier_share", &p.max_outlier_share,
          "with auto_q, a tracked search needing more than this share of wrong measurements "
          "restarts from the prior (1: never)",
          Range{0, 1, true, false});
}

int ChooseQ(int q, bool auto_q, int m, const std::function<bool(int)>& nonempty) {
  if (!auto_q) return q;
  for (int candidate = q; candidate < m; ++candidate)
    if (nonempty(candidate)) return candidate;
  return std::max(q, m);
}

StepResult RelaxedEstimator::Step(const Views& views, const StopCondition& stop) {
  const MeasurementSetView& view = *views.measurement_set;
  const bool tracking = params_.filter && view.predict && !previous_hull_.IsEmpty() &&
                        previous_hull_.size() == view.prior.size();
  std::optional<RelaxedSolution> solution;
  if (tracking) {
    const Box tracked = Intersect(view.prior, view.predict(previous_hull_));
    if (!tracked.IsEmpty()) solution = Solve(tracked, view, views.space, stop);
  }
  // Static recovery (paper 003 §6.7): a tracked search that found nothing
  // (more outliers than q, or an earlier estimate that lost the truth)
  // starts again from the global prior.
  const int m = static_cast<int>(view.measurements.size());
  auto lost = [&](const RelaxedSolution& s) {
    if (s.summary.status == ContractStatus::kStopped) return false;
    return s.estimate->Hull().IsEmpty() ||
           (params_.auto_q && s.q > params_.max_outlier_share * m);
  };
  const bool reset = tracking && (!solution || lost(*solution));
  if (reset) ++resets_;
  if (reset && solution) total_work_ += solution->summary.work;
  if (reset || !solution) solution = Solve(view.prior, view, views.space, stop);
  total_work_ += solution->summary.work;
  previous_hull_ = solution->estimate->Hull();
  StepResult result;
  result.estimate = std::move(solution->estimate);
  result.summary = solution->summary;
  result.hulls_by_q = std::move(solution->hulls_by_q);
  result.properties = {{"q", static_cast<std::int64_t>(solution->q)},
                       {"measurements", static_cast<std::int64_t>(view.measurements.size())},
                       {"reset", static_cast<std::int64_t>(reset ? 1 : 0)}};
  for (Property& p : solution->properties) result.properties.push_back(std::move(p));
  for (Property& p : WorkProperties(solution->summary.work)) result.properties.push_back(std::move(p));
  return result;
}

Properties RelaxedEstimator::RunProperties() const {
  Properties out = WorkProperties(total_work_);
  out.push_back({"resets", resets_});
  return out;
}

}  // namespace icp
