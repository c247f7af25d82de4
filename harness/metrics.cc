#include "harness/metrics.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>

#include "core/random.h"

namespace icp {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kBootstrapResamples = 1000;

bool TruthKnown(const StepRecord& s) {
  if (s.contained != -1) return true;
  for (const VariableRecord& v : s.vars) {
    if (!std::isnan(v.truth)) return true;
  }
  return false;
}

// Percentile bootstrap: the 2.5% and 97.5% quantiles of the means of
// kBootstrapResamples resamples drawn with replacement.
void BootstrapMeanInterval(const std::vector<double>& values, std::uint64_t seed, double* lo,
                           double* hi) {
  *lo = *hi = kNaN;
  if (values.empty()) return;
  RandomEngine rng(seed);
  std::vector<double> means;
  means.reserve(kBootstrapResamples);
  for (int r = 0; r < kBootstrapResamples; ++r) {
    double sum = 0;
    for (std::size_t i = 0; i < values.size(); ++i) sum += values[UniformIndex(rng, values.size())];
    means.push_back(sum / static_cast<double>(values.size()));
  }
  std::sort(means.begin(), means.end());
  *lo = Quantile(means, 0.025);
  *hi = Quantile(std::move(means), 0.975);
}

}  // namespace

bool IsEmptyEstimate(const StepRecord& s) {
  if (s.status == "empty") return true;
  for (const VariableRecord& v : s.vars) {
    if (!(v.lo <= v.hi)) return true;
  }
  return false;
}

double Mean(const std::vector<double>& values) {
  if (values.empty()) return kNaN;
  double sum = 0;
  for (double v : values) sum += v;
  return sum / static_cast<double>(values.size());
}


double Quantile(std::vector<double> values, double p) {
  // NaN entries carry no order; they are left out.
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return std::isnan(v); }),
               values.end());
  if (values.empty() || !(p >= 0 && p <= 1)) return kNaN;
  std::sort(values.begin(), values.end());
  const double h = p * static_cast<double>(values.size() - 1);
  const std::size_t below = static_cast<std::size_t>(std::floor(h));
  if (below + 1 >= values.size()) return values.back();
  const double a = values[below];
  const double b = values[below + 1];
  const double frac = h - static_cast<double>(below);
  if (frac == 0 || a == b) return a;
  if (std::isinf(a) || std::isinf(b)) return (1 - frac) * a + frac * b;  // no inf - inf
  return a + frac * (b - a);
}

namespace {
// truth moved by the multiple of period that brings it nearest to x's
// midpoint (truth itself for a plain component or an unbounded x).
double Representative(double truth, double period, const Interval& x) {
  if (period <= 0 || x.IsEmpty() || !(x.Width() < kInf)) return truth;
  const double turns = std::round(((x.lo() + x.hi()) / 2 - truth) / period);
  return turns == 0 ? truth : truth + turns * period;
}

// The box every estimate of the step lies in.
Box Domains(const Views& views) {
  if (views.csp) return NewestState(*views.csp, views.csp->csp.domains(), views.space.size());
  if (views.measurement_set) return views.measurement_set->prior;
  return Box(static_cast<std::size_t>(views.space.size()));
}
}  // namespace

bool ContainsState(const StateSpace& space, const Estimate& estimate, std::vector<double> point) {
  const Box hull = estimate.Hull();
  if (hull.IsEmpty()) return false;
  for (int c = 0; c < space.size(); ++c) point[c] = Representative(point[c], space.Period(c), hull[c]);
  return estimate.Contains(point);
}

Properties CoverageProperties(const Step& step, const Estimate& estimate) {
  Properties out;
  if (step.truth.empty()) return out;
  for (const int percent : kCoverageLevels) {
    const std::optional<Box> region = estimate.CredibleRegion(percent / 100.0);
    if (!region) return out;
    bool covered = !region->IsEmpty();
    for (int c = 0; c < step.views.space.size() && covered; ++c)
      covered = (*region)[c].Contains(
          Representative(step.truth[c], step.views.space.Period(c), (*region)[c]));
    out.push_back({"covered_" + std::to_string(percent), std::int64_t{covered}});
  }
  return out;
}

