#include "algorithms/relaxed/relaxed_estimator.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

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
  set.Add("outlier_share", &p.outlier_share,
          "the assumption: at most q_bound = max(q, floor(share * m)) of a step's m measurements "
          "are wrong; without auto_q the step uses q_bound, with auto_q a q above it restarts",
          Range::Closed(0, 1));
}

int QBound(int q, double share, int m) {
  // The shortest fixed-point text that reads back as share: its digits are
  // the decimal the spec wrote. Beyond 18 decimals (no spec writes those)
  // the double's own product is floored.
  char text[400];
  const auto [end, error] =
      std::to_chars(text, text + sizeof text, share, std::chars_format::fixed);
  const std::string_view digits(text, error == std::errc() ? end - text : 0);
  const std::size_t point = digits.find('.');
  const std::size_t decimals = point == std::string_view::npos ? 0 : digits.size() - point - 1;
  if (digits.empty() || decimals > 18)
    return std::max(q, static_cast<int>(std::floor(share * m)));
  __int128 numerator = 0, denominator = 1;
  for (char c : digits) {
    if (c == '.') continue;
    numerator = numerator * 10 + (c - '0');
  }
  for (std::size_t i = 0; i < decimals; ++i) denominator *= 10;
  return std::max(q, static_cast<int>(numerator * m / denominator));
}

int ChooseQ(int q, bool auto_q, int m, const std::function<bool(int)>& nonempty) {
  if (!auto_q) return q;
  for (int candidate = q; candidate < m; ++candidate)
    if (nonempty(candidate)) return candidate;
  return std::max(q, m);
}

StepResult RelaxedEstimator::Step(const Views& views, const StopCondition& stop) {
  const MeasurementSetView& view = *views.measurement_set;
  const int m = static_cast<int>(view.measurements.size());
  const int q_bound = QBound(params_.q, params_.outlier_share, m);
  const int q = params_.auto_q ? params_.q : q_bound;
  const bool tracking = params_.filter && view.predict && !previous_hull_.IsEmpty() &&
                        previous_hull_.size() == view.prior.size();
  // A solution that contradicts the assumption: empty under it, or auto_q
  // above q_bound. A stopped solve proves nothing either way.
  auto inconsistent = [&](const RelaxedSolution& s) {
    if (s.summary.status == ContractStatus::kStopped) return false;
    return s.estimate->Hull().IsEmpty() || s.q > q_bound;
  };
  std::optional<RelaxedSolution> solution;
  if (tracking) {
    const Box tracked = Intersect(view.prior, view.predict(previous_hull_));
    if (!tracked.IsEmpty()) solution = Solve(tracked, view, views.space, q, stop);
  }
  // Static recovery (paper 003 §6.7): a tracked search that found nothing,
  // or contradicts the assumption, starts again from the global prior.
  const bool reset = tracking && (!solution || inconsistent(*solution));
  if (reset) ++resets_;
  if (reset && solution) total_work_ += solution->summary.work;
  if (reset || !solution) solution = Solve(view.prior, view, views.space, q, stop);
  total_work_ += solution->summary.work;
  previous_hull_ = solution->estimate->Hull();
  const bool fired = reset || inconsistent(*solution);
  StepResult result;
  result.estimate = std::move(solution->estimate);
  result.summary = solution->summary;
  result.hulls_by_q = std::move(solution->hulls_by_q);
  result.properties = {{"q", static_cast<std::int64_t>(solution->q)},
                       {"q_bound", static_cast<std::int64_t>(q_bound)},
                       {"measurements", static_cast<std::int64_t>(m)},
                       {"tracked", static_cast<std::int64_t>(tracking && !reset ? 1 : 0)},
                       {"inconsistent", static_cast<std::int64_t>(fired ? 1 : 0)},
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