StepRecord MeasureStep(const Step& step, const Estimate& estimate) {
  const StateSpace& space = step.views.space;
  const Box hull = estimate.Hull();
  const bool empty = hull.IsEmpty();
  const bool known = !step.truth.empty();
  StepRecord r;
  r.step = step.views.step;
  r.estimate = std::string(estimate.Kind());
  std::vector<double> truth = step.truth;
  for (int c = 0; c < space.size(); ++c) {
    VariableRecord v;
    v.name = space.names[c];
    v.lo = empty ? kInf : hull[c].lo();
    v.hi = empty ? -kInf : hull[c].hi();
    if (known) truth[c] = Representative(truth[c], space.Period(c), hull[c]);
    v.truth = known ? truth[c] : kNaN;
    r.vars.push_back(v);
  }
  r.contained = known ? (ContainsState(space, estimate, step.truth) ? 1 : 0) : -1;
  // The truth's outlier count, to compare with the q a relaxed solver found.
  if (step.views.measurement_set && !step.views.measurement_set->outliers.empty()) {
    const auto& o = step.views.measurement_set->outliers;
    r.properties.push_back({"true_outliers", static_cast<std::int64_t>(std::count(o.begin(), o.end(), true))});
  }
  r.area = kNaN;
  r.centre_error = kNaN;
  if (space.x >= 0 && space.y >= 0 && !empty) {
    r.area = estimate.Area(space.x, space.y);
    const std::vector<double> centre = estimate.Centre();
    if (known && !centre.empty())
      r.centre_error = std::hypot(centre[space.x] - truth[space.x], centre[space.y] - truth[space.y]);
  }
  return r;
}

void PostStateJudge::Judge(const Step& step, Properties* properties) {
  // A step's truth is its newest state's: keyed by that state's time, which
  // is the step's own except where one step holds many states (chain).
  const int newest = step.views.csp ? step.views.csp->newest : step.views.step;
  if (!step.truth.empty()) truths_.emplace_back(newest, step.truth);
  const std::optional<double> post = NumberProperty(*properties, "post_step");
  if (!post) return;
  const int state = static_cast<int>(*post);
  while (!truths_.empty() && truths_.front().first < state) truths_.pop_front();
  if (truths_.empty() || truths_.front().first != state) return;  // its truth is unknown
  const std::vector<double>& truth = truths_.front().second;
  const StateSpace& space = step.views.space;
  std::vector<double> lo(space.size()), hi(space.size()), t(space.size());
  bool contained = true;
  for (int c = 0; c < space.size(); ++c) {
    const std::string& name = space.names[c];
    const auto l = NumberProperty(*properties, "post_" + name + "_lo");
    const auto h = NumberProperty(*properties, "post_" + name + "_hi");
    if (!l || !h) return;  // not every component reported
    lo[c] = *l;
    hi[c] = *h;
    const bool empty = !(lo[c] <= hi[c]);
    t[c] = empty ? truth[c] : Representative(truth[c], space.Period(c), Interval(lo[c], hi[c]));
    contained = contained && !empty && lo[c] <= t[c] && t[c] <= hi[c];
  }
  for (int c = 0; c < space.size(); ++c) properties->push_back({"post_" + space.names[c] + "_truth", t[c]});
  properties->push_back({"post_contained", static_cast<std::int64_t>(contained ? 1 : 0)});
  const int x = space.x, y = space.y;
  if (x < 0 || y < 0 || !(lo[x] <= hi[x]) || !(lo[y] <= hi[y])) return;
  properties->push_back(
      {"post_area", (Interval(Interval(lo[x], hi[x]).Width()) * Interval(Interval(lo[y], hi[y]).Width())).hi()});
  properties->push_back(
      {"post_centre_error", std::hypot((lo[x] + hi[x]) / 2 - t[x], (lo[y] + hi[y]) / 2 - t[y])});
}

std::vector<StepRecord> PostLocalizedStates(const std::vector<StepRecord>& steps) {
  std::vector<StepRecord> states;
  for (const StepRecord& s : steps) {
    const std::optional<double> post = NumberProperty(s.properties, "post_step");
    const std::optional<double> contained = NumberProperty(s.properties, "post_contained");
    if (!post || !contained) continue;
    StepRecord r;
    r.step = static_cast<int>(*post);
    r.estimate = "box";
    r.status = s.status;
    r.contained = static_cast<int>(*contained);
    r.area = NumberProperty(s.properties, "post_area").value_or(kNaN);
    r.centre_error = NumberProperty(s.properties, "post_centre_error").value_or(kNaN);
    r.solve_time_s = kNaN;
    for (const VariableRecord& v : s.vars) {
      const std::string prefix = "post_" + v.name;
      r.vars.push_back({v.name, NumberProperty(s.properties, prefix + "_lo").value_or(kNaN),
                        NumberProperty(s.properties, prefix + "_hi").value_or(kNaN),
                        NumberProperty(s.properties, prefix + "_truth").value_or(kNaN)});
    }
    if (!states.empty() && states.back().step == r.step) {
      states.back() = std::move(r);  // a later, final box of the same state
    } else {
      states.push_back(std::move(r));
    }
  }
  return states;
}

std::string InvalidEstimateReason(const Views& views, const Estimate& estimate) {
  if (std::string why = estimate.Malformed(views.space.names); !why.empty()) return why;
  const Box hull = estimate.Hull();
  if (static_cast<int>(hull.size()) != views.space.size())
    return "the estimate has " + std::to_string(hull.size()) + " components, the state " +
           std::to_string(views.space.size());
  if (const int nan = FirstNaNComponent(hull); nan >= 0) return views.space.names[nan] + " has a NaN bound";
  if (hull.IsEmpty() || !estimate.ClaimsEnclosure()) return "";
  const Box domains = Domains(views);
  for (int c = 0; c < views.space.size(); ++c) {
    const std::string& name = views.space.names[c];
    const double period = views.space.Period(c);
    if (period > 0 && !(domains[c].Width() < period)) continue;  // any frame is fine
    if (!hull[c].IsSubsetOf(domains[c]))
      return name + " = [" + FormatDouble(hull[c].lo()) + ", " + FormatDouble(hull[c].hi()) +
             "] is not inside its domain [" + FormatDouble(domains[c].lo()) + ", " +
             FormatDouble(domains[c].hi()) + "]";
  }
  return "";
}

void MetricsAccumulator::Add(const StepRecord& s) {
  ++steps_;
  const bool empty = IsEmptyEstimate(s);
  const bool truth_known = TruthKnown(s);

  if (!empty && !std::isnan(s.area)) {
    area_sum_ += s.area;
    ++areas_;
  }

  // Paper 004 eq. 31 over the steps whose truth is known; an empty box
  // holds nothing, so it counts as inconsistent whatever contained says.
  if (s.contained != -1 || (empty && truth_known)) {
    ++judged_;
    if (!empty && s.contained == 1) ++consistent_;
  }

  if (!std::isnan(s.centre_error)) {
    squared_error_sum_ += s.centre_error * s.centre_error;
    ++errors_;
  }
  if (!std::isnan(s.solve_time_s)) times_.push_back(s.solve_time_s);

  for (const VariableRecord& v : s.vars) {
    auto it = std::find_if(corridors_.begin(), corridors_.end(),
                           [&](const CorridorSums& c) { return c.corridor.var == v.name; });
    if (it == corridors_.end()) {
      CorridorSums c;
      c.corridor.var = v.name;
      c.corridor.min_lower = std::numeric_limits<double>::infinity();
      c.corridor.max_upper = -std::numeric_limits<double>::infinity();
      corridors_.push_back(c);
      it = corridors_.end() - 1;
    }
    if (empty || std::isnan(v.truth)) continue;
    const double lower = v.lo - v.truth;
    const double upper = v.hi - v.truth;
    it->sum_lower += lower;
    it->sum_upper += upper;
    it->corridor.min_lower = std::min(it->corridor.min_lower, lower);
    it->corridor.max_upper = std::max(it->corridor.max_upper, upper);
    ++it->count;
  }
}

RunMetrics MetricsAccumulator::Finish(std::uint64_t bootstrap_seed) const {
  RunMetrics m;
  m.steps = steps_;
  m.mean_area = areas_ == 0 ? kNaN : area_sum_ / static_cast<double>(areas_);
  m.consistency_rate = judged_ == 0 ? kNaN : static_cast<double>(consistent_) / judged_;
  m.centre_rmse = errors_ == 0 ? kNaN : std::sqrt(squared_error_sum_ / static_cast<double>(errors_));

  m.time_mean_s = Mean(times_);
  m.time_median_s = Quantile(times_, 0.5);
  m.time_p90_s = Quantile(times_, 0.9);
  BootstrapMeanInterval(times_, bootstrap_seed, &m.time_mean_ci_lo_s, &m.time_mean_ci_hi_s);

  for (CorridorSums c : corridors_) {
    if (c.count == 0) {
      c.corridor.mean_lower = c.corridor.mean_upper = kNaN;
      c.corridor.min_lower = c.corridor.max_upper = kNaN;
    } else {
      c.corridor.mean_lower = c.sum_lower / c.count;
      c.corridor.mean_upper = c.sum_upper / c.count;
    }
    m.corridors.push_back(c.corridor);
  }
  return m;
}

RunMetrics ComputeMetrics(const std::vector<StepRecord>& steps, std::uint64_t bootstrap_seed) {
  MetricsAccumulator metrics;
  for (const StepRecord& s : steps) metrics.Add(s);
  return metrics.Finish(bootstrap_seed);
}

}  // namespace icp
